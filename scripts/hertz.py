#!/usr/bin/python3
"""Hertz's contact of a cylinder on a plane (prm/hertz_cylinder.prm) on the
three meshes of prm/meshes (h near the contact 0.008, 0.004 and 0.002):
the contact half-width and the largest pressure against Hertz's
a = sqrt(4 P R (1 - nu^2) / (pi E)) and p_max = 2 P / (pi a), with the
resolution of the half-width (half a node spacing) and the change of the
pressure from mesh to mesh, written between the markers of
doc/contact.md; and the 3D slice with Coulomb friction
(prm/hertz_cylinder_3d.prm) on its three meshes: contact, stick and slip
nodes and the active-set iterations, written between the markers of
doc/friction.md.

And Cattaneo-Mindlin (prm/cattaneo_mindlin.prm) at nu = 0.3 and 0.45: the
stick zone's half-width against c = a sqrt(1 - Q / (mu P)) with the
run's own a, P and Q, into doc/contact.md.

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


MESHES_3D = [("hertz_cylinder_3d_coarse", 0.016),
             ("hertz_cylinder_3d_medium", 0.008), ("hertz_cylinder_3d", 0.004)]


def run(mesh, work, scene="hertz_cylinder"):
    text = (f"include {ROOT}/prm/{scene}.prm\n"
            "subsection Geometry\n"
            f"  set Mesh file = {ROOT}/prm/meshes/{mesh}.msh\nend\n"
            "subsection Output\n  set Output every = 0\nend\n")
    rows, seconds = run_scene(mesh, text, work)
    last = rows[-1]
    return dict(cells=int(last["cells"]), dofs=int(last["dofs"]),
                a=float(last.get("contact_length") or last["contact_area"]),
                p=float(last["max_contact_pressure"]),
                nodes=int(last["contact_nodes"]),
                stick=int(last["stick_nodes"]), slip=int(last["slip_nodes"]),
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


def run_cattaneo(nu, work):
    text = (f"include {ROOT}/prm/cattaneo_mindlin.prm\n"
            "subsection Geometry\n"
            f"  set Mesh file = {ROOT}/prm/meshes/cattaneo_mindlin.msh\nend\n"
            f"subsection Material\n  set Poisson's ratio = {nu}\nend\n"
            "subsection Output\n  set Output every = 0\nend\n")
    rows, seconds = run_scene(f"cattaneo_mindlin_{nu}", text, work)
    normal = [r for r in rows if abs(float(r["time"]) - 1) < 1e-9][0]
    last = rows[-1]
    P, Q = float(last["normal_force"]), float(last["friction_force"])
    a = float(last["contact_length"]) / 2
    c = float(last["stick_length"]) / 2
    return dict(nu=nu, P=P, Q=Q, a=a, c=c, mu=0.3,
                normal=float(normal["stick_length"])
                / float(normal["contact_length"]),
                its=max(int(r["active_set_iterations"]) for r in rows[1:]),
                seconds=seconds)


def table_cattaneo(results):
    lines = ["| ν | P | Q | a | stick ratio after the normal load | c | "
             "c/a | Cattaneo–Mindlin sqrt(1 − Q/(μP)) | difference | "
             "most active-set iterations in a step | run [s] |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        ratio = r["c"] / r["a"]
        closed = math.sqrt(1 - r["Q"] / (r["mu"] * r["P"]))
        lines.append(f"| {r['nu']} | {r['P']:.3f} | {r['Q']:.3f} | "
                     f"{r['a']:.4f} | {r['normal']:.3f} | {r['c']:.4f} | "
                     f"{ratio:.3f} | {closed:.3f} | "
                     f"{100 * (ratio / closed - 1):+.1f} % | {r['its']} | "
                     f"{r['seconds']:.1f} |")
    return lines


def table_3d(results):
    lines = ["| mesh | h at the contact | cells | dofs | nodes in contact | "
             "stick / slip | active-set iterations | p_max | run [s] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for mesh, h, r in results:
        lines.append(f"| {mesh} | {h} | {r['cells']} | {r['dofs']} | "
                     f"{r['nodes']} | {r['stick']} / {r['slip']} | "
                     f"{r['its']} | {r['p']:.3f} | {r['seconds']:.1f} |")
    return lines


def main():
    results = []
    with tempfile.TemporaryDirectory() as work:
        for mesh, h in MESHES:
            results.append((mesh, h, run(mesh, work)))
            print(table(results)[-1], flush=True)
        results_3d = []
        for mesh, h in MESHES_3D:
            results_3d.append((mesh, h, run(mesh, work, "hertz_cylinder_3d")))
            print(table_3d(results_3d)[-1], flush=True)
        results_cm = []
        for nu in (0.3, 0.45):
            results_cm.append(run_cattaneo(nu, work))
            print(table_cattaneo(results_cm)[-1], flush=True)
    doc = os.path.join(ROOT, "doc", "contact.md")
    write_block(doc, "hertz", table(results))
    write_block(doc, "hertz (Cattaneo–Mindlin)", table_cattaneo(results_cm))
    doc_3d = os.path.join(ROOT, "doc", "friction.md")
    write_block(doc_3d, "hertz", table_3d(results_3d))
    print(f"wrote {doc} and {doc_3d}")


if __name__ == "__main__":
    main()
