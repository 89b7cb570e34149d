#!/usr/bin/python3
"""Runs the benchmark of the paper scene: vpcontact with each linear algebra
back-end and solver path on 1 and 2 MPI ranks, and the DOLFINx peer
(../shared/peer-dolfinx) on the same sizes, in one run on one machine; writes
every run to a CSV file and the report (scripts/bench_report.py) from it.

Usage (from anywhere): bench.py VPCONTACT [SIZE ...] [options]; see --help.
A benchmark reports figures: nothing here passes or fails."""
import argparse
import csv
import datetime
import glob
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import bench_against  # noqa: E402  (next to this file)
import openblas_core  # noqa: E402
import bench_report  # noqa: E402
from bench_process import ENV, run_retrying  # noqa: E402

PYTHON = "/usr/bin/python3"  # Debian's interpreter, the one with dolfinx


def arguments():
    p = argparse.ArgumentParser(
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("executable", help="the vpcontact binary (build/vpcontact)")
    p.add_argument("sizes", nargs="*", type=int,
                   help="cells per side (default 128 256 512; --quick: 16 32)")
    p.add_argument("--steps", type=int, default=None,
                   help="time steps over T = 1 (default 100, --quick 10)")
    p.add_argument("--rounds", type=int, default=1,
                   help="run everything this many times, the sizes one after "
                   "the other within a round; the report shows the median "
                   "of each run (the machine's speed drifts between runs)")
    p.add_argument("--quick", action="store_true",
                   help="smoke test: sizes 16 32, 10 steps, report in "
                   "/tmp/vpcontact_bench/performance.md unless --out is given")
    p.add_argument("--out", help="report path (default doc/performance.md)")
    p.add_argument("--csv", help="raw results (default figures/bench.csv "
                   "next to the report)")
    p.add_argument("--workdir", default="/tmp/vpcontact_bench",
                   help="prm files, run folders, logs (default %(default)s)")
    p.add_argument("--peer", default=os.path.join(
        ROOT, "..", "shared", "peer-dolfinx", "peer.py"),
        help="the peer's peer.py (default ../shared/peer-dolfinx/peer.py)")
    p.add_argument("--no-peer", action="store_true", help="skip the peer")
    p.add_argument("--against", action="append", default=[],
                   metavar="COMMIT[:REGEX]", help="also build vpcontact "
                   "at COMMIT (in a temporary git worktree under --workdir) "
                   "and run each configuration with it right after HEAD's, "
                   "or only those whose name matches REGEX (as --configs); "
                   "the report compares their phases (repeatable)")
    p.add_argument("--huge-pages", nargs="?", const=".", metavar="REGEX",
                   help="also run HEAD's build with VPCONTACT_HUGE_PAGES=1 "
                   "(the heap in transparent huge pages) right after each "
                   "configuration, or each whose name matches REGEX; the "
                   "report compares it like an --against commit")
    p.add_argument("--one-thread", nargs="?", const="1 rank", metavar="REGEX",
                   help="also run HEAD's build with DEAL_II_NUM_THREADS=1 "
                   "right after each configuration on 1 rank, or each whose "
                   "name matches REGEX: what 2 ranks gain over 1 by the "
                   "ranks alone; the report compares it like an --against "
                   "commit")
    p.add_argument("--configs", metavar="REGEX", help="only the runs whose "
                   "name matches (re.search), as in 'vpcontact Trilinos "
                   "Cholesky, 1 rank' or 'peer gamg, 2 ranks': "
                   "'Trilinos Cholesky' selects one path, 'AMG, 2 ranks' "
                   "several")
    p.add_argument("--floor", action="store_true", help="also set Output/"
                   "Report solve floor where the binary has it (a solve "
                   "after the timed part)")
    a = p.parse_args()
    a.sizes = a.sizes or ([16, 32] if a.quick else [128, 256, 512])
    a.steps = a.steps or (10 if a.quick else 100)
    a.out = a.out or ("/tmp/vpcontact_bench/performance.md" if a.quick
                      else os.path.join(ROOT, "doc", "performance.md"))
    a.csv = a.csv or os.path.join(os.path.dirname(os.path.abspath(a.out)),
                                  "figures", "bench.csv")
    a.executable = os.path.abspath(a.executable)
    return a


def parameters(executable):
    """The entries of `vpcontact --print-parameters` as {"Section/Entry":
    allowed values (a list for a Selection, else None)}: which back-ends,
    solvers and switches this binary has (the Solver section changes while
    the program is developed, and a prm with an unknown entry is refused)."""
    text = run_retrying([executable, "--print-parameters"])[0]
    entries, path, comments = {}, [], []
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("#"):
            comments.append(s.lstrip("# "))
        elif s.startswith("subsection "):
            path.append(s[len("subsection "):])
        elif s == "end" and path:
            path.pop()
        elif s.startswith("set "):
            name = s[4:].split("=")[0].strip()
            doc = " ".join(comments)
            m = re.search(r"Allowed: \[Selection (.*?)\s*\]", doc)
            entries["/".join(path + [name])] = (
                [v.strip() for v in m.group(1).split("|")] if m else None)
        if not s.startswith("#"):
            comments = []
    return entries


# Phases of the TimerOutput table, grouped for the report: first matching
# pattern (case-insensitive) wins; "Setup" (mesh, dofs, sparsity, once per
# run) is out of the time per step. The same groups hold the timers of an
# earlier commit (--against), whose names may differ ("Error indicators"
# before "Error estimate"). Names the patterns do not know go to "other" in
# the report and stay whole in the CSV's phases column.
PHASE_GROUPS = [("setup", r"^setup"), ("damage_solve", r"damage.*solve"),
                ("damage_assembly", r"damage"),
                ("preconditioner", r"preconditioner|factori|amg setup"),
                ("assembly", r"assembl"), ("solve", r"solve"),
                ("stress", r"stress"), ("estimate", r"error (estim|indic)"),
                ("output", r"output|postprocess")]
PHASES = bench_report.PHASES  # the same names, in the CSV's order


def timer_table(out):
    """The TimerOutput table: total seconds and {phase: (calls, seconds,
    damage (min, max) over ranks or None)}. Two layouts: the plain one
    (rank 0's times) and deal.II's wall-time statistics over ranks (min with
    rank, average, max with rank), where the max is what the run waits for."""
    total = float(re.search(r"Total wallclock time elapsed(?: since start)?"
                            r"\s+\|\s+([0-9.e+-]+)s", out).group(1))
    phases = {}
    name = r"\| ([A-Za-z0-9][A-Za-z0-9 ,.()/+_-]*?)\s+\|\s+(\d+) \|"
    t = r"\s+([0-9.e+-]+)s"
    for m in re.finditer(name + t + r" \|", out):
        phases[m.group(1).strip()] = (int(m.group(2)), float(m.group(3)), None)
    for m in re.finditer(name + t + r"\s+\d+ \|" + t + r" \|" + t +
                         r"\s+\d+ \|", out):
        phases[m.group(1).strip()] = (int(m.group(2)), float(m.group(5)),
                                      (float(m.group(3)), float(m.group(5))))
    return total, phases


def launch(a, command, ranks, tag, finished, timeout=None, environment=()):
    """Runs a command under /usr/bin/time -v (for the peak memory of each
    process), under mpirun for several ranks, and keeps its output in the
    log folder; (stdout, the row's status, wall time, peak resident set
    summed over the ranks, log, peak private memory summed over the ranks,
    bench_process.py). With @p timeout (seconds) the run gets SIGTERM then,
    which vpcontact answers by stopping after its step. The @p environment
    entries (NAME=VALUE) are set for the command alone."""
    executable = command[0]
    if environment:
        command = ["env"] + list(environment) + command
    rss = os.path.join(a.workdir, "logs", tag + ".rss")
    for f in glob.glob(rss + ".*"):
        os.remove(f)
    if os.path.exists("/usr/bin/time"):
        # A file per rank: the ranks' stderr interleaves under mpirun.
        command = ["sh", "-c", 'exec /usr/bin/time -v -o '
                   '"$0.${OMPI_COMM_WORLD_RANK:-0}" "$@"', rss] + command
    if ranks > 1:
        # Binding each rank to a core is Open MPI's default; oversubscribe
        # only where the machine has fewer cores than ranks.
        command = (["mpirun", "-np", str(ranks)] +
                   (["--oversubscribe"] if os.cpu_count() < ranks else [])
                   + command)
    if timeout:
        command = ["timeout", "-s", "TERM", "-k", "60", str(timeout)] + command
    private = {}
    out, err, rc, wall = run_retrying(command, executable, private=private)
    log = os.path.join(a.workdir, "logs", tag + ".log")
    with open(log, "w") as f:
        f.write(" ".join(command) + "\n" + out + "\n--- stderr ---\n" + err)
    # The reason of a failure: the first line naming an error, not
    # mpirun's rules of dashes around it.
    lines = [l.strip() for l in (err + out).splitlines()
             if l.strip() and not set(l.strip()) <= set("-=*")]
    status = "ok" if rc == 0 and finished(out) else "failed: " + next(
        (l for l in lines if re.search(r"error|exception|abort", l, re.I)),
        lines[-1] if lines else f"exit {rc}")[:120]
    peaks = [int(k) / 1024 for f in glob.glob(rss + ".*") for k in
             re.findall(r"Maximum resident set size \(kbytes\): (\d+)",
                        open(f).read())]
    return out, dict(status=status, exit_code=rc, process_wall_s=wall, log=log,
                     mem_all_mb=sum(peaks) if peaks else "",
                     mem_private_mb=private.get("mb", ""))


def program_run(a, size, algebra, solver, ranks, program, tag):
    """One run of vpcontact (a bench_against.Program: HEAD's build or an
    earlier commit's) on the paper scene; a dict of the CSV's columns."""
    has = program.has
    folder = os.path.join(a.workdir, "runs", tag)
    shutil.rmtree(folder, ignore_errors=True)
    prm = os.path.join(a.workdir, tag + ".prm")
    solver_section = f"  set Linear solver = {solver}\n"
    if "Solver/Linear algebra" in has:
        solver_section += f"  set Linear algebra = {algebra}\n"
    floor = a.floor and "Output/Report solve floor" in has
    with open(prm, "w") as f:
        f.write(open(program.scene).read())
        # The scene as in the file (fields and error estimate every 10
        # steps); only the size, the step count over T = 1, the folder and
        # the solver change.
        f.write(f"\nsubsection Geometry\n  set Subdivisions = {size}, {size}\n"
                f"end\nsubsection Time\n  set End time = 1\n"
                f"  set Time step = {1 / a.steps!r}\nend\n"
                f"subsection Output\n  set Directory = {folder}\n"
                + ("  set Report solve floor = true\n" if floor else "")
                + f"end\nsubsection Solver\n{solver_section}end\n")
    out, row = launch(a, [program.executable, prm], ranks, tag,
                      lambda out: "Total wallclock" in out,
                      environment=program.environment)
    if row["status"] != "ok":
        return row
    total, phases = timer_table(out)
    groups = {g: 0. for g in PHASES + ["setup"]}
    damage_ranks = None
    for name, (calls, seconds, by_rank) in phases.items():
        group = next((g for g, p in PHASE_GROUPS
                      if re.search(p, name, re.I)), "other")
        groups[group] += seconds
        if group == "damage_solve" and by_rank:
            damage_ranks = [x + y for x, y in zip(damage_ranks or (0, 0),
                                                  by_rank)]
    setup = groups["setup"]
    dofs = re.search(r"mesh: \d+ cells, (\d+) dofs", out)
    memory = re.search(r"Peak memory \(rank 0\):\s+(\d+) kB", out)
    floor_m = re.search(r"one displacement solve takes ([0-9.e+-]+) s", out)
    # The damage solves' work (free nodes times CG iterations), summed over
    # the ranks, and on several ranks the largest per rank against the mean
    # (DamageProblem::work_summary()).
    work = re.search(r"Damage solves, free nodes times CG iterations: "
                     r"([0-9.e+-]+)", out)
    balance = re.search(r"Damage solves, free nodes times CG iterations per "
                        r"rank: .*, mean ([0-9.e+-]+) \(largest / mean "
                        r"([0-9.e+-]+)\)", out)
    if balance:
        row["damage_work"] = float(balance.group(1)) * ranks
    elif work:
        row["damage_work"] = float(work.group(1))
    row.update(dofs=int(dofs.group(1)) if dofs else "",
               total_s=total, setup_s=setup,
               per_step_ms=1000 * (total - setup) / a.steps,
               mem_rank0_mb=int(memory.group(1)) / 1024 if memory else "",
               floor_ms=1000 * float(floor_m.group(1)) if floor_m else "",
               damage_work_balance=float(balance.group(2)) if balance
               else "",
               phases=";".join(f"{n}={c}x{s:.6g}"
                               for n, (c, s, _) in sorted(phases.items())))
    for g in PHASES:
        row[g + "_ms"] = 1000 * groups[g] / a.steps
    if damage_ranks:
        row["damage_solve_min_ms"], row["damage_solve_max_ms"] = (
            1000 * x / a.steps for x in damage_ranks)
    try:  # iterations per step from statistics.csv (step 0: initial state)
        with open(os.path.join(folder, "statistics.csv")) as f:
            steps = [r for r in csv.DictReader(f) if int(r["step"]) > 0]
        for column in ("linear", "active_set"):
            row[column + "_its"] = statistics.mean(
                int(r[column + "_iterations"]) for r in steps)
    except (OSError, KeyError, ValueError, statistics.StatisticsError):
        pass
    shutil.rmtree(folder, ignore_errors=True)  # the fields: up to GBs
    return row


def peer_run(a, size, solver, ranks, tag):
    """One run of the DOLFINx peer; its totals come from the .json it
    writes next to --out (rank 0's timers)."""
    csv_out = os.path.join(a.workdir, "runs", tag + ".csv")
    command = [PYTHON, os.path.abspath(a.peer), "--n", str(size), "--steps",
               str(a.steps), "--solver", solver, "--out", csv_out, "--quiet"]
    summary = os.path.splitext(csv_out)[0] + ".json"
    _, row = launch(a, command, ranks, tag,
                           lambda out: os.path.exists(summary))
    if row["status"] != "ok":
        return row
    s = json.load(open(summary))
    n = a.steps
    row.update(dofs=s["dofs_velocity"] + s["dofs_damage"],
               total_s=s["t_total"], setup_s=s["t_setup"],
               per_step_ms=1000 * s["t_loop"] / n,
               assembly_ms=1000 * s["t_assembly_sum"] / n,
               preconditioner_ms=1000 * s["t_vel_setup_sum"] / n,
               solve_ms=1000 * s["t_vel_solve_sum"] / n,
               damage_solve_ms=1000 * s["t_dmg_solve_sum"] / n,
               other_ms=1000 * s["t_other_sum"] / n,
               linear_its=s.get("vel_lin_its_mean", ""),
               active_set_its=s.get("fric_iters_total", 0) / n)
    os.remove(summary)
    return row


def start_memory(a, head, peer_runs):
    """The peak memory of a run on 4 x 4 cells, 2 steps (vpcontact: HEAD,
    Trilinos, CG with AMG; the peer: CG with GAMG), 1 rank: what a run
    holds whatever its mesh, mostly the libraries it loads. Stored in
    every row (MACHINE); '' where a run failed or the peer is skipped."""
    folder = os.path.join(a.workdir, "runs", "start")
    shutil.rmtree(folder, ignore_errors=True)
    prm = os.path.join(a.workdir, "start.prm")
    with open(prm, "w") as f:
        f.write(open(head.scene).read())
        f.write("\nsubsection Geometry\n  set Subdivisions = 4, 4\nend\n"
                "subsection Time\n  set End time = 0.02\n"
                "  set Time step = 0.01\nend\n"
                f"subsection Output\n  set Directory = {folder}\nend\n"
                "subsection Solver\n  set Linear solver = CG with AMG\n"
                + ("  set Linear algebra = Trilinos\n"
                   if "Solver/Linear algebra" in head.has else "")
                + "end\n")
    _, mine = launch(a, [head.executable, prm], 1, "start_vpcontact",
                     lambda out: "Total wallclock" in out)
    shutil.rmtree(folder, ignore_errors=True)
    theirs = {}
    if peer_runs:
        summary = os.path.join(a.workdir, "runs", "start_peer.json")
        _, theirs = launch(
            a, [PYTHON, os.path.abspath(a.peer), "--n", "4", "--steps", "2",
                "--solver", "gamg", "--out",
                os.path.splitext(summary)[0] + ".csv", "--quiet"],
            1, "start_peer", lambda out: os.path.exists(summary))
        for f in glob.glob(os.path.splitext(summary)[0] + ".*"):
            os.remove(f)
    ok = [mine["status"] == "ok", theirs.get("status") == "ok"]
    return {"start_mem_vpcontact_mb": mine["mem_all_mb"] if ok[0] else "",
            "start_mem_peer_mb": theirs["mem_all_mb"] if ok[1] else "",
            "start_private_vpcontact_mb":
                mine["mem_private_mb"] if ok[0] else "",
            "start_private_peer_mb": theirs["mem_private_mb"] if ok[1] else ""}


def machine():
    """Where and on what the benchmark runs, stored in every CSV row."""
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
                if l.startswith("model name")), platform.processor())
    memory = next(int(l.split()[1]) for l in open("/proc/meminfo")
                  if l.startswith("MemTotal"))
    osname = next((l.split("=", 1)[1].strip().strip('"')
                   for l in open("/etc/os-release")
                   if l.startswith("PRETTY_NAME")), platform.platform())

    def version(command):
        r = subprocess.run(command, capture_output=True, text=True)
        return r.stdout.strip() if r.returncode == 0 else ""
    package = ["dpkg-query", "-W", "-f=${Version}"]
    commit = version(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"])
    if version(["git", "-C", ROOT, "status", "--porcelain", "--",
                "source", "include", "CMakeLists.txt"]):
        commit += " with local changes"
    # The kernel's transparent huge page mode, the word in brackets:
    # vpcontact asks for huge pages where it is "madvise" and
    # VPCONTACT_HUGE_PAGES=1 (huge_pages.h).
    try:
        thp = re.search(r"\[(\w+)\]", open(
            "/sys/kernel/mm/transparent_hugepage/enabled").read()).group(1)
    except (OSError, AttributeError):
        thp = ""
    return dict(
        date=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), cpu=cpu,
        thp=thp, blas=openblas_core.core(),
        cores=os.cpu_count(), memory_gb=round(memory / 2**20, 1), os=osname,
        dealii=version(package + ["libdeal.ii-dev"]),
        petsc=version(package + ["libpetsc-real-dev"]),
        dolfinx=version([PYTHON, "-c",
                         "import dolfinx; print(dolfinx.__version__)"]),
        commit=commit)


def missing(program, algebra, solver):
    """Why `program` cannot run a configuration, or None: an earlier commit
    may lack a back-end or a solver (its Solver section is read from
    `--print-parameters`); such a run is skipped and the report says so."""
    if not program.has:
        return "its --print-parameters printed no entries"
    algebras = program.has.get("Solver/Linear algebra") or ["Trilinos"]
    if algebra not in algebras:
        return ("this vpcontact has no Solver/Linear algebra = "
                f"{algebra} (--print-parameters)")
    if solver not in (program.has.get("Solver/Linear solver") or []):
        return f"this vpcontact has no Solver/Linear solver = {solver}"
    return None


def config_name(code, algebra, solver, ranks):
    """What --configs matches: 'vpcontact Trilinos Cholesky, 1 rank',
    'peer gamg, 2 ranks'."""
    return bench_report.config_name({"code": code, "algebra": algebra,
                                     "solver": solver, "ranks": ranks})


def plan(a, programs):
    """The runs of one round per size: (program, code, back-end, solver,
    path, ranks, reason to skip or None). Each configuration of vpcontact
    runs with every program (HEAD's build first, then each --against
    commit) one right after the other, so that they meet the machine in the
    same state; the peer runs once, with HEAD's commit in its rows. The
    direct path is CHOLMOD Cholesky where Trilinos runs serial and MUMPS
    otherwise; the AMG path is CG with AMG (the peer: CG with PETSc GAMG).
    --configs keeps the runs whose config_name matches."""
    runs = []
    for algebra in ("Trilinos", "PETSc"):
        for path, ranks, solver in (
                ("direct", 1, "Cholesky" if algebra == "Trilinos" else "MUMPS"),
                ("direct", 2, "MUMPS"), ("AMG", 1, "CG with AMG"),
                ("AMG", 2, "CG with AMG")):
            runs += [(p, "vpcontact", algebra, solver, path, ranks,
                      missing(p, algebra, solver)) for p in programs
                     if not getattr(p, "configs", None) or re.search(
                         p.configs, config_name("vpcontact", algebra, solver,
                                                ranks))]
    peer_skip = ("--no-peer" if a.no_peer else f"no {a.peer}"
                 if not os.path.exists(a.peer) else None)
    if not peer_skip and subprocess.run([PYTHON, "-c", "import dolfinx"],
                                        capture_output=True).returncode:
        peer_skip = f"{PYTHON} cannot import dolfinx"
    for solver, path, ranks in (("lu", "direct", 1), ("gamg", "AMG", 1),
                                ("gamg", "AMG", 2)):
        runs.append((programs[0], "peer", "DOLFINx/PETSc", solver, path,
                     ranks, peer_skip))
    if not a.configs:
        return runs
    try:
        chosen = [r for r in runs if re.search(
            a.configs, config_name(r[1], r[2], r[3], r[5]))]
    except re.error as e:
        sys.exit(f"error: --configs {a.configs!r} is no regular expression "
                 f"({e})")
    if not chosen:
        sys.exit(f"error: --configs {a.configs!r} matches none of: " +
                 "; ".join(sorted({config_name(r[1], r[2], r[3], r[5])
                                   for r in runs})))
    return chosen


def huge_pages(a, head):
    """With --huge-pages: HEAD's build once more, its heap in transparent
    huge pages (VPCONTACT_HUGE_PAGES=1, huge_pages.h), labelled as a commit
    of its own so that the report sets its phases beside HEAD's."""
    if not a.huge_pages:
        return []
    program = bench_against.Program(head.commit + " huge pages",
                                    head.executable, ROOT)
    program.has = head.has
    program.configs = a.huge_pages
    program.environment = ("VPCONTACT_HUGE_PAGES=1",)
    return [program]


def one_thread(a, head):
    """With --one-thread: HEAD's build once more on one thread per rank
    (DEAL_II_NUM_THREADS=1), labelled as a commit of its own. A run on 1
    rank otherwise uses deal.II's threads on every core, so that its
    figures against 2 ranks mix the threads' gain with the ranks'."""
    if not a.one_thread:
        return []
    program = bench_against.Program(head.commit + bench_report.ONE_THREAD,
                                    head.executable, ROOT)
    program.has = head.has
    program.configs = a.one_thread
    program.environment = ("DEAL_II_NUM_THREADS=1",)
    return [program]


def earlier_programs(a, worktrees, head_commit):
    """A build of each --against commit with the entries it offers."""
    programs = []
    for entry in dict.fromkeys(a.against):  # each once, in the given order
        commit, _, configs = entry.partition(":")
        program = worktrees.add(commit, os.path.join(a.workdir, "logs"))
        program.configs = configs or None
        if program.commit == head_commit:
            sys.exit(f"error: --against {commit} is HEAD itself "
                     f"({head_commit}); give an earlier commit")
        program.has = parameters(program.executable)
        programs.append(program)
    return programs


def benchmark(a, info, runs):
    """Runs every round; the rows of the CSV, which is rewritten after each
    run, so that an interrupted benchmark keeps what it measured
    (bench_report.py can report it)."""
    rows = []
    for round_ in range(1, a.rounds + 1):
        for size in a.sizes:
            for program, code, algebra, solver, path, ranks, skip in runs:
                row = dict(info, round=round_, size=size, steps=a.steps,
                           code=code, algebra=algebra, solver=solver,
                           path=path, ranks=ranks, commit=program.commit,
                           head=info["commit"], scene=program.scene_hash)
                tag = re.sub(r"[^A-Za-z0-9]+", "_", f"{code}_{algebra}_"
                             f"{solver}_{size}_{ranks}_r{round_}" +
                             (f"_{program.commit}" if code == "vpcontact"
                              else ""))
                if skip:
                    if round_ == 1 and size == a.sizes[0]:
                        rows.append(dict(row, status="skipped: " + skip))
                    continue
                row.update(program_run(a, size, algebra, solver, ranks,
                                       program, tag) if code == "vpcontact"
                           else peer_run(a, size, solver, ranks, tag))
                row = bench_report.untimed_in_other(row)
                rows.append(row)
                shown = (f"{row['total_s']:.2f} s, {row['per_step_ms']:.1f}"
                         " ms per step" if row["status"] == "ok"
                         else row["status"] + f" (log {row['log']})")
                label = (f"{code} {program.commit}" if code == "vpcontact"
                         else code)
                print(f"{size}^2, {ranks} rank(s), {label} {algebra} "
                      f"{solver}, round {round_}: {shown}", flush=True)
                bench_report.write_csv(a.csv, rows)
    return rows


def main():
    a = arguments()
    for d in ("runs", "logs"):
        os.makedirs(os.path.join(a.workdir, d), exist_ok=True)
    info = machine()
    # The worktrees of --against are this run's own: they go at the end,
    # also when a run fails or the benchmark is interrupted.
    head = bench_against.Program(info["commit"], a.executable, ROOT)
    head.has = parameters(a.executable)
    if not head.has:
        sys.exit(f"{a.executable} --print-parameters printed no entries")
    plan(a, [head])  # a --configs that selects nothing stops before a build
    with bench_against.Worktrees(a.workdir) as worktrees:
        runs = plan(a, [head] + huge_pages(a, head) + one_thread(a, head)
                    + earlier_programs(a, worktrees, head.commit))
        for program, code, algebra, solver, _, ranks, skip in runs:
            if skip:
                label = (f"{code} {program.commit}" if code == "vpcontact"
                         else code)
                print(f"note: skipping {label} {algebra} {solver} on {ranks}"
                      f" rank(s): {skip}", flush=True)
        if any(r[1] == "peer" and not r[6] for r in runs):
            # The peer compiles its forms on its first run (seconds, cached
            # in ~/.cache/fenics); a tiny run first keeps that out of the
            # timings.
            for solver in ("lu", "gamg"):
                subprocess.run([PYTHON, a.peer, "--n", "4", "--steps", "2",
                                "--solver", solver, "--quiet"], env=ENV,
                               capture_output=True)
        info.update(start_memory(
            a, head, any(r[1] == "peer" and not r[6] for r in runs)))
        rows = benchmark(a, info, runs)
    bench_report.write_csv(a.csv, rows)  # also where every run was skipped
    bench_report.write_report(a.out, a.csv, rows)
    print(f"wrote {a.csv} and {a.out}")


if __name__ == "__main__":
    main()
