#!/usr/bin/python3
"""Times the setup of a run against the number of cells, for a Gmsh file of
triangles whose nodes and cells come in a random order (the L shape of
prm/meshes/make_l_shape.py, 'shuffled') and for a generated simplex box of
the same number of triangles, both with gradient damage; writes
doc/figures/bench_setup.csv, and scripts/bench_report.py puts the table into
doc/performance.md.

Usage: bench_setup.py VPCONTACT [--sizes N ...]   (the L shape of size N has
6 N^2 triangles; the box has 3N x N squares cut in two)
A benchmark reports figures: nothing here passes or fails."""
import argparse
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import bench  # noqa: E402  (next to this file)

COLUMNS = ["mesh", "cells", "dofs", "setup_s", "before_timer_s", "total_s",
           "process_wall_s", "mem_rank0_mb", "ranks", "date", "cpu",
           "commit"]


def scene(mesh_lines, folder):
    """One step with damage and no output: the run is its setup."""
    return (mesh_lines +
            "subsection Damage\n  set Model = gradient\nend\n"
            "subsection Time\n  set Time step = 0.01\n  set End time = 0.01\n"
            "end\nsubsection Error estimate\n  set Estimate error = false\n"
            f"end\nsubsection Output\n  set Directory = {folder}\n"
            "  set Output every = 0\nend\n")


def gmsh_scene(a, n, folder):
    mesh = os.path.join(a.workdir, f"l_shape_{n}_shuffled.msh")
    if not os.path.exists(mesh):
        with open(mesh, "w") as f:
            subprocess.run([sys.executable, os.path.join(
                ROOT, "prm", "meshes", "make_l_shape.py"), str(n),
                "triangles", "shuffled"], stdout=f, check=True)
    # The boundary ids of make_l_shape.py: 1 bottom, 2 left, 3 right end,
    # 4 the rest (traction free; a mesh file's ids must all be named).
    return scene(f"subsection Geometry\n  set Mesh = file\n"
                 f"  set Mesh file = {mesh}\nend\n"
                 "subsection Boundary conditions\n"
                 "  set Clamped boundary ids  = 2\n"
                 "  set Traction boundary ids = 3\n"
                 "  set Contact boundary ids  = 1\n"
                 "  set Free boundary ids     = 4\n"
                 "  set Traction              = 20*t; -40*t\nend\n", folder)


def box_scene(n, folder):
    return scene(f"subsection Geometry\n  set Cell type = simplex\n"
                 f"  set Upper corner = 3, 1\n"
                 f"  set Subdivisions = {3 * n}, {n}\nend\n"
                 "subsection Boundary conditions\n"
                 "  set Contact boundary ids = 2\nend\n", folder)


def run(a, mesh, n):
    tag = f"setup_{mesh}_{n}"
    folder = os.path.join(a.workdir, "runs", tag)
    prm = os.path.join(a.workdir, tag + ".prm")
    with open(prm, "w") as f:
        f.write(gmsh_scene(a, n, folder) if mesh == "gmsh" else
                box_scene(n, folder))
    out, row = bench.launch(a, [a.executable, prm], a.ranks, tag,
                            lambda out: "Total wallclock" in out)
    row.update(mesh=mesh, ranks=a.ranks)
    if row["status"] != "ok":
        return row
    total, phases = bench.timer_table(out)
    cells = re.search(r"mesh: (\d+) cells.*?, (\d+) dofs", out)
    memory = re.search(r"Peak memory \(rank 0\):\s+(\d+) kB", out)
    # The timer starts with the simulator: loading the libraries and
    # starting MPI come before it, in the process's wall time only.
    row.update(cells=int(cells.group(1)), dofs=int(cells.group(2)),
               setup_s=phases["Setup"][1], total_s=total,
               before_timer_s=row["process_wall_s"] - total,
               mem_rank0_mb=int(memory.group(1)) / 1024 if memory else "")
    return row


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("executable")
    p.add_argument("--sizes", type=int, nargs="+",
                   default=[50, 100, 200, 310])
    p.add_argument("--ranks", type=int, default=1)
    p.add_argument("--workdir", default="/tmp/vpcontact_bench_setup")
    p.add_argument("--csv", default=os.path.join(ROOT, "doc", "figures",
                                                 "bench_setup.csv"))
    a = p.parse_args()
    os.makedirs(os.path.join(a.workdir, "logs"), exist_ok=True)
    machine = bench.machine()
    rows = []
    for n in a.sizes:
        for mesh in ("gmsh", "box"):
            row = run(a, mesh, n)
            row.update({k: machine.get(k, "") for k in ("date", "cpu",
                                                        "commit")})
            print({k: row.get(k) for k in ("mesh", "status", "cells",
                                           "setup_s", "before_timer_s")},
                  flush=True)
            rows.append(row)
    import csv
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            if r["status"] == "ok":
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v)
                            for k, v in r.items()})
    subprocess.run([sys.executable, os.path.join(ROOT, "scripts",
                                                 "bench_report.py")],
                   check=True)


if __name__ == "__main__":
    main()
