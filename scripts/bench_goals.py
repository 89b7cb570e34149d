"""The performance goals of the project (issue 47) on the largest mesh of a
benchmark, the figures reached and what stands in the way where a goal is
missed: the table of doc/performance.md that bench_report.py writes."""
import math

from bench_report import (ONE_THREAD, PHASE_TITLES, config, damage, fmt,
                          head_setting, percent, ratio, short)
from bench_tables import memory_ratio


def slower_reasons(slower, beside=()):
    """What the benchmark knows about the phases of HEAD that are slower
    than an earlier commit's: one sentence per kind of phase that is.
    @p beside: for each Cholesky run whose displacement solve is slower,
    (HEAD's row, the earlier commit's row)."""
    named = " ".join(t for _, t in slower)
    text = ("Each figure compares HEAD's run with the earlier commit's, "
            "which ran right after it in the same round (with `--rounds N`, "
            "each configuration's run of median total time).")
    for now, then in beside:
        def pair(r):
            return sum(r.get(p + "_ms") or 0 for p in
                       ("solve", "damage_assembly", "damage_solve"))
        text += (f" With Cholesky on one process the *displacement solve* "
                 "is only the wait for the substitutions that the damage "
                 "step beside them (damage assembly and damage solves) does "
                 "not hide: the shorter the damage step, the more of the "
                 "substitutions show. The three phases together take "
                 f"{fmt(pair(now))} ms per step at {now['commit']} against "
                 f"{fmt(pair(then))} ms at {then['commit']}. Substitutions "
                 "of the program's own shorten the wait but save less than "
                 "the rule of [design.md](design.md) asks (10 % of the run), "
                 "so the library's stay.")
    if "stress update" in named:
        text += (" The stress update also sums the step's stored energy and "
                 "largest von Mises stress while the new stress is in the "
                 "cache, which the output phase did in a pass of its own "
                 "before 4b13578 (at 211b1ab too): read the two phases "
                 "together.")
    if "CG + AMG AMG setup" in named:
        text += (" The AMG path builds ML once per run with the rigid "
                 "motions as its near-null space, where 211b1ab gave it "
                 "the constant mode of each component: the setup costs "
                 "more and the displacement solve, the step's largest "
                 "phase, much less.")
    if "output" in named:
        text += (" The output: HEAD reads the nodal values at the "
                 "vertices into a piece of its own (each vertex once) "
                 "and compresses and writes it in a thread beside the "
                 "steps where the rank has several threads; on 2 ranks, "
                 "one core each, it writes at once, so that the *output* "
                 "phase holds the compression and the write, which "
                 "211b1ab's writer thread took from the other phases of "
                 "the rank's only core.")
    if " other " in named:
        text += (" *Other* is the step's work outside the named phases, "
                 "which the program's timer does not split: the damage "
                 "step's right-hand side of the change, its first set "
                 "decision, the nodes it frees ahead of the front and the "
                 "start of its work set, each a pass over all damage nodes "
                 "(on several ranks with ghost exchanges and a product "
                 "with the matrix), the displacement's start vector and "
                 "update, the friction sets, storing the new damage, and "
                 "the initial state at t = 0 (the run's time after its "
                 "set-up is divided among its steps). The passes between "
                 "the damage solves run on the work set inside *damage "
                 "solve*; the wait for the last field output is in "
                 "*output*.")
    return text + " Every phase and its decision is in [design.md](design.md)."


def start_memory(best, mine, peer, size):
    """What a run holds whatever its mesh, from the tiny runs of
    scripts/bench (the CSV's start_mem_* columns), and the rest of the
    peak of @p mine and @p peer; '' where a figure is missing."""
    any_row = next(iter(best.values()))
    try:
        v = float(any_row.get("start_mem_vpcontact_mb", ""))
        p = float(any_row.get("start_mem_peer_mb", ""))
    except ValueError:
        return ""
    if not mine or not peer:
        return ""
    text = (f"A run on 4 x 4 cells (2 steps) already holds {fmt(v)} MB in "
            f"vpcontact and {fmt(p)} MB in the peer, mostly the libraries "
            "each loads (vpcontact: deal.II's library and the libraries it "
            "links, among them Trilinos, PETSc, p4est, OpenCASCADE and Gmsh; "
            "the peer: Python, DOLFINx and PETSc); above that the run on "
            f"{size}² cells needs {fmt(mine['mem_all_mb'] - v)} MB against "
            f"the peer's {fmt(peer['mem_all_mb'] - p)} MB. ")
    try:
        vp = float(any_row.get("start_private_vpcontact_mb", ""))
        pp = float(any_row.get("start_private_peer_mb", ""))
        mp, gp = float(mine["mem_private_mb"]), float(peer["mem_private_mb"])
    except (ValueError, KeyError):
        return text
    return text + (
        f"Of the 4 x 4 run's resident set only {fmt(vp)} MB are private "
        f"in vpcontact and {fmt(pp)} MB in the peer; the rest are pages "
        "mapped from the libraries' files (their code, and the dynamic "
        "symbol tables the loader reads when it resolves a library's "
        "symbols, of which deal.II's are the largest: [memory.md](memory.md) "
        "lists them), which the page cache holds once for all processes "
        "that map them. The private "
        f"memory at the peak, {fmt(mp)} MB against the peer's {fmt(gp)} "
        f"MB ({fmt(mp / gp)} times), is what the run holds of its own. ")


def work_shares(algebras, get):
    """The busiest rank's share of the damage solves' work (free nodes
    times CG iterations) in the 2-rank AMG runs, what that leaves of the
    ranks' gain, and the work on 2 ranks against 1, from the runs' own
    summary lines (DamageProblem::work_summary()), where they printed
    them."""
    found = {}
    for a in algebras:
        r1 = get("vpcontact", a, "CG with AMG", 1)
        r2 = get("vpcontact", a, "CG with AMG", 2)
        balance = r2 and r2.get("damage_work_balance")
        if not balance:
            continue
        text = (f"{100 * float(balance) / 2:.0f} % of the work "
                f"lies on one rank, which leaves at most "
                f"{2 / float(balance):.3g} times one rank's speed")
        if r1 and r1.get("damage_work") and r2.get("damage_work"):
            # The busiest rank's work against all of 1 rank's.
            more = float(r2["damage_work"]) / float(r1["damage_work"])
            text += (f", and the 2 ranks together do {more:.3g} times the "
                     "work of 1, the iterations that block Jacobi between "
                     "them adds, which leaves at most "
                     f"{2 / (more * float(balance)):.3g} times")
        found.setdefault(text, []).append(a)
    # Both packages run the program's own region solver for the damage, so
    # their figures are often the same: said once for both.
    return (". Measured by the runs themselves (free nodes times CG "
            "iterations): " + "; ".join(
                f"with {' and '.join(packages)}"
                + (" alike" if len(packages) > 1 else "") + f", {text}"
                for text, packages in found.items())) if found else ""


def goals(best, sizes, algebras, every=None):
    """The performance goals of the project on the largest mesh against the
    figures reached, and what stands in the way where a goal is missed.
    @p every: the runs of every commit (HEAD's and --against's), keyed by
    size and (code, algebra, solver, ranks, commit)."""
    size = max(sizes)

    def get(code, algebra, solver, ranks, s=size):
        return best.get((s, (code, algebra, solver, ranks)))

    peer = "DOLFINx/PETSc"
    serial = [r for (s, k), r in best.items() if s == size and k[3] == 1]
    mine = [r for r in serial if r["code"] == "vpcontact"]
    theirs = [r for r in serial if r["code"] == "peer"]
    if not mine or not theirs:
        return ["The goals need vpcontact and the peer on the same sizes."]
    fastest = min(mine, key=lambda r: r["total_s"])
    peer_fastest = min(theirs, key=lambda r: r["total_s"])
    g1, g2 = get("peer", peer, "gamg", 1), get("peer", peer, "gamg", 2)

    def figure(algebra, f):
        a1 = get("vpcontact", algebra, "CG with AMG", 1)
        a2 = get("vpcontact", algebra, "CG with AMG", 2)
        return f(a1, a2) if a1 and a2 and g1 and g2 else "–"

    def each(f):
        return "; ".join(f"{a} {figure(a, f)}" for a in algebras)

    def by_ranks(f):
        """f(1 rank, 2 ranks) with HEAD's run of one thread on 1 rank
        (bench.py --one-thread), where the benchmark has it: what the
        ranks alone gain, without deal.II's threads on the 1-rank side."""
        found = []
        for a in algebras:
            alone = (every or {}).get((size, ("vpcontact", a, "CG with AMG",
                                              1, fastest["commit"]
                                              + ONE_THREAD)))
            a2 = get("vpcontact", a, "CG with AMG", 2)
            if alone and a2:
                found.append(f"{a} {fmt(f(alone, a2))}")
        return ("; from 1 rank of one thread: " + "; ".join(found)
                if found else "")

    def growth(r_a, r_b):
        return (r_b["per_step_ms"] / r_a["per_step_ms"]) ** (
            math.log(4) / math.log(r_b["dofs"] / r_a["dofs"]))

    def largest_growth(algebra):
        # One size alone (scripts/bench 512) has no growth to show.
        worst = 0
        for (s, k), r in best.items():
            if (s != min(sizes) or s == size or k[0] != "vpcontact"
                    or k[1] != algebra):
                continue
            big = best.get((size, k))
            if big:
                worst = max(worst, growth(r, big))
        return fmt(worst) if worst else "–"

    share = {p: ratio(fastest.get(p + "_ms"), fastest["per_step_ms"])
             for p in ("damage_solve", "solve", "assembly", "other")}
    # With Cholesky on one process the substitutions run beside the damage
    # step (LinearSolver::solve_in_background()), and the timer of the
    # solve holds only the wait for them.
    beside = fastest["solver"] == "Cholesky"
    substitutions = (
        "waiting for the triangular substitutions" if beside else
        "triangular substitutions")
    overlap = (
        "The substitutions run beside the damage step in a second thread "
        "(the damage of step n needs only step n−1's data), as at 211b1ab; "
        "the wait is what the damage step does not hide." if beside else
        "The substitutions run after the damage step; with Cholesky they "
        "run beside it in a second thread (the damage of step n needs only "
        "step n−1's data), as at 211b1ab.")
    # The fastest serial run of an earlier commit (--against), against the
    # same peer run: how far the earlier kernels alone go.
    earlier = [r for (s, k), r in (every or {}).items()
               if s == size and k[0] == "vpcontact" and k[3] == 1
               and r["commit"] != fastest["commit"]
               and not head_setting(r)]
    then = ""
    if earlier:
        e = min(earlier, key=lambda r: r["total_s"])
        then = (f" In the same run the program at {e['commit']} ({config(e)}"
                ", its own kernels, no error estimate) took "
                f"{fmt(ratio(e['total_s'], peer_fastest['total_s']))} of the "
                "peer's time, so 0.2 needs about half of what those kernels "
                "reach, not only their return.")
    # Every phase of every HEAD run against the same run of each earlier
    # commit; a phase the earlier commit did not have (0 ms) is left out.
    slower, beside_pairs = [], []
    for (s, k), r in (every or {}).items():
        if s != size or k[0] != "vpcontact" or r["commit"] != fastest["commit"]:
            continue
        for (s2, k2), e in every.items():
            if (s2 != size or k2[:4] != k[:4] or e["commit"] == r["commit"]
                    or head_setting(e)):
                continue
            for phase, title in PHASE_TITLES:
                now, then_ms = r.get(phase + "_ms"), e.get(phase + "_ms")
                if now and then_ms and now > then_ms:
                    slower.append((then_ms / now, f"{config(r)} {title} "
                                   f"{fmt(then_ms / now)} against "
                                   f"{e['commit']}"))
                    if phase == "solve" and r["solver"] == "Cholesky":
                        beside_pairs.append((r, e))
    slower.sort()
    rows = [
        ("best serial run at most 0.2 of the peer's best serial run",
         f"{fmt(ratio(fastest['total_s'], peer_fastest['total_s']))} "
         f"({config(fastest)} / {short(peer_fastest)})",
         f"The step of {config(fastest)} is "
         f"{100 * share['damage_solve']:.0f} % damage solves, "
         f"{100 * share['solve']:.0f} % {substitutions}, "
         f"{100 * share['assembly']:.0f} % right-hand side assembly and "
         f"{100 * (share.get('other') or 0):.0f} % work outside the named "
         "phases (*other*: the damage step's passes over all nodes "
         "before its first solve, the displacement's start vector and "
         "update, the friction sets), the rest the error estimate, the stress update, the damage "
         "assembly and the output: no one phase holds the gap, and 0.2 "
         "would need every phase at about half its time. The damage "
         "solves run the program's region solver (CG over the free "
         "nodes, the preconditioner of a region kept for the step), "
         "and the passes between them visit the nodes the solves can "
         "change (`DamageWorkSet`). "
         + overlap + then),
        ("no phase of HEAD slower than the same phase of an earlier commit "
         "(speed of HEAD relative to it)",
         (f"{len(slower)} phase(s) slower, the slowest: "
          + "; ".join(t for _, t in slower[:6]) if slower else
          "every phase no slower" if every else "–"),
         slower_reasons(slower, beside_pairs)),
        ("CG + AMG at most 0.5 of the peer's CG + GAMG, 1 rank",
         each(lambda a1, a2: fmt(ratio(a1["total_s"], g1["total_s"]))),
         "The AMG cycles on the displacement block (ML or GAMG) are the "
         "step. With either package, the products with the matrix on the "
         "finest level and in CG are the program's (RowPatternMatrix, "
         "[design.md](design.md)); the coarser levels, the transfers "
         "between them and the number of cycles per solve are the "
         "library's."),
        ("the same on 2 ranks",
         each(lambda a1, a2: fmt(ratio(a2["total_s"], g2["total_s"]))),
         "As on 1 rank."),
        ("peak memory of CG + AMG at most the peer's, 1 rank",
         each(lambda a1, a2: memory_ratio(a1, g1)),
         start_memory(best, get("vpcontact", algebras[0], "CG with AMG", 1),
                      g1, size)
         + "With ML the peak comes in the run's set-up, while ML forms the "
         "Galerkin product R A P of its finest level: A P, ML's own copy "
         "of A P and the storage of R A P, allocated at an estimate of its "
         "size, are held at once, on top of the matrix, the mesh and the "
         "prolongator P and its transpose R, which ML stores; later in the "
         "run, the steps that write the fields included, the heap stays "
         "below that peak ([memory.md](memory.md) splits the peak by "
         "function, measured by `scripts/memory_profile`). The size of "
         "that product is ML's; the program calls it on the matrix it "
         "assembled, without a copy. For the whole run the program holds "
         "the mesh "
         "(deal.II's cells of every level, p4est's forest of one tree, the "
         "DoFHandler's indices), the matrix and its sparsity graph, the "
         "fields at the quadrature points, the points and entry positions "
         "kept per cell, and the damage matrix once (the rows that its "
         "solver and its products read); with PETSc on one rank, PETSc "
         "reads that matrix where it is, without a copy (on several ranks "
         "a copy in PETSc's layout comes on top, see the row below). The peer holds one PETSc "
         "matrix and GAMG's hierarchy."),
        ("the same per rank on 2 ranks",
         each(lambda a1, a2: memory_ratio(a2, g2)),
         "Peak memory summed over the ranks on both sides (the peer "
         "reports the sum); in brackets the private memory, which leaves "
         "out the pages mapped from the libraries' files that every "
         "rank's resident set counts again. Each rank holds its own cells with a layer of "
         "ghost cells, its rows of the matrices and its part of ML's "
         "or GAMG's hierarchy; with PETSc also a copy of its rows of the "
         "matrix, since PETSc splits a rank's rows into the columns it "
         "owns and the others where Epetra keeps each row in one piece "
         "([design.md](design.md)); the coarse mesh, which every rank holds whole, is one "
         "p4est tree for the box of the paper scene."),
        ("CG + AMG speed-up from 1 to 2 ranks at least 1.7",
         each(lambda a1, a2: fmt(ratio(a1["total_s"], a2["total_s"])))
         + by_ranks(lambda a1, a2: ratio(a1["total_s"], a2["total_s"])),
         "A run on 1 rank already uses both cores in its threaded parts "
         "(assembly, stress update) and writes its fields in a thread "
         "beside the steps, so 2 ranks gain only in the "
         "solves: the displacement solve's AMG cycles gain (the column "
         "*displacement solve* of the table above), the damage solves "
         "gain less (the next row). The figures from 1 rank of one thread "
         "(`scripts/bench --one-thread`, `DEAL_II_NUM_THREADS=1`) take "
         "the threads out of the comparison: what the ranks alone gain, "
         "as with one rank per core on a node of many cores."),
        ("damage solves speed-up from 1 to 2 ranks at least 1.6",
         each(lambda a1, a2: fmt(ratio(damage(a1), damage(a2))))
         + by_ranks(lambda a1, a2: ratio(damage(a1), damage(a2))),
         "The damage solves work on the free nodes only, which lie around "
         "the loaded corner, mostly on one rank, while the other waits in "
         "the reductions" + work_shares(algebras, get) + ". The "
         "preconditioner is block Jacobi between the ranks, and the first "
         "solve of each step, whose change is smooth over the whole free "
         "region, needs more than twice the iterations of one rank's; the "
         "later solves of a step cost the same (the message of the commit "
         "that wrote this sentence counts both at 512² cells, and the "
         "attempts that did not help: a start vector corrected on "
         "subdomain constants, the region moved to equal shares of the "
         "ranks, which took more iterations than it saved). The "
         "preconditioner's diagonal takes in half of the cut rows' entries "
         "in other ranks' columns ([damage.md](damage.md)): that takes CG "
         "iterations off the 2-rank solves, and leaves the imbalance."),
        ("error estimate at most 5 % of the run, best serial run",
         percent(ratio(fastest.get("estimate_ms"), fastest["per_step_ms"]))
         + f" ({config(fastest)})",
         "The scene estimates every 10th step and the last "
         "(`Error estimate/Every steps = 10` in prm/paper_fig1.prm; its "
         "estimate grows with time, so the largest is the last step's). "
         "An estimate recovers the stress, the strain and the damage "
         "gradient at the nodes: two passes over the quadrature points, "
         "like the stress update's one ([convergence.md](convergence.md)); "
         "at every step (`Every steps = 1`, the default for other scenes) "
         "it costs about ten times the figure here."),
        ("error estimate speed-up from 1 to 2 ranks at least 1.6",
         each(lambda a1, a2: fmt(ratio(a1.get("estimate_ms"),
                                       a2.get("estimate_ms"))))
         + by_ranks(lambda a1, a2: ratio(a1.get("estimate_ms"),
                                         a2.get("estimate_ms"))),
         "On 1 rank the estimate already runs in deal.II's threads on "
         "both cores; 2 ranks split the cells but not the cores. From 1 "
         "rank of one thread, the ranks split both."),
        ("time per step grows at most 4.4 times per 4 times the unknowns, "
         + (f"{min(sizes)}² to {size}²" if len(sizes) > 1
            else "from the smallest mesh to the largest"),
         "largest over the runs: " + "; ".join(
             f"{a} {largest_growth(a)}" for a in algebras),
         "The factors' fill and the damage solves' iterations grow faster "
         "than the unknowns; on 2 cores the larger meshes leave the "
         "caches."),
    ]
    # A run of part of the configurations (--configs) or of one size shows
    # only the goals its runs measure: the best serial run needs the direct
    # paths of both programs, the phases an earlier commit, the growth two
    # sizes.
    direct = ({r["code"] for r in serial
               if r["solver"] in ("Cholesky", "MUMPS", "lu")}
              == {"vpcontact", "peer"})
    against = any(r["commit"] != fastest["commit"] and not head_setting(r)
                  for (s, k), r in (every or {}).items())
    measured = [direct, against] + [True] * 8 + [len(sizes) > 1]
    assert len(measured) == len(rows)
    left_out = [title for (title, _, _), shown in zip(rows, measured)
                if not shown]
    lines = ["| goal | reached | what stands in the way where it is missed |",
             "|---|---|---|"]
    lines += [f"| {g} | {r} | {w} |"
              for (g, r, w), shown in zip(rows, measured) if shown]
    if left_out:
        lines += ["", "Not measured by this run: " + "; ".join(left_out)
                  + "."]
    return lines
