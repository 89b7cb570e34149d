#!/usr/bin/python3
"""Benchmark of the paper scene (prm/paper_fig1.prm: friction, damage,
output every 10 steps, 100 steps) at several mesh sizes, serial and on 2
MPI ranks at the largest size. Writes doc/performance.md with, per run:
dofs, wall time, time per step split by phase (from the program's
TimerOutput table), peak memory, and the floor measured in the same run (one
displacement solve with everything reused) with the ratio step/floor.

Usage: bench.py VPCONTACT [SIZE ...]   (from the repository root)"""
import csv
import os
import platform
import re
import subprocess
import sys

executable = sys.argv[1]
sizes = [int(s) for s in sys.argv[2:]] or [64, 128, 256, 512]
steps = 100
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(size, ranks, solver="CG with AMG", background=True):
    tag = (f"{size}_{ranks}" + ("_cholesky" if solver == "Cholesky" else "")
           + ("" if background else "_sequential"))
    prm = f"/tmp/vpcontact_bench_{tag}.prm"
    with open(prm, "w") as f:
        f.write(open("prm/paper_fig1.prm").read())
        f.write(f"""
subsection Geometry
  set Subdivisions = {size}, {size}
end
subsection Output
  set Directory          = results/bench_{tag}
  set Report solve floor = true
end
subsection Solver
  set Linear solver       = {solver}
  set Second thread       = {"true" if background else "false"}
end
""")
    command = ([executable, prm] if ranks == 1 else
               ["mpirun", "-np", str(ranks), "--oversubscribe", executable, prm])
    out = subprocess.run(command, capture_output=True, text=True, env=env,
                         check=True).stdout
    matches = list(re.finditer(
        r"\| ([A-Za-z -]+?)\s+\|\s+(\d+) \|\s+([0-9.e+-]+)s \|", out))
    phases = {m.group(1).strip(): float(m.group(3)) for m in matches}
    calls = {m.group(1).strip(): int(m.group(2)) for m in matches}
    total = float(re.search(r"Total wallclock time elapsed since start\s+\|\s+"
                            r"([0-9.e+-]+)s", out).group(1))
    floor = re.search(r"one displacement solve takes ([0-9.e+-]+) s \("
                      r"(\d+ CG iterations|solve with the factors), "
                      r"(\d+) dofs", out)
    kernels = re.search(r"one matrix-vector product ([0-9.e+-]+) ms, one "
                        r"(?:preconditioner application|solve with the "
                        r"factors) ([0-9.e+-]+) ms", out)
    memory = re.search(r"Peak memory \(rank 0\):\s+(\d+) kB", out)
    # The friction active-set iterations and the linear iterations of every
    # step (CG iterations, or solves with the factors), from the run's
    # statistics.csv, averaged over the steps.
    with open(f"results/bench_{tag}/statistics.csv") as f:
        rows = [r for r in csv.DictReader(f) if int(r["step"]) > 0]
    active_set = sum(int(r["active_set_iterations"]) for r in rows) / len(rows)
    linear = sum(int(r["linear_iterations"]) for r in rows) / len(rows)
    if solver == "Cholesky" and not background:
        solver = "Cholesky, one thread"
    return dict(size=size, ranks=ranks, solver=solver, total=total,
                phases=phases,
                damage_solves=calls.get("Damage solve", 0) / steps,
                floor=float(floor.group(1)),
                floor_its=floor.group(2).split()[0] if "CG" in floor.group(2)
                else "factors",
                dofs=int(floor.group(3)),
                matvec=float(kernels.group(1)), vcycle=float(kernels.group(2)),
                memory=int(memory.group(1)) / 1024 if memory else float("nan"),
                active_set=active_set, linear=linear)


def bandwidth():
    """Best of 5 of the triad rate of scripts/bandwidth.cc in GB/s: one copy
    alone, and the sum over one copy per core run at the same time."""
    binary = "/tmp/vpcontact_bandwidth"
    subprocess.run(["g++", "-O2", "-o", binary, "scripts/bandwidth.cc"],
                   check=True)
    one, together = 0., 0.
    for _ in range(5):
        one = max(one, float(subprocess.run(
            [binary], capture_output=True, text=True, check=True).stdout))
        copies = [subprocess.Popen([binary], stdout=subprocess.PIPE, text=True)
                  for _ in range(os.cpu_count())]
        together = max(together, sum(float(p.communicate()[0])
                                     for p in copies))
    return one, together


results = []
for size in sizes:
    results.append(run(size, 1))
    print(f"{size}^2, 1 rank: {results[-1]['total']:.1f} s", flush=True)
results.append(run(sizes[-1], 2))
print(f"{sizes[-1]}^2, 2 ranks: {results[-1]['total']:.1f} s", flush=True)
# The serial Cholesky factorization (Solver/Linear solver = Cholesky),
# factorized once per run and reused by every step.
# The machine's speed changes by 30-50 % from run to run (the same 512^2
# run took 43 to 60 s within an hour), more than the growth per size that
# the table is to show. So the Cholesky sizes run in several rounds, the
# sizes one after the other within a round, and the table shows the median
# run of each size; every run is listed below it.
rounds = int(os.environ.get("VPCONTACT_BENCH_ROUNDS", "3"))
cholesky_runs = {size: [] for size in sizes}
for round_ in range(rounds):
    for size in sizes:
        cholesky_runs[size].append(run(size, 1, "Cholesky"))
        print(f"{size}^2, 1 rank, Cholesky, round {round_ + 1}: "
              f"{cholesky_runs[size][-1]['total']:.1f} s", flush=True)


def per_step_total(r):
    return sum(r["phases"].values()) - r["phases"].get("Setup", 0)


cholesky = [sorted(cholesky_runs[size], key=per_step_total)[rounds // 2]
            for size in sizes]
# The same in one thread (Solver/Second thread = false: the solves with the
# factors after the damage step instead of beside it, the passes over the
# cells in one piece), at the largest size.
sequential = run(sizes[-1], 1, "Cholesky", background=False)
print(f"{sizes[-1]}^2, 1 rank, Cholesky, one thread: {sequential['total']:.1f} s",
      flush=True)
bandwidth_one, bandwidth_all = bandwidth()

groups = [("displacement: assembly", ["Assemble right-hand side",
                                      "Assemble residual", "Assemble matrix"]),
          ("displacement: AMG setup or factorization",
           ["Build preconditioner"]),
          ("displacement: solve", ["Solve"]),
          ("stress update", ["Stress update"]),
          ("damage: assembly", ["Damage assembly"]),
          ("damage: solve", ["Damage solve"]),
          ("output", ["Postprocess and output"])]
with open("doc/performance.md", "w") as out:
    out.write(f"""# Performance

Measured by `scripts/bench` (this page is its output) on this machine:
{platform.processor() or platform.machine()}, {os.cpu_count()} cores,
Debian 12, deal.II 9.4 release build, Trilinos ML AMG. The scene is
`prm/paper_fig1.prm` (friction, damage, paper's law, fields written every 10
steps) with N x N cells and 100 steps, with the default solver of the
displacement system (CG with AMG) and, in the last rows, with `Solver/Linear
solver = Cholesky` (a supernodal factorization by SuiteSparse CHOLMOD
with OpenBLAS in two BLAS threads; the substitutions the program's own, in
one thread). A serial
run uses the machine's second core (`Solver/Second thread`, default true):
the passes over the cells work on two halves of the cells at once, and the
solves with the factors run beside the damage step; "Cholesky, one thread"
is the largest size with `Second thread = false`. On 2 ranks each rank is
bound to one core and uses one thread. The
**floor** is measured at the end of the same run: one solve of the
displacement system with the matrix and its AMG or factors as they are and
the last right-hand side, from a zero start vector (CG iterations in
brackets; for Cholesky one forward and one backward substitution). Times per
step are wall-clock milliseconds averaged over the 100 steps; the AMG setup
or the factorization (once per run, since the stick set does not change) is
in them, spread over the 100 steps; the mesh and dof setup is in the total
only. Where the solves with the factors run beside the damage step,
"displacement: solve" is the time the damage step did not hide.
The iterations per step are averages over the 100 steps of the columns
`active_set_iterations` and `linear_iterations` of the run's
`statistics.csv`: the stick/slip iterations of the friction solve, and
the CG iterations summed over them (with Cholesky, the solves with the
factors).

| cells | ranks | solver | dofs | total [s] | per step [ms] | floor [ms] | step / floor | """ +
              " | ".join(g for g, _ in groups) + """ | friction active-set iterations per step | displacement linear iterations per step | damage solves per step | peak memory rank 0 [MB] |
|---|---|---|---|---|---|---|---|""" + "---|" * len(groups) + "---|---|---|---|\n")
    for r in results + cholesky + [sequential]:
        per_step = 1000 * sum(v for k, v in r["phases"].items()
                              if k not in ("Setup",)) / steps
        cells = [1000 * sum(r["phases"].get(k, 0) for k in keys) / steps
                 for _, keys in groups]
        solver = "CG + AMG" if r["solver"] == "CG with AMG" else r["solver"]
        out.write(f"| {r['size']}^2 | {r['ranks']} | {solver} | {r['dofs']} | "
                  f"{r['total']:.1f} | {per_step:.1f} | "
                  f"{1000 * r['floor']:.1f} ({r['floor_its']}) | "
                  f"{per_step / (1000 * r['floor']):.2f} | " +
                  " | ".join(f"{c:.1f}" for c in cells) +
                  f" | {r['active_set']:.2f} | {r['linear']:.1f}"
                  f" | {r['damage_solves']:.1f} | {r['memory']:.0f} |\n")
    serial = [r for r in results if r["ranks"] == 1]
    for name, runs in (("CG + AMG", serial), ("Cholesky", cholesky)):
        out.write(f"\nGrowth of the time per step per 4x dofs, {name}: ")
        out.write(", ".join(
            f"{a['size']}^2 -> {b['size']}^2: x "
            f"{per_step_total(b) / per_step_total(a):.2f}"
            for a, b in zip(runs, runs[1:])) + ".\n")
    out.write(f"\nCholesky, every run ({rounds} rounds, the median in the "
              "table), time per step in ms: " + "; ".join(
                  f"{size}^2: " + ", ".join(
                      f"{1000 * per_step_total(r) / steps:.1f}"
                      for r in cholesky_runs[size]) for size in sizes)
              + ". Growth per 4x dofs within each round: " + "; ".join(
                  f"{a}^2 -> {b}^2: " + ", ".join(
                      f"x {per_step_total(rb) / per_step_total(ra):.2f}"
                      for ra, rb in zip(cholesky_runs[a], cholesky_runs[b]))
                  for a, b in zip(sizes, sizes[1:])) + ".\n")
    big1 = serial[-1]
    big2 = results[-1]
    out.write(f"\nStrong scaling at {big2['size']}^2: 1 rank {big1['total']:.1f} s, "
              f"2 ranks {big2['total']:.1f} s, speed-up "
              f"{big1['total'] / big2['total']:.2f}. Per phase, 1 rank against "
              "2: " + ", ".join(
                  f"{g} x {sum(big1['phases'].get(k, 0) for k in keys) / max(1e-9, sum(big2['phases'].get(k, 0) for k in keys)):.2f}"
                  for g, keys in groups) + ". The kernels of the solve, "
              f"timed at the end of the run: one matrix-vector product "
              f"{big1['matvec']:.2f} ms against {big2['matvec']:.2f} ms (x "
              f"{big1['matvec'] / big2['matvec']:.2f}), one AMG V-cycle "
              f"{big1['vcycle']:.2f} ms against {big2['vcycle']:.2f} ms (x "
              f"{big1['vcycle'] / big2['vcycle']:.2f}).\n")
    out.write(f"\nMemory bandwidth (`scripts/bandwidth.cc`, STREAM triad on "
              f"3 x 64 MB, best of 5): one process alone "
              f"{bandwidth_one:.1f} GB/s, {os.cpu_count()} processes at "
              f"the same time {bandwidth_all:.1f} GB/s together, x "
              f"{bandwidth_all / bandwidth_one:.2f}.\n")
    out.write(open("doc/performance_notes.md").read())
print("wrote doc/performance.md")
