"""The section of doc/performance.md on the automatic solver choice, from
doc/figures/bench_solvers.csv (scripts/bench_solvers), for
scripts/bench_report.py."""
from bench_report import sibling_rows

# The columns of the table: (solver, ranks).
RUNS = [("Cholesky", 1), ("MUMPS", 1), ("CG with AMG", 1), ("MUMPS", 2),
        ("CG with AMG", 2)]


def fmt(v):
    return f"{v:.3g}" if isinstance(v, (int, float)) else "–"


def fastest(rows, scene, size, ranks):
    """The solver of the least time per step on @p ranks ranks, or None."""
    times = {r["solver"]: r["per_step_ms"] for r in rows
             if (r["scene"], r["size"]) == (scene, size)
             and int(r["ranks"]) == ranks and r["status"] == "ok"}
    return min(times, key=times.get) if times else None


def one_rank_sentence(rows, cases):
    """Where a factorization was the faster on 1 rank, and where CG with
    AMG was: with the stick set changing in most steps (a factorization
    anew at each change) or with one factorization that ten steps do not
    amortize."""
    lost = [(scene, size) for scene, size in cases
            if fastest(rows, scene, size, 1) == "CG with AMG"]
    if not lost:
        return ("On one rank a factorization was the faster in every case "
                "measured.")

    def changes(scene, size):
        its = [r.get("active_set_its") for r in rows
               if (r["scene"], r["size"], r["solver"]) ==
               (scene, size, "Cholesky")]
        return bool(its) and isinstance(its[0], (int, float)) and its[0] > 1.5
    slip = [f"{a} {b}" for a, b in lost if changes(a, b)]
    once = [f"{a} {b}" for a, b in lost if not changes(a, b)]
    text = "On one rank CG with AMG was the faster"
    parts = []
    if slip:
        parts.append(
            " in " + ", ".join(slip) + ", where the stick set changes in "
            "most steps (column *AS its per step*) and each change "
            "factorizes anew: for such a scene name `CG with AMG`, which "
            "builds its hierarchy in a fraction of a factorization's time")
    if once:
        parts.append(
            " in " + ", ".join(once) + ", where one factorization serves "
            "the whole run and ten steps do not amortize it: over a longer "
            "run its share falls (the paper scene's 100 steps at the top of "
            "this page)")
    return (text + ";".join(parts) + ". The limits above are those of an "
            "earlier measurement (commit 13ac5d8, Intel Xeon), which "
            "counted the time of the steps only; `automatic` does not yet "
            "weigh the steps of the run against a factorization's one-time "
            "cost.")


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
        "Time per step in ms (ten steps of 0.01 s, no field output, no "
        "error estimate; the run's time after its set-up over the steps, so "
        "that the factorization or the AMG hierarchy counts wherever the run "
        "builds it) of "
        "each displacement solver on 2D and 3D scenes of growing size; "
        "*unknowns* counts the displacement's (the damage's come on top in "
        "the paper scenes). `Solver/Linear solver = automatic` (the default) "
        "takes Cholesky on one process and MUMPS on several up to "
        "`LinearSolver::factorization_limit()` displacement unknowns "
        "(2,000,000 in 2D, 210,000 in 3D), and CG with AMG beyond; on several "
        "ranks in 2D it factorizes only from 100,000 unknowns on, since "
        "below that CG with AMG was the faster on 2 ranks. "
        + one_rank_sentence(rows, cases) +
        " The 3D limit "
        "is the largest 3D size measured, the 2D limit is set by the "
        "factors' memory, which grows like n log n. *AS its per step*: the "
        "friction active-set iterations per step (of the run with Cholesky); "
        "each one after the first whose stick set changed builds the "
        "factorization or the AMG hierarchy anew, unless the change is "
        "small enough to keep it (a few nodes). Measured by "
        "`scripts/bench_solvers` at "
        f"commit {m['commit']} on {m['date']} ({m['cpu']}); "
        "`scripts/bench_solvers [--quick]` measures it again.", "",
        "| scene | size | unknowns | AS its per step | " +
        " | ".join(f"{s}, {n} rank{'s' if n > 1 else ''}" for s, n in RUNS) +
        " | fastest, 1 rank | fastest, 2 ranks |",
        "|---|---|---|---|" + "---|" * (len(RUNS) + 2)]
    for scene, size in cases:
        by = {(r["solver"], int(r["ranks"])): r for r in rows
              if (r["scene"], r["size"]) == (scene, size)}
        dim = int(next(iter(by.values()))["dim"])
        dofs = next((r["dofs"] for r in by.values()
                     if isinstance(r.get("dofs"), int)), "")
        damage = scene in ("paper_fig1", "paper_fig1_3d")
        unknowns = (dofs * dim // (dim + 1) if damage and dofs != ""
                    else dofs)
        times = {k: r["per_step_ms"] for k, r in by.items()
                 if r["status"] == "ok"}
        best = [fastest(rows, scene, size, n) or "–" for n in (1, 2)]
        its = by.get(("Cholesky", 1), {}).get("active_set_its", "")
        lines.append(f"| {scene} | {size} | {unknowns} | {fmt(its)} | " +
                     " | ".join(fmt(times.get(k)) for k in RUNS) +
                     f" | {best[0]} | {best[1]} |")
    return lines + build_table(rows, cases)


def build_table(rows, cases):
    """The same runs split into what the builds cost and what a step costs
    besides, for a run of another length: a run of S steps takes about
    build + S x step (a scene whose stick set changes builds again at each
    change, so its build grows with the steps too)."""
    if not any(isinstance(r.get("build_s"), (int, float)) for r in rows):
        return []
    lines = [
        "", "The same runs split in two: *build* is the time the run spent "
        "building the factorizations or AMG hierarchies, or waiting for a "
        "factorization begun in the background (Cholesky's runs beside the "
        "damage step), in s over the ten steps; *step* the rest of a step "
        "in ms. A run of S steps without stick changes takes about "
        "build + S x step: the ten-step figures above weigh the build ten "
        "times as much as a run of 100 steps does.", "",
        "| scene | size | " +
        " | ".join(f"{s}, {n} rank{'s' if n > 1 else ''}: build [s] / step "
                   "[ms]" for s, n in RUNS) + " |",
        "|---|---|" + "---|" * len(RUNS)]
    for scene, size in cases:
        by = {(r["solver"], int(r["ranks"])): r for r in rows
              if (r["scene"], r["size"]) == (scene, size)
              and r["status"] == "ok"}
        cells = [f"{fmt(by[k].get('build_s'))} / "
                 f"{fmt(by[k].get('rest_per_step_ms'))}" if k in by else "–"
                 for k in RUNS]
        lines.append(f"| {scene} | {size} | " + " | ".join(cells) + " |")
    return lines
