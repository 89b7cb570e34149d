#!/usr/bin/python3
"""Profiles the heap of one run of the paper scene with heaptrack and writes
where its peak goes to doc/memory.md: the heap at its peak split by the
program's function that asked for it (and, inside the displacement solver's
set-up, by the library function), and the largest heap after the first step
against the peak.

Usage: memory_profile.py VPCONTACT [--cells N] [--steps S]
                         [--solver NAME] [--out PAGE]
heaptrack (Debian package heaptrack) records every allocation; the run takes
about twice as long under it. A profile reports figures: nothing here passes
or fails."""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import bench  # noqa: E402  (next to this file)
import mapped_pages  # noqa: E402

MB = 1e6


def scene(a, folder):
    return (f"include {ROOT}/prm/paper_fig1.prm\n"
            f"subsection Geometry\n  set Subdivisions = {a.cells}, {a.cells}\n"
            f"end\nsubsection Time\n  set End time = {a.steps * 0.01!r}\nend\n"
            f"subsection Solver\n  set Linear solver = {a.solver}\nend\n"
            f"subsection Output\n  set Directory = {folder}\nend\n")


def record(a, workdir):
    """Runs the scene under heaptrack; returns heaptrack's data file."""
    prm = os.path.join(workdir, "scene.prm")
    with open(prm, "w") as f:
        f.write(scene(a, os.path.join(workdir, "output")))
    data = os.path.join(workdir, "heap")
    run = subprocess.run(["heaptrack", "-o", data, a.vpcontact, prm],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("memory_profile: the run under heaptrack failed:\n"
                 + run.stdout[-2000:] + run.stderr[-2000:])
    found = [f for f in os.listdir(workdir) if f.startswith("heap.")]
    if not found:
        sys.exit("memory_profile: heaptrack wrote no data file")
    return os.path.join(workdir, found[0])


def clean(frame):
    """A frame's function name without its arguments."""
    frame = frame.replace("(anonymous namespace)", "anon")
    return re.sub(r"\(.*", "", frame).replace("<>", "")


def ml_stage(frames):
    """The stage of ML's set-up an allocation belongs to: the function ML's
    hierarchy builder (or, outside it, the preconditioner's set-up) called."""
    for parent in ("ML_Gen_MultiLevelHierarchy",
                   "ML_Epetra::MultiLevelPreconditioner::ComputePreconditioner"):
        at = [i for i, s in enumerate(frames) if s == parent]
        if at and at[-1] + 1 < len(frames):
            return frames[at[-1] + 1]
    return next((s for s in frames if s.startswith("ML")), "other")


def peak_split(data, workdir):
    """The heap at its peak by the deepest frame of the program's own code,
    and the part under the displacement solver's set-up by the library
    function below the preconditioner's initialize()."""
    graph = os.path.join(workdir, "peak.txt")
    subprocess.run(["heaptrack_print", "-f", data, "--print-flamegraph",
                    graph, "--flamegraph-cost-type", "peak"],
                   capture_output=True, check=True)
    own, library = collections.Counter(), collections.Counter()
    with open(graph) as f:
        for line in f:
            stack, _, cost = line.rstrip().rpartition(" ")
            if not cost.isdigit():
                continue
            frames = [clean(s) for s in stack.split(";")]
            ours = [i for i, s in enumerate(frames) if "VPContact::" in s]
            key = frames[ours[-1]] if ours else "(outside the program)"
            own[key] += int(cost)
            if ours and "SpdSolver::initialize" in key:
                library[ml_stage(frames[ours[-1] + 1:])] += int(cost)
    return own, library


def heap_over_time(data, workdir):
    """(the time of the sampled peak as a share of the run, the largest heap
    in the last quarter of the run: the steps, long after the set-up) from
    heaptrack's time series. The series samples the heap; the exact peak is
    the sum of peak_split()'s parts."""
    series = os.path.join(workdir, "massif.txt")
    subprocess.run(["heaptrack_print", "-f", data, "--print-massif", series],
                   capture_output=True, check=True)
    points = []
    time = None
    with open(series) as f:
        for line in f:
            if line.startswith("time="):
                time = float(line[5:])
            elif line.startswith("mem_heap_B="):
                points.append((time, int(line[11:])))
    end = points[-1][0]
    peak = max(points, key=lambda p: p[1])
    later = max(m for t, m in points if t >= 0.75 * end)
    return peak[0] / end, later


def table(counter, total, limit):
    rows = ["| allocated under | MB at the peak | share |", "|---|---|---|"]
    rest = total
    for name, cost in counter.most_common(limit):
        rows.append(f"| `{name}` | {cost / MB:.1f} | {100 * cost / total:.0f} % |")
        rest -= cost
    rows.append(f"| everything else | {rest / MB:.1f} | {100 * rest / total:.0f} % |")
    return "\n".join(rows)


def page(a, own, library, over_time, peak_rss, mapped):
    when, later = over_time
    info = bench.machine()
    total = peak = sum(own.values())
    solver = sum(c for k, c in own.items() if "SpdSolver::initialize" in k)
    return f"""# Memory

Where the heap of a run goes at its peak: the paper scene
(`prm/paper_fig1.prm`) on {a.cells} x {a.cells} cells, {a.steps} steps,
`Solver/Linear solver = {a.solver}`, 1 rank, fields written as the scene sets;
recorded by heaptrack and written by `scripts/memory_profile` at commit
{info["commit"]} on {info["date"]} ({info["cpu"]}, {info["cores"]} cores).

* Peak heap: {peak / MB:.0f} MB, reached at about {100 * when:.0f} % of the
  run's time (heaptrack's clock, from its sampled time series). The largest heap in the last quarter of the run
  (its steps and field output, long after the set-up): {later / MB:.0f} MB.
  Peak resident set (the heap, the program's libraries and the stacks) of
  the same run without heaptrack, as the run prints it: {peak_rss}.
* The displacement solver's set-up holds {solver / MB:.0f} MB of the peak
  ({100 * solver / total:.0f} %).

## The heap at its peak, by the program's function

The deepest function of vpcontact on the call stack of each allocation that
is alive at the peak; library calls below it are counted with it.

{table(own, total, 15)}

## The displacement solver's set-up at the peak, by library function

The stage of ML's set-up each allocation comes from: the function that ML's
hierarchy builder calls (`ML_Gen_AmatrixRAP`: the Galerkin product R A P of
a level; `ML_MultiLevel_Gen_Prolongator`: the aggregates and the smoothed
prolongator P; `ML_MultiLevel_Gen_Restriction`: its transpose R, stored), or
outside the hierarchy the one the preconditioner's set-up calls (smoothers,
coarse solver).

{table(library, solver, 8) if solver else "(none: this solver builds no ML hierarchy)"}

## The pages mapped from files

The resident set counts, beside the heap and the stacks, the pages of the
files the run maps: the code and read-only data of the program's libraries
and their dynamic symbol tables, which the loader reads while it resolves
the symbols a library exports and uses (deal.II's library exports its
template instances, so its table of names is large). The page cache holds
them once for every process of the machine that maps them, all ranks of a
run included, and can drop them and read them again; they are not memory
the run holds of its own. `scripts/bench` reports, beside the peak resident
set, the peak of the anonymous memory alone (*private memory*).

{mapped}
## Regenerating

`scripts/memory_profile [--cells N] [--steps S] [--solver NAME] [--out PAGE]`
(default 512 cells per side, 10 steps, `CG with AMG`, this page). It needs
heaptrack (`apt-get install heaptrack`). Run it with nothing else busy.
"""


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawTextHelpFormatter)
    p.add_argument("vpcontact")
    p.add_argument("--cells", type=int, default=512)
    p.add_argument("--steps", type=int, default=10)
    p.add_argument("--solver", default="CG with AMG")
    p.add_argument("--out", default=os.path.join(ROOT, "doc", "memory.md"))
    a = p.parse_args()
    if subprocess.run(["which", "heaptrack"], capture_output=True).returncode:
        sys.exit("memory_profile: heaptrack is not installed "
                 "(apt-get install heaptrack)")
    with tempfile.TemporaryDirectory(prefix="vpcontact_memory_") as workdir:
        data = record(a, workdir)
        own, library = peak_split(data, workdir)
        over_time = heap_over_time(data, workdir)
        plain = os.path.join(workdir, "plain.prm")
        with open(plain, "w") as f:
            f.write(scene(a, os.path.join(workdir, "output_plain")))
        # The same run without heaptrack, for its resident set and the
        # pages it maps from files.
        output = os.path.join(workdir, "plain.out")
        mapped = mapped_pages.page_section([a.vpcontact, plain], output)
        plain = open(output).read()
        rss = re.search(r"Peak memory \(rank 0\):\s*(\d+) kB", plain)
        peak_rss = f"{int(rss.group(1)) / 1000:.0f} MB" if rss else "not printed"
    with open(a.out, "w") as f:
        f.write(page(a, own, library, over_time, peak_rss, mapped))
    print(f"memory_profile: wrote {a.out}")


if __name__ == "__main__":
    main()
