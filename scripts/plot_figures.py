#!/usr/bin/python3
"""Figures of the paper scene from vpcontact's own output (run by
scripts/figures): the paper's Figs. 2-4 (deformed mesh with the initial
outline, von Mises norm and damage at the final time), the contact status
along the base for paper_fig1_slip, the contact face and the damage of the
3D scenes (paper_fig1_3d_slip, paper_fig1_3d), and time histories from
statistics.csv.

Usage: plot_figures.py RESULTS_FOLDER FIGURE_FOLDER
Needs Debian's python3-matplotlib and python3-vtk9 (/usr/bin/python3)."""
import csv
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import vtk
from matplotlib.collections import PolyCollection
from vtk.util.numpy_support import vtk_to_numpy


def time_series(folder):
    """(time, .pvtu path) of every output in folder/solution.pvd."""
    root = ET.parse(os.path.join(folder, "solution.pvd")).getroot()
    return [(float(d.get("timestep")), os.path.join(folder, d.get("file")))
            for d in root.iter("DataSet")]


def read(pvtu):
    """Points, cells (n x 4 vertex indices of quadrilaterals or n x 3 of
    triangles), point arrays by name, cell arrays by name."""
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(pvtu)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2]
    connectivity = vtk_to_numpy(grid.GetCells().GetData())
    cells = connectivity.reshape(-1, connectivity[0] + 1)[:, 1:]
    data = grid.GetPointData()
    arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    by_cell = grid.GetCellData()
    cell_arrays = {by_cell.GetArrayName(i): vtk_to_numpy(by_cell.GetArray(i))
                   for i in range(by_cell.GetNumberOfArrays())}
    return points, cells, arrays, cell_arrays


def statistics(folder):
    with open(os.path.join(folder, "statistics.csv")) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) if r[k] else np.nan for r in rows])
            for k in rows[0]}


def deformed(points, arrays):
    return points + arrays["displacement"][:, :2]


def save(fig, path):
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    print("wrote", path)


def histories(folder, out, scene):
    """Time histories of a damage scene with friction from statistics.csv:
    largest von Mises norm, damage, friction utilisation."""
    s = statistics(folder)
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.6))
    axes[0].plot(s["time"], s["von_mises_max"])
    axes[0].set_ylabel("max von Mises [N/m$^2$]")
    axes[1].plot(s["time"], s["damage_min"], label="min $\\zeta$")
    axes[1].plot(s["time"], 1 - s["damaged_fraction"],
                 label="sound fraction ($\\zeta$ = 1)")
    axes[1].set_ylim(-0.05, 1.05)
    axes[1].legend()
    axes[2].plot(s["time"], s["friction_utilisation"])
    axes[2].set_ylabel("max $|\\sigma_\\tau|/g$")
    for a in axes:
        a.set_xlabel("t [s]")
        a.grid(alpha=0.3)
    fig.suptitle(f"{scene}: time histories from statistics.csv")
    save(fig, os.path.join(out, f"{scene}_history.png"))


def paper_figures(folder, out, scene="paper_fig1", element=""):
    """Figs. 2-4 of the paper; element names a non-default element in the
    titles."""
    t, pvtu = time_series(folder)[-1]
    points, cells, arrays, cell_arrays = read(pvtu)
    x = deformed(points, arrays)

    # Fig. 2: deformed mesh at the final time and the initial configuration.
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.add_collection(PolyCollection(x[cells], facecolors="none",
                                     edgecolors="k", linewidths=0.3))
    ax.plot([0, 1, 1, 0, 0], [0, 0, 1, 1, 0], "r--", lw=1.2,
            label="initial configuration")
    ax.set_aspect("equal")
    ax.autoscale()
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12))
    ax.set_title(f"Deformed mesh at t = {t:g} s (true scale){element}")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    save(fig, os.path.join(out, f"{scene}_deformed.png"))

    # Fig. 3: von Mises norm of the stress (cell averages) on the deformed body.
    fig, ax = plt.subplots(figsize=(6.4, 5))
    values = cell_arrays["von_mises"]
    patches = PolyCollection(x[cells], array=values, cmap="viridis",
                             edgecolors="face", linewidths=0.2)
    ax.add_collection(patches)
    fig.colorbar(patches, ax=ax, label="von Mises norm [N/m$^2$]")
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_title(f"Von Mises stress norm at t = {t:g} s{element}")
    save(fig, os.path.join(out, f"{scene}_von_mises.png"))

    # Fig. 4: damage field (Q1 or P1, nodal values) on the deformed body.
    fig, ax = plt.subplots(figsize=(6.4, 5))
    triangles = cells if cells.shape[1] == 3 else \
        np.vstack([cells[:, [0, 1, 2]], cells[:, [0, 2, 3]]])
    shading = ax.tripcolor(x[:, 0], x[:, 1], triangles, arrays["damage"],
                           shading="gouraud", cmap="inferno", vmin=0, vmax=1)
    fig.colorbar(shading, ax=ax, label="damage $\\zeta$ (1 sound, 0 broken)")
    ax.set_aspect("equal")
    ax.set_title(f"Damage at t = {t:g} s{element}")
    save(fig, os.path.join(out, f"{scene}_damage.png"))

    histories(folder, out, scene)


def slip_figures(folder, out, g=20.0):
    series = time_series(folder)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    shown = series[1::3]
    if shown[-1] != series[-1]:
        shown.append(series[-1])
    for t, pvtu in shown:
        points, cells, arrays, _ = read(pvtu)
        base = np.isclose(points[:, 1], 0.0)
        x = points[base, 0]
        status = arrays["contact_status"][base]
        traction = arrays["tangential_traction"][base]
        order = np.argsort(x)
        x, status, traction = x[order], status[order], traction[order]
        keep = status > 0
        line, = ax.plot(x[keep], traction[keep], "-", lw=1, label=f"t = {t:g}")
        ax.plot(x[status == 1], traction[status == 1], "o", ms=3,
                color=line.get_color())
        ax.plot(x[status == 2], traction[status == 2], "x", ms=5,
                color=line.get_color())
    ax.axhline(g, color="k", ls=":", lw=1)
    ax.axhline(-g, color="k", ls=":", lw=1, label="$\\pm g$")
    ax.set_xlabel("x along the base [m]")
    ax.set_ylabel("tangential traction $\\sigma_\\tau$ [N/m$^2$]")
    ax.set_title("paper_fig1_slip: contact status along the base "
                 "(o stick, x slip)")
    ax.legend(fontsize=8, ncol=2)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "paper_fig1_slip_contact.png"))

    s = statistics(folder)
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.plot(s["time"], s["stick_nodes"], label="stick nodes")
    ax.plot(s["time"], s["slip_nodes"], label="slip nodes")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("contact nodes")
    ax.legend()
    ax.grid(alpha=0.3)
    ax.set_title("paper_fig1_slip: stick and slip nodes")
    save(fig, os.path.join(out, "paper_fig1_slip_history.png"))


def read_points(pvtu):
    """Points (n x 3) and point arrays by name of a 3D output (the points
    repeat per cell; a point's arrays are its node's values)."""
    reader = vtk.vtkXMLPUnstructuredGridReader()
    reader.SetFileName(pvtu)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    return (vtk_to_numpy(grid.GetPoints().GetData()),
            {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
             for i in range(data.GetNumberOfArrays())})


def slip3d_figures(folder, out, g=20.0):
    """The contact face z = 0 of paper_fig1_3d_slip at three times: stick
    and slip nodes and the tangential traction sigma_tau / g as arrows."""
    series = time_series(folder)
    shown = [series[1], series[len(series) // 2], series[-1]]
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.4))
    for ax, (t, pvtu) in zip(axes, shown):
        points, arrays = read_points(pvtu)
        face = np.isclose(points[:, 2], 0.0) & (arrays["contact_status"] > 0)
        _, first = np.unique(np.round(points[face], 12), axis=0,
                             return_index=True)
        p = points[face][first]
        status = arrays["contact_status"][face][first]
        traction = arrays["tangential_traction"][face][first] / g
        for value, marker, label in ((1, "o", "stick"), (2, "x", "slip")):
            pick = status == value
            ax.plot(p[pick, 0], p[pick, 1], marker, ms=4, label=label)
        ax.quiver(p[:, 0], p[:, 1], traction[:, 0], traction[:, 1],
                  angles="xy", scale_units="xy", scale=12, width=0.004)
        ax.set_aspect("equal")
        ax.set_xlim(-0.05, 1.05)
        ax.set_ylim(-0.05, 1.05)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.set_title(f"t = {t:g} s")
    axes[0].legend(loc="upper left", fontsize=8)
    fig.suptitle("paper_fig1_3d_slip: the contact face z = 0 (clamped edge "
                 "x = 0); arrows: $\\sigma_\\tau / g$, length 1/12 at "
                 "$|\\sigma_\\tau| = g$")
    save(fig, os.path.join(out, "paper_fig1_3d_slip_contact.png"))


def paper3d_figures(folder, out):
    """The damage of paper_fig1_3d at the final time on the faces y = 0 and
    z = 0 (the contact face), and its time histories."""
    t, pvtu = time_series(folder)[-1]
    points, arrays = read_points(pvtu)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.6))
    for ax, (axis, plane) in zip(axes, ((1, "y = 0, the side"),
                                        (2, "z = 0, the contact face"))):
        face = np.isclose(points[:, axis], 0.0)
        other = [a for a in range(3) if a != axis]
        shading = ax.tricontourf(points[face, other[0]], points[face, other[1]],
                                 arrays["damage"][face],
                                 levels=np.linspace(0, 1, 21), cmap="inferno")
        ax.set_aspect("equal")
        ax.set_xlabel("xyz"[other[0]] + " [m]")
        ax.set_ylabel("xyz"[other[1]] + " [m]")
        ax.set_title(plane)
    fig.colorbar(shading, ax=axes, label="damage $\\zeta$ (1 sound, 0 broken)")
    fig.suptitle(f"paper_fig1_3d: damage at t = {t:g} s")
    save(fig, os.path.join(out, "paper_fig1_3d_damage.png"))

    histories(folder, out, "paper_fig1_3d")


if __name__ == "__main__":
    results, figures = sys.argv[1], sys.argv[2]
    os.makedirs(figures, exist_ok=True)
    paper_figures(os.path.join(results, "paper_fig1"), figures)
    paper_figures(os.path.join(results, "paper_fig1_p1"), figures,
                  "paper_fig1_p1", ", P1 on triangles")
    slip_figures(os.path.join(results, "paper_fig1_slip"), figures)
    slip3d_figures(os.path.join(results, "paper_fig1_3d_slip"), figures)
    paper3d_figures(os.path.join(results, "paper_fig1_3d"), figures)
