#!/usr/bin/python3
"""Runs the 3D scenes (prm/paper_fig1_3d.prm, the paper's; and
prm/paper_fig1_3d_slip.prm, whose contact face slips) on N^3 cells with CG
and AMG on the given numbers of MPI ranks for a few steps, and writes the
time per step, its split by phase and the peak memory to
doc/figures/bench_3d.csv; scripts/bench_report.py puts them into
doc/performance.md.

Usage: bench_3d.py VPCONTACT [--cells N] [--steps S] [--ranks R ...]
                             [--scenes paper slip] [--timeout T]
                             [--against COMMIT=VPCONTACT ...]
--against runs the same scenes with the executable of an earlier commit
right after each of this one's, so that time and memory compare side by
side on one machine in one sitting (the column *commit* tells them apart).
The rows of scenes not run this time stay in the CSV as they were.
A benchmark reports figures: nothing here passes or fails."""
import argparse
import datetime
import os
import re
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import bench  # noqa: E402  (next to this file)

# Each scene's file and its default cells per side: the slip scene has no
# damage, so 72^3 cells give it over a million unknowns (3 * 73^3), as the
# paper scene's 64^3 (4 * 65^3).
SCENES = {"paper": ("paper_fig1_3d.prm", 64),
          "slip": ("paper_fig1_3d_slip.prm", 72)}
COLUMNS = ["scene", "cells_per_side", "ranks", "steps", "status", "dofs", "total_s",
           "setup_s", "per_step_ms"] + [p + "_ms" for p in bench.PHASES] + [
           "mem_rank0_mb", "mem_all_mb", "mem_private_mb", "linear_its",
           "active_set_its", "phases", "date", "cpu", "commit"]


def run(a, scene, ranks, executable, label=""):
    cells = a.cells or SCENES[scene][1]
    tag = f"{scene}3d_{cells}_{ranks}{label}"
    folder = os.path.join(a.workdir, "runs", tag)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(os.path.join(a.workdir, "logs"), exist_ok=True)
    prm = os.path.join(a.workdir, tag + ".prm")
    with open(prm, "w") as f:
        f.write(f"include {ROOT}/prm/{SCENES[scene][0]}\n"
                f"subsection Geometry\n  set Subdivisions = "
                f"{cells}, {cells}, {cells}\nend\n"
                f"subsection Time\n  set End time = {a.steps * 0.01!r}\nend\n"
                f"subsection Solver\n  set Linear solver = CG with AMG\nend\n"
                f"subsection Error estimate\n  set Estimate error = false\n"
                f"end\nsubsection Output\n  set Directory = {folder}\n"
                f"  set Output every = 0\nend\n")
    out, row = bench.launch(a, [executable, prm], ranks, tag,
                            lambda out: "Total wallclock" in out,
                            timeout=a.timeout)
    row.update(scene=scene, cells_per_side=cells, ranks=ranks,
               steps=a.steps)
    if row["status"] != "ok":
        return partial(a, row, folder)
    total, phases = bench.timer_table(out)
    groups = {g: 0. for g in bench.PHASES + ["setup"]}
    for name, (calls, seconds, _) in phases.items():
        group = next((g for g, p in bench.PHASE_GROUPS
                      if re.search(p, name, re.I)), "other")
        groups[group] += seconds
    dofs = re.search(r"mesh: \d+ cells, (\d+) dofs", out)
    memory = re.search(r"Peak memory \(rank 0\):\s+(\d+) kB", out)
    row.update(dofs=int(dofs.group(1)), total_s=total,
               setup_s=groups["setup"],
               per_step_ms=1000 * (total - groups["setup"]) / a.steps,
               mem_rank0_mb=int(memory.group(1)) / 1024 if memory else "",
               phases=";".join(f"{n}={c}x{s:.6g}"
                               for n, (c, s, _) in sorted(phases.items())))
    for g in bench.PHASES:
        row[g + "_ms"] = 1000 * groups[g] / a.steps
    stats = open(os.path.join(folder, "statistics.csv")).read().splitlines()
    head = stats[0].split(",")
    steps = [dict(zip(head, s.split(","))) for s in stats[2:]]
    for column in ("linear", "active_set"):
        row[column + "_its"] = sum(int(r[column + "_iterations"])
                                   for r in steps) / len(steps)
    shutil.rmtree(folder, ignore_errors=True)
    return row


def step_rows(folder):
    """The rows of the run's statistics.csv after step 0."""
    path = os.path.join(folder, "statistics.csv")
    if not os.path.exists(path):
        return []
    stats = open(path).read().splitlines()
    head = stats[0].split(",")
    return [dict(zip(head, s.split(","))) for s in stats[2:]]


def partial(a, row, folder):
    """A run stopped by --timeout: its time per step, iterations and size
    from the steps it finished (statistics.csv), no phases."""
    steps = [r for r in step_rows(folder) if r.get("wall_time")]
    # timeout(1) exits with 124 after its SIGTERM, 137 after the SIGKILL
    # that follows; any other exit is a failure of the run itself.
    if not a.timeout or row.get("exit_code") not in (124, 137):
        return row
    if not steps:
        # Stopped inside its first step: what is known is that a step takes
        # longer than the whole time allowed, which the report says.
        row.update(status=f"stopped after 0 of {a.steps} steps "
                   f"(--timeout {a.timeout} s)")
        return row
    row.update(status=f"stopped after {len(steps)} of {a.steps} steps "
               f"(--timeout {a.timeout} s)",
               dofs=int(steps[0]["dofs"]),
               per_step_ms=1000 * sum(float(r["wall_time"]) for r in steps)
               / len(steps))
    for column in ("linear", "active_set"):
        row[column + "_its"] = sum(int(r[column + "_iterations"])
                                   for r in steps) / len(steps)
    return row


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("executable")
    p.add_argument("--cells", type=int, default=None, help="cells per side "
                   "(default: 64 for the paper scene, 72 for the slip scene)")
    p.add_argument("--steps", type=int, default=5)
    p.add_argument("--ranks", type=int, nargs="+", default=[2])
    p.add_argument("--scenes", nargs="+", choices=sorted(SCENES),
                   default=["paper", "slip"])
    p.add_argument("--timeout", type=int, default=0, help="stop a run "
                   "after this many seconds and report the steps it "
                   "finished (0: no limit)")
    p.add_argument("--workdir", default="/tmp/vpcontact_bench_3d")
    p.add_argument("--csv", default=os.path.join(ROOT, "doc", "figures",
                                                 "bench_3d.csv"))
    p.add_argument("--against", nargs="+", default=[], metavar="COMMIT=EXE",
                   help="also run each scene with EXE, built from COMMIT")
    a = p.parse_args()
    machine = bench.machine()
    against = [tuple(x.split("=", 1)) for x in a.against]
    rows = []
    for scene, ranks in [(s, r) for s in a.scenes for r in a.ranks]:
        runs = [(machine.get("commit", ""), a.executable, "")] + [
            (commit, exe, "_" + commit) for commit, exe in against]
        for commit, executable, label in runs:
            row = run(a, scene, ranks, executable, label)
            row.update(date=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
                       cpu=machine.get("cpu", ""), commit=commit)
            print({k: row.get(k) for k in ("scene", "ranks", "commit", "status",
                                           "dofs", "total_s", "per_step_ms")},
                  flush=True)
            rows.append(row)
    import csv
    if os.path.exists(a.csv):
        with open(a.csv) as f:
            rows += [r for r in csv.DictReader(f) if r["scene"] not in a.scenes]
    # One scene's rows together and the scenes in a fixed order, so that the
    # report reads the same whichever scenes this sitting ran.
    order = list(SCENES)
    rows.sort(key=lambda r: order.index(r["scene"]) if r["scene"] in order
              else len(order))
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v)
                        for k, v in r.items()})
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts",
                                                 "bench_report.py")],
                   check=True)


if __name__ == "__main__":
    main()
