"""The section of doc/performance.md on the automatic solver choice, from
doc/figures/bench_solvers.csv (scripts/bench_solvers), for
scripts/bench_report.py."""
from bench_report import sibling_rows

# The columns of the table: (solver, ranks).
RUNS = [("Cholesky", 1), ("MUMPS", 1), ("CG with AMG", 1), ("MUMPS", 2),
        ("CG with AMG", 2)]


def fmt(v):
    return f"{v:.3g}" if isinstance(v, (int, float)) else "–"


def solver_choice(csv_path):
    """The table of time per step of each solver on each scene and size,
    and the fastest on 1 and on 2 ranks, if bench_solvers.csv exists beside
    the CSV of the 2D runs."""
    rows = sibling_rows(csv_path, "bench_solvers.csv")
    if not rows:
        return []
    m = rows[0]
    cases = []
    for r in rows:
        if (r["scene"], r["size"]) not in cases:
            cases.append((r["scene"], r["size"]))
    lines = [
        "", "## Which solver the automatic choice takes", "",
        "Time per step in ms (ten steps of 0.01 s, the factorization or the "
        "AMG hierarchy included, no field output, no error estimate) of "
        "each displacement solver on 2D and 3D scenes of growing size; "
        "*unknowns* counts the displacement's (the damage's come on top in "
        "the paper scenes). `Solver/Linear solver = automatic` (the default) "
        "takes Cholesky on one process and MUMPS on several up to "
        "`LinearSolver::factorization_limit()` displacement unknowns "
        "(2,000,000 in 2D, 210,000 in 3D), and CG with AMG beyond; on several "
        "ranks in 2D it factorizes only from 100,000 unknowns on, since "
        "below that CG with AMG was the faster on 2 ranks. On one rank a "
        "factorization was the faster in every case measured; the 3D limit "
        "is the largest 3D size measured, the 2D limit is set by the "
        "factors' memory, which grows like n log n. Measured by `scripts/bench_solvers` at "
        f"commit {m['commit']} on {m['date']} ({m['cpu']}); "
        "`scripts/bench_solvers [--quick]` measures it again.", "",
        "| scene | size | unknowns | " +
        " | ".join(f"{s}, {n} rank{'s' if n > 1 else ''}" for s, n in RUNS) +
        " | fastest, 1 rank | fastest, 2 ranks |",
        "|---|---|---|" + "---|" * (len(RUNS) + 2)]
    for scene, size in cases:
        by = {(r["solver"], int(r["ranks"])): r for r in rows
              if (r["scene"], r["size"]) == (scene, size)}
        dim = int(next(iter(by.values()))["dim"])
        dofs = next((r["dofs"] for r in by.values()
                     if isinstance(r.get("dofs"), int)), "")
        damage = scene.startswith("paper_fig1")
        unknowns = (dofs * dim // (dim + 1) if damage and dofs != ""
                    else dofs)
        times = {k: r["per_step_ms"] for k, r in by.items()
                 if r["status"] == "ok"}

        def fastest(n):
            runs = {k: t for k, t in times.items() if k[1] == n}
            return min(runs, key=runs.get)[0] if runs else "–"
        lines.append(f"| {scene} | {size} | {unknowns} | " +
                     " | ".join(fmt(times.get(k)) for k in RUNS) +
                     f" | {fastest(1)} | {fastest(2)} |")
    return lines
