#!/usr/bin/python3
"""Active-set iterations of the Tresca friction iteration under mesh
refinement, in 2D (prm/paper_fig1_slip.prm) and 3D
(prm/paper_fig1_3d_slip.prm): runs each scene on three meshes (serial, the
scene's own solver) and writes the table between the markers of
doc/friction.md.

Usage: scripts/friction_iterations [--steps N]  (default: the scenes' 100)."""
import argparse
import os
import tempfile

from scene_runs import ROOT, run_scene, write_block

RUNS = [("paper_fig1_slip", 2, n) for n in (32, 64, 128)] + \
       [("paper_fig1_3d_slip", 3, n) for n in (6, 12, 24)]


def run(scene, dim, n, steps, work):
    text = (f"include {ROOT}/prm/{scene}.prm\n"
            "subsection Geometry\n"
            f"  set Subdivisions = {', '.join([str(n)] * dim)}\nend\n"
            "subsection Output\n  set Output every = 0\nend\n"
            "subsection Error estimate\n  set Estimate error = false\nend\n")
    if steps:
        text += f"subsection Time\n  set End time = {steps * 0.01}\nend\n"
    rows, seconds = run_scene(f"{scene}_{n}", text, work)
    its = [int(r["active_set_iterations"]) for r in rows[1:]]
    nodes = int(rows[0]["stick_nodes"]) + int(rows[0]["slip_nodes"])
    violation = max(float(r["friction_violation"] or 0) for r in rows)
    mixed = sum(1 for r in rows[1:] if int(r["stick_nodes"]) > 0
                and int(r["slip_nodes"]) > 0)
    return dict(scene=scene, dim=dim, n=n, dofs=int(rows[0]["dofs"]),
                nodes=nodes, first=its[0], later=max(its[1:]),
                mean=sum(its) / len(its), steps=len(its), mixed=mixed,
                violation=violation, seconds=seconds)


def table(results):
    lines = ["| scene | mesh | dofs | contact nodes | step 1 (cold start) | "
             "largest after step 1 | mean | steps with stick and slip | "
             "largest violation (of g) | run [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        mesh = " × ".join([str(r["n"])] * r["dim"])
        lines.append(f"| {r['scene']} | {mesh} | {r['dofs']} | {r['nodes']} "
                     f"| {r['first']} | {r['later']} | {r['mean']:.2f} | "
                     f"{r['mixed']} of {r['steps']} | {r['violation']:.1e} | "
                     f"{r['seconds']:.0f} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=0)
    args = parser.parse_args()
    results = []
    with tempfile.TemporaryDirectory() as work:
        for scene, dim, n in RUNS:
            results.append(run(scene, dim, n, args.steps, work))
            print(table(results)[-1], flush=True)
    doc = os.path.join(ROOT, "doc", "friction.md")
    write_block(doc, "friction_iterations", table(results))
    print(f"wrote {doc}")


if __name__ == "__main__":
    main()
