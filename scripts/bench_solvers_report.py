"""The section of doc/performance.md on the automatic solver choice, from
doc/figures/bench_solvers.csv (scripts/bench_solvers), for
scripts/bench_report.py."""
import math

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
            "factorizes anew, while CG with AMG builds its hierarchy in a "
            "fraction of a factorization's time: `automatic` takes CG with "
            "AMG for the rest of a run once its factorizations anew come "
            "more often than one per S\\* steps (after a margin of two, "
            "`SolverChoice::refactorizations_outweigh()`), and for such a "
            "scene `CG with AMG` named in the parameter file saves the "
            "factorizations before the switch")
    if once:
        parts.append(
            " in " + ", ".join(once) + ", where one factorization serves "
            "the whole run and ten steps do not amortize it: over a longer "
            "run its share falls (the paper scene's 100 steps at the top of "
            "this page)")
    return text + ";".join(parts) + "."


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
        "takes Cholesky on one process and MUMPS on several where the run's "
        "steps repay the factorization's one-time cost, and CG with AMG "
        "elsewhere (`SolverChoice`; the second table below gives the number "
        "of steps from which a factorization is the faster). "
        + one_rank_sentence(rows, cases) +
        " A factorization is never taken beyond 2,000,000 displacement "
        "unknowns in 2D and 210,000 in 3D (`SolverChoice::"
        "factorization_limit()`): the 3D limit is the largest 3D size "
        "measured, the 2D limit is set by the "
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


# The factorization against CG with AMG on as many ranks.
PAIRS = [(("Cholesky", 1), ("CG with AMG", 1)),
         (("MUMPS", 2), ("CG with AMG", 2))]

# Cases where a factorization's step is less than this share of CG with
# AMG's enter the fit of the break-even counts: where the two steps cost
# about the same, the count is large and ill-determined, and the choice
# changes a run's time little either way.
FIT_STEP_RATIO = 1 / 1.2


def break_even(by, pair):
    """The number of steps from which the factorization of @p pair is the
    faster (0: from the first), None where it is the slower per step, or
    '' where a run is missing."""
    f, a = (by.get(k) for k in pair)
    if not f or not a or not all(isinstance(r.get(c), (int, float))
                                 for r in (f, a)
                                 for c in ("build_s", "rest_per_step_ms")):
        return ""
    gain = a["rest_per_step_ms"] - f["rest_per_step_ms"]
    if gain <= 0:
        return None
    return max(0.0, (f["build_s"] - a["build_s"]) * 1000 / gain)


def unknowns_of(row):
    """The displacement unknowns of a run (the damage's come on top in the
    paper scenes)."""
    dim, dofs = int(row["dim"]), row["dofs"]
    damage = row["scene"] in ("paper_fig1", "paper_fig1_3d")
    return dofs * dim // (dim + 1) if damage else dofs


def fit_break_even(rows, cases, dim, pair):
    """Least squares of log S* on log n over the cases of @p dim without
    slip where the factorization's step is clearly the cheaper: S*(10^5)
    and the power, or None."""
    points = []
    for scene, size in cases:
        by = {(r["solver"], int(r["ranks"])): r for r in rows
              if (r["scene"], r["size"]) == (scene, size)
              and r["status"] == "ok" and int(r["dim"]) == dim}
        f, a = (by.get(k) for k in pair)
        s = break_even(by, pair)
        if (not isinstance(s, float) or s <= 0
                or float(f.get("active_set_its") or 1) > 1.5
                or f["rest_per_step_ms"] > FIT_STEP_RATIO *
                a["rest_per_step_ms"]):
            continue
        points.append((math.log(unknowns_of(f) / 1e5), math.log(s)))
    if len(points) < 2:
        return None
    mx = sum(x for x, _ in points) / len(points)
    my = sum(y for _, y in points) / len(points)
    power = (sum((x - mx) * (y - my) for x, y in points)
             / sum((x - mx) ** 2 for x, _ in points))
    return math.exp(my - power * mx), power, len(points)


def fit_sentence(rows, cases):
    """The fitted break-even counts, which SolverChoice::break_even_steps()
    takes (rounded) from the run of this benchmark that it names."""
    parts = []
    for dim in (2, 3):
        for pair in PAIRS:
            fit = fit_break_even(rows, cases, dim, pair)
            if fit:
                n = pair[0][1]
                parts.append(
                    f"{dim}D on {n} rank{'s' if n > 1 else ''}: "
                    f"S\\*(10^5) = {fit[0]:.3g}, p = {fit[1]:.2f} "
                    f"({fit[2]} cases)")
    if not parts:
        return []
    return ["", "Fitted as S\\*(n) = S\\*(10^5) (n / 10^5)^p over the cases "
            "without slip in which the factorization's step costs less than "
            f"{FIT_STEP_RATIO:.2f} of CG with AMG's (where the two cost about "
            "the same, S\\* is large and ill-determined, and the choice changes "
            "a run's time little): " + "; ".join(parts) + ". "
            "`SolverChoice::break_even_steps()` takes these fits, rounded, "
            "from the run of commit fb85cda, and those of 2 ranks for any "
            "number of processes: on more, CG with AMG gains more from them "
            "than MUMPS does, so there the counts are lower bounds."]


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
        "times as much as a run of 100 steps does. *S\\**: the number of "
        "steps from which the factorization is the faster, (build − build "
        "of CG with AMG) / (step of CG with AMG − step), on 1 rank "
        "(Cholesky) and 2 ranks (MUMPS); *never* where its step costs "
        "more.", "",
        "| scene | size | " +
        " | ".join(f"{s}, {n} rank{'s' if n > 1 else ''}: build [s] / step "
                   "[ms]" for s, n in RUNS) + " | S\\*, 1 rank | S\\*, "
        "2 ranks |",
        "|---|---|" + "---|" * (len(RUNS) + 2)]
    for scene, size in cases:
        by = {(r["solver"], int(r["ranks"])): r for r in rows
              if (r["scene"], r["size"]) == (scene, size)
              and r["status"] == "ok"}
        cells = [f"{fmt(by[k].get('build_s'))} / "
                 f"{fmt(by[k].get('rest_per_step_ms'))}" if k in by else "–"
                 for k in RUNS]
        for pair in PAIRS:
            count = break_even(by, pair)
            cells.append("never" if count is None else
                         f"{count:.0f}" if isinstance(count, float) else "–")
        lines.append(f"| {scene} | {size} | " + " | ".join(cells) + " |")
    return lines + fit_sentence(rows, cases)
