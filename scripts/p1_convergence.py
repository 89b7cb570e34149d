#!/usr/bin/python3
"""The paper scene (prm/paper_fig1_p1.prm on triangles, prm/paper_fig1.prm on
quadrilaterals) at 32^2, 64^2 and 128^2 squares, serial: the displacement at
the monitor points (1, 1) and (1, 0.5) at T, its change under refinement and
observed order, and the difference between P1 and Q1 at each size. Writes
doc/figures/p1_convergence.csv and the table between the markers of
doc/simplex.md.

Usage: scripts/p1_convergence [--steps N]  (default: the scene's 100)."""
import argparse
import csv
import math
import os
import tempfile

from scene_runs import ROOT, run_scene, write_block

SIZES = (32, 64, 128)
SCENES = {"P1": "paper_fig1_p1", "Q1": "paper_fig1"}
COLUMNS = ("monitor1_ux", "monitor1_uy", "monitor2_ux", "monitor2_uy")


def run(element, n, steps, work):
    text = (f"include {ROOT}/prm/{SCENES[element]}.prm\n"
            "subsection Geometry\n"
            f"  set Subdivisions = {n}, {n}\nend\n"
            "subsection Output\n  set Output every = 0\n"
            "  set Monitor points = 1, 1; 1, 0.5\nend\n")
    if steps:
        text += f"subsection Time\n  set End time = {steps * 0.01}\nend\n"
    rows, seconds = run_scene(f"{element}_{n}", text, work)
    last = rows[-1]
    # The scenes estimate every 10th step and the last; the other rows leave
    # the estimate columns empty.
    estimate = max(float(r["estimate_space"]) + float(r["estimate_time"])
                   for r in rows if r["estimate_space"])
    cg = [int(r["linear_iterations"]) for r in rows[1:]]
    return dict(element=element, n=n, cells=int(last["cells"]),
                dofs=int(last["dofs"]), time=float(last["time"]),
                estimate=estimate, cg=sum(cg) / len(cg), seconds=seconds,
                **{c: float(last[c]) for c in COLUMNS})


def distance(a, b):
    return math.sqrt(sum((a[c] - b[c]) ** 2 for c in COLUMNS))


def add_derived(results):
    """Change from the previous size, observed order, and P1 - Q1."""
    for element in SCENES:
        rows = [r for r in results if r["element"] == element]
        for i, r in enumerate(rows):
            r["change"] = distance(r, rows[i - 1]) if i > 0 else None
            r["order"] = None
            if i > 1 and r["change"] > 0:
                r["order"] = math.log2(rows[i - 1]["change"] / r["change"])
    for r in results:
        other = [q for q in results if q["n"] == r["n"]
                 and q["element"] != r["element"]]
        r["to_other"] = distance(r, other[0]) if other else None


def fmt(x, spec):
    return "–" if x is None else format(x, spec)


def table(results):
    lines = ["| element | squares | cells | dofs | u_x(1, 1) | u_y(1, 1) | "
             "u_x(1, 0.5) | u_y(1, 0.5) | change from the coarser mesh | "
             "observed order | P1 − Q1 | estimated error | CG its per step | "
             "run [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        lines.append(
            f"| {r['element']} | {r['n']}² | {r['cells']} | {r['dofs']} | "
            + " | ".join(f"{r[c]:.6e}" for c in COLUMNS)
            + f" | {fmt(r['change'], '.2e')} | {fmt(r['order'], '.2f')} | "
            f"{fmt(r['to_other'], '.2e')} | {r['estimate']:.3e} | "
            f"{r['cg']:.1f} | {r['seconds']:.1f} |")
    return lines


def summary(results):
    """The sentences under the table."""
    p1 = [r for r in results if r["element"] == "P1"]
    q1 = [r for r in results if r["element"] == "Q1"]
    return ["", f"On the finest meshes the observed order of the monitor "
            f"displacement is {p1[-1]['order']:.2f} for P1 and "
            f"{q1[-1]['order']:.2f} for Q1, with k = 0.01 on every mesh. "
            f"P1 − Q1 goes from {p1[0]['to_other']:.2e} at {p1[0]['n']}² to "
            f"{p1[-1]['to_other']:.2e} at {p1[-1]['n']}², a factor "
            f"{p1[0]['to_other'] / p1[-1]['to_other']:.1f} over two "
            f"refinements: both elements approach one limit. At "
            f"{p1[-1]['n']}² the P1 run takes "
            f"{p1[-1]['seconds'] / q1[-1]['seconds']:.2f} times the Q1 run's "
            f"time, with {p1[-1]['cg'] / q1[-1]['cg']:.2f} times its CG "
            f"iterations per step on the same number of unknowns."]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=0)
    args = parser.parse_args()
    results = []
    with tempfile.TemporaryDirectory() as work:
        for element in SCENES:
            for n in SIZES:
                results.append(run(element, n, args.steps, work))
                print(element, n, f"{results[-1]['seconds']:.1f} s",
                      flush=True)
    add_derived(results)
    figures = os.path.join(ROOT, "doc", "figures", "p1_convergence.csv")
    with open(figures, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(results[0].keys()))
        writer.writeheader()
        writer.writerows(results)
    doc = os.path.join(ROOT, "doc", "simplex.md")
    write_block(doc, "p1_convergence", table(results) + summary(results))
    print("\n".join(table(results)))
    print(f"wrote {doc} and {figures}")


if __name__ == "__main__":
    main()
