"""The section *Setup against the mesh size* of doc/performance.md, from
bench_setup.csv beside the CSV of the 2D runs (scripts/bench_setup writes
it)."""
from bench_report import fmt, sibling_rows


def setup_scaling(csv_path):
    """The section of setup time against the mesh size from bench_setup.csv
    beside the CSV of the 2D runs (scripts/bench_setup), if there is one."""
    rows = sibling_rows(csv_path, "bench_setup.csv")
    if not rows:
        return []
    m = rows[0]
    box = {r["cells"]: r for r in rows if r["mesh"] == "box"}
    lines = [
        "", "## Setup against the mesh size", "",
        "The setup of a run (the timer's *Setup*: the distributed mesh, "
        "degrees of freedom, constraints, sparsity patterns, matrices and "
        "the damage problem's numbering, mass and preconditioner) from a "
        "Gmsh file of triangles "
        "whose nodes and cells come in a random order (the L shape of "
        "`prm/meshes/make_l_shape.py N triangles shuffled`, 6N² triangles) "
        "and from a generated simplex box of as many triangles "
        "(`Subdivisions = 3N, N`), both with gradient damage, one step, on "
        f"{m['ranks']} rank(s); measured by `scripts/bench_setup` at commit "
        f"{m['commit']} on {m['date']} ({m['cpu']}). *before the timer*: "
        "the process's wall time outside the timer's total: loading the "
        "program's libraries and starting MPI (reading and checking the "
        "mesh file come after, in the total but not in *Setup*). *ratio*: "
        "the Gmsh file's setup over the box's. `scripts/bench_setup "
        "[--sizes N ...]` (default 50 100 200 310) measures it again.", "",
        "| mesh | cells | dofs | setup [s] | before the timer [s] | "
        "whole run [s] | memory rank 0 [MB] | ratio |",
        "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        other = box.get(r["cells"]) if r["mesh"] == "gmsh" else None
        ratio = (fmt(r["setup_s"] / other["setup_s"])
                 if other and other["setup_s"] else "–")
        lines.append(
            f"| {'Gmsh file, shuffled' if r['mesh'] == 'gmsh' else 'box'} | "
            f"{r['cells']} | {r['dofs']} | {fmt(r['setup_s'])} | "
            f"{fmt(r['before_timer_s'])} | {fmt(r['process_wall_s'])} | "
            f"{fmt(r['mem_rank0_mb'])} | {ratio} |")
    return lines
