#!/usr/bin/python3
"""Hertz's contact of a cylinder on a plane (prm/hertz_cylinder.prm) on the
three meshes of prm/meshes (h near the contact 0.008, 0.004 and 0.002):
the contact half-width and the largest pressure against Hertz's
a = sqrt(4 P R (1 - nu^2) / (pi E)) and p_max = 2 P / (pi a), with the
resolution of the half-width (half a node spacing) and the change of the
pressure from mesh to mesh, written between the markers of
doc/contact.md.

Usage: scripts/hertz"""
import math
import os
import tempfile

from scene_runs import ROOT, run_scene, write_block

P, R, E, NU = 10.0, 1.0, 1000.0, 0.3
A = math.sqrt(4 * P * R * (1 - NU ** 2) / (math.pi * E))
P_MAX = 2 * P / (math.pi * A)
# The meshes' size near the contact: gmsh's h of hertz_cylinder.geo, halved
# by its subdivision into quadrilaterals.
MESHES = [("hertz_cylinder_coarse", 0.008), ("hertz_cylinder_medium", 0.004),
          ("hertz_cylinder", 0.002)]


def run(mesh, work):
    text = (f"include {ROOT}/prm/hertz_cylinder.prm\n"
            "subsection Geometry\n"
            f"  set Mesh file = {ROOT}/prm/meshes/{mesh}.msh\nend\n"
            "subsection Output\n  set Output every = 0\nend\n")
    rows, seconds = run_scene(mesh, text, work)
    last = rows[-1]
    return dict(cells=int(last["cells"]), dofs=int(last["dofs"]),
                a=float(last["contact_length"]),
                p=float(last["max_contact_pressure"]),
                nodes=int(last["contact_nodes"]),
                its=int(last["active_set_iterations"]), seconds=seconds)


def change(values, k):
    """The relative change of values[k] from the previous mesh's."""
    if k == 0:
        return "–"
    return f"{100 * abs(values[k] - values[k - 1]) / abs(values[k]):.2f} %"


def table(results):
    lines = [f"Hertz: a = {A:.5f}, p_max = {P_MAX:.3f}.", "",
             "| mesh | h at the contact | cells | dofs | contact nodes | "
             "active-set iterations | a | error of a | h/2 of a | p_max | "
             "error of p_max | change from the coarser mesh | run [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    ps = [r["p"] for _, _, r in results]
    for k, (mesh, h, r) in enumerate(results):
        lines.append(f"| {mesh} | {h} | {r['cells']} | {r['dofs']} | "
                     f"{r['nodes']} | {r['its']} | {r['a']:.5f} | "
                     f"{100 * abs(r['a'] - A) / A:.2f} % | "
                     f"{100 * h / 2 / A:.2f} % | {r['p']:.3f} | "
                     f"{100 * abs(r['p'] - P_MAX) / P_MAX:.2f} % | "
                     f"{change(ps, k)} | {r['seconds']:.1f} |")
    return lines


def main():
    results = []
    with tempfile.TemporaryDirectory() as work:
        for mesh, h in MESHES:
            results.append((mesh, h, run(mesh, work)))
            print(table(results)[-1], flush=True)
    doc = os.path.join(ROOT, "doc", "contact.md")
    write_block(doc, "hertz", table(results))
    print(f"wrote {doc}")


if __name__ == "__main__":
    main()
