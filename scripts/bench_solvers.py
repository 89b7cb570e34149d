#!/usr/bin/python3
"""Times the displacement solvers against each other on 2D and 3D scenes of
growing size (the paper scenes, the 2D paper scene whose base slips, the
plate and the block with a hole), for
the thresholds of Solver/Linear solver = automatic: each scene and size with Cholesky (1 rank), MUMPS and CG with AMG (1 and 2 ranks),
ten steps, no field output; writes doc/figures/bench_solvers.csv, and
scripts/bench_report.py puts the table into doc/performance.md.

Usage: bench_solvers.py VPCONTACT [--steps N] [--quick]
A benchmark reports figures: nothing here passes or fails."""
import argparse
import csv
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import bench  # noqa: E402  (next to this file)

COLUMNS = ["scene", "size", "dim", "dofs", "solver", "ranks", "status",
           "steps", "per_step_ms", "first_step_ms", "build_s",
           "rest_per_step_ms", "active_set_its",
           "mem_all_mb", "date",
           "cpu", "commit"]

# (scene, size label, dimension, parameter lines)
def scenes(quick):
    box2 = [128, 256] if quick else [128, 256, 512]
    box3 = [16, 24] if quick else [16, 24, 32, 40]
    hole = [0, 1] if quick else [0, 1, 2]
    out = []
    for n in box2:
        out.append(("paper_fig1", f"{n}^2", 2,
                    f"include {ROOT}/prm/paper_fig1.prm\n"
                    f"subsection Geometry\n  set Subdivisions = {n}, {n}\n"
                    "end\n"))
    # The paper scene without damage and with a low friction bound: most of
    # the base slips, and its stick set changes in most steps, each change
    # a new factorization or AMG hierarchy.
    for n in box2:
        out.append(("paper_fig1_slip", f"{n}^2", 2,
                    f"include {ROOT}/prm/paper_fig1_slip.prm\n"
                    f"subsection Geometry\n  set Subdivisions = {n}, {n}\n"
                    "end\n"))
    for n in box3:
        out.append(("paper_fig1_3d", f"{n}^3", 3,
                    f"include {ROOT}/prm/paper_fig1_3d.prm\n"
                    f"subsection Geometry\n  set Subdivisions = {n}, {n}, "
                    f"{n}\nend\n"))
    for r in ([1, 2] if quick else [1, 2, 3]):
        out.append(("plate_with_hole", f"refined {r}x", 2,
                    f"include {ROOT}/prm/plate_with_hole.prm\n"
                    "subsection Geometry\n"
                    f"  set Mesh file = {ROOT}/prm/meshes/plate_with_hole.msh\n"
                    f"  set Global refinements = {r}\nend\n"))
    for r in hole:
        for mesh in ("block_with_hole", "block_with_hole_tets"):
            if mesh.endswith("tets") and r > 1:
                continue
            out.append((mesh, f"refined {r}x", 3,
                        f"include {ROOT}/prm/block_with_hole.prm\n"
                        "subsection Geometry\n"
                        f"  set Mesh file = {ROOT}/prm/meshes/{mesh}.msh\n"
                        f"  set Global refinements = {r}\nend\n"))
    return out


SOLVERS = [("Cholesky", 1, "Trilinos"), ("CG with AMG", 1, "Trilinos"),
           ("MUMPS", 1, "PETSc"), ("MUMPS", 2, "PETSc"),
           ("CG with AMG", 2, "Trilinos")]


def run(a, scene, size, lines, solver, ranks, algebra):
    name = re.sub(r"[^A-Za-z0-9]+", "_", f"{scene}_{size}_{solver}_{ranks}")
    folder = os.path.join(a.workdir, name)
    prm = os.path.join(a.workdir, name + ".prm")
    with open(prm, "w") as f:
        f.write(lines + "subsection Time\n  set End time = "
                f"{a.steps / 100:g}\n  set Time step = 0.01\nend\n"
                "subsection Solver\n"
                f"  set Linear solver = {solver}\n"
                f"  set Linear algebra = {algebra}\nend\n"
                "subsection Error estimate\n  set Estimate error = false\nend\n"
                f"subsection Output\n  set Directory = {folder}\n"
                "  set Output every = 0\nend\n")
    command = [a.executable, prm]
    if ranks > 1:
        command = ["mpirun", "-np", str(ranks), "--oversubscribe"] + command
    log = os.path.join(a.workdir, name + ".log")
    with open(log, "w") as out:
        status = subprocess.run(["/usr/bin/time", "-f", "%M", "-o",
                                 log + ".rss"] + command, stdout=out,
                                stderr=subprocess.STDOUT,
                                env=dict(os.environ,
                                         OMPI_ALLOW_RUN_AS_ROOT="1",
                                         OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1"),
                                timeout=1800).returncode
    row = {"scene": scene, "size": size, "solver": solver, "ranks": ranks,
           "status": "ok" if status == 0 else f"failed ({status})"}
    if status != 0:
        return row
    return measured(row, folder, log, ranks)


def measured(row, folder, log, ranks):
    """The figures of a finished run into @p row: the time per step is the
    run's time after its set-up (the timer's total less *Setup*) over the
    steps, so that the factorization or the AMG hierarchy counts wherever
    the run builds it (a factorization may come before the first step, at
    the initial state, or in it)."""
    with open(os.path.join(folder, "statistics.csv")) as f:
        steps = [r for r in csv.DictReader(f)][1:]
    times = [float(r["wall_time"]) * 1000 for r in steps]
    with open(log) as f:
        total, phases = bench.timer_table(f.read())
    setup = phases.get("Setup", (0, 0., None))[1]
    # The factorizations or AMG hierarchies (every one of the run, after
    # each change of the stick set too) and the rest of the steps.
    build = phases.get("Build preconditioner", (0, 0., None))[1]
    row.update({"dofs": int(steps[-1]["dofs"]), "steps": len(times),
                "per_step_ms": (total - setup) * 1000 / len(times),
                "build_s": build,
                "rest_per_step_ms": (total - setup - build) * 1000
                / len(times),
                "first_step_ms": times[0],
                "active_set_its": sum(int(r["active_set_iterations"])
                                      for r in steps) / len(steps)})
    with open(log + ".rss") as f:
        rss = [int(v) for v in f.read().split() if v.isdigit()]
    row["mem_all_mb"] = (rss[-1] * ranks / 1024) if rss else ""
    return row


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("executable")
    p.add_argument("--steps", type=int, default=10)
    p.add_argument("--quick", action="store_true")
    p.add_argument("--workdir", default="/tmp/vpcontact_bench_solvers")
    p.add_argument("--csv", default=os.path.join(ROOT, "doc", "figures",
                                                 "bench_solvers.csv"))
    a = p.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    machine = bench.machine()
    rows = []
    for scene, size, dim, lines in scenes(a.quick):
        for solver, ranks, algebra in SOLVERS:
            row = run(a, scene, size, lines, solver, ranks, algebra)
            row.update({"dim": dim}, **{k: machine.get(k, "")
                                        for k in ("date", "cpu", "commit")})
            print({k: row.get(k) for k in ("scene", "size", "dofs", "solver",
                                           "ranks", "status",
                                           "per_step_ms")}, flush=True)
            rows.append(row)
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
