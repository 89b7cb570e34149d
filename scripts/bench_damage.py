"""Times the two solvers of the damage obstacle problem side by side on the
paper scene (Solver/Damage obstacle solver = active set | SNES VI, both with
Solver/Linear algebra = PETSc and the MUMPS displacement solve, one rank) and
writes doc/figures/damage_obstacle_solvers.md. Called by scripts/bench_damage.
"""
import argparse
import csv
import os
import re
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOLVERS = ("active set", "SNES VI")


def run(executable, workdir, size, steps, solver):
    tag = f"{size}_{solver.replace(' ', '_')}"
    folder = os.path.join(workdir, tag)
    prm = os.path.join(workdir, tag + ".prm")
    with open(prm, "w") as f:
        f.write(open(os.path.join(ROOT, "prm", "paper_fig1.prm")).read())
        f.write(f"\nsubsection Geometry\n  set Subdivisions = {size}, {size}\n"
                f"end\nsubsection Time\n  set End time = 1\n"
                f"  set Time step = {1 / steps!r}\nend\n"
                f"subsection Output\n  set Directory = {folder}\n"
                f"  set Output every = 0\nend\n"
                f"subsection Solver\n  set Linear algebra = PETSc\n"
                f"  set Linear solver = MUMPS\n"
                f"  set Damage obstacle solver = {solver}\nend\n")
    out = subprocess.run([executable, prm], capture_output=True, text=True,
                         check=True).stdout
    total = float(re.search(r"Total wallclock time elapsed since start\s*\|"
                            r"\s*([\d.]+)s", out).group(1))
    damage = re.search(r"\| Damage solve\s*\|\s*(\d+)\s*\|\s*([\d.]+)s", out)
    rows = list(csv.DictReader(open(os.path.join(folder, "statistics.csv"))))
    return dict(total=total, calls=int(damage.group(1)),
                seconds=float(damage.group(2)),
                iterations=sum(int(r["damage_iterations"]) for r in rows),
                rows=rows)


def largest_difference(a, b):
    """The largest relative difference of the printed statistics."""
    keys = ("u_max", "von_mises_max", "elastic_energy", "damage_min",
            "damaged_fraction")
    return max(abs(float(x[k]) - float(y[k])) / max(abs(float(x[k])), 1e-300)
               for x, y in zip(a, b) for k in keys)


def main():
    p = argparse.ArgumentParser(description=__doc__)
    p.add_argument("executable")
    p.add_argument("sizes", nargs="*", type=int, default=[128, 256, 512])
    p.add_argument("--steps", type=int, default=100)
    p.add_argument("--workdir", default="/tmp/vpcontact_bench_damage")
    p.add_argument("--out", default=os.path.join(
        ROOT, "doc", "figures", "damage_obstacle_solvers.md"))
    a = p.parse_args()
    os.makedirs(a.workdir, exist_ok=True)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short",
                             "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    lines = [
        "# Damage obstacle solvers side by side",
        "",
        f"Written by `scripts/bench_damage` at commit {commit} on "
        f"{time.strftime('%Y-%m-%d %H:%M')}, {os.cpu_count()} cores: the "
        f"paper scene, {a.steps} steps, no field output, one rank, "
        "`Solver/Linear algebra = PETSc`, `Linear solver = MUMPS`; only "
        "`Solver/Damage obstacle solver` differs. *solves*: CG solves "
        "(active set) or Newton steps (SNES VI) over the run.",
        "",
        "| cells | solver | run [s] | damage solve [s] | solves | "
        "largest relative difference of the statistics |",
        "|---|---|---|---|---|---|"]
    for size in a.sizes:
        results = {s: run(a.executable, a.workdir, size, a.steps, s)
                   for s in SOLVERS}
        difference = largest_difference(results[SOLVERS[0]]["rows"],
                                        results[SOLVERS[1]]["rows"])
        for s in SOLVERS:
            r = results[s]
            lines.append(f"| {size}² | {s} | {r['total']:.1f} | "
                         f"{r['seconds']:.2f} | {r['iterations']} | "
                         + (f"{difference:.1e} |" if s == SOLVERS[1]
                            else "– |"))
        print(lines[-2] + "\n" + lines[-1], flush=True)
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
