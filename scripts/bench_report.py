#!/usr/bin/python3
"""Writes doc/performance.md from the raw results of scripts/bench.py (one
CSV row per run), so that the page can be regenerated from the data alone.

Usage: bench_report.py [CSV [REPORT]]  (defaults doc/figures/bench.csv and
doc/performance.md). The page reports figures without judging them."""
import csv
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# The groups of phases of a step (ms per step), as bench.py forms them from
# the program's timer table and the peer's totals, and their titles.
PHASES = ["damage_solve", "damage_assembly", "preconditioner", "assembly",
          "solve", "stress", "estimate", "output", "other"]
PHASE_TITLES = [("assembly", "assembly"),
                ("preconditioner", "AMG setup or factorization"),
                ("solve", "displacement solve"), ("stress", "stress update"),
                ("damage_assembly", "damage assembly"),
                ("damage_solve", "damage solve"),
                ("estimate", "error estimate"), ("output", "output"),
                ("other", "other")]
# commit: the commit whose vpcontact made the row (the peer's rows: HEAD's);
# head: the tree the benchmark ran from, the same in every row; scene: a
# hash of the scene file that commit's binary read.
MACHINE = ["date", "cpu", "cores", "memory_gb", "os", "dealii", "petsc",
           "dolfinx", "commit", "head", "scene", "thp", "blas",
           "start_mem_vpcontact_mb", "start_mem_peer_mb",
           "start_private_vpcontact_mb", "start_private_peer_mb"]
COLUMNS = (["round", "size", "steps", "code", "algebra", "solver", "path",
            "ranks", "status", "dofs", "total_s", "setup_s", "per_step_ms"]
           + [p + "_ms" for p in PHASES]
           + ["damage_solve_min_ms", "damage_solve_max_ms",
              "damage_work", "damage_work_balance", "mem_rank0_mb",
              "mem_all_mb", "mem_private_mb", "process_wall_s", "linear_its", "active_set_its",
              "floor_ms", "phases", "log"] + MACHINE)


def blas_line(m):
    """Where the runs had OpenBLAS's generic kernels: what that costs and
    how to choose others (openblas_core.py)."""
    if (m.get("blas") or "").lower() != "prescott":
        return []
    return ["* OpenBLAS did not know this CPU and ran its generic Prescott "
            "(SSE3) kernels, in vpcontact and in the peer alike: their dense "
            "products are several times slower than those of the kernels for "
            "the CPU's vector instructions, and the factorizations and "
            "substitutions of Cholesky and MUMPS take longer with them. "
            "`OPENBLAS_CORETYPE` chooses the kernels (README, "
            "*Running a scene*; `scripts/openblas_core.py` tells)."]


def huge_page_line(m):
    """What the kernel's transparent huge page mode means for the runs."""
    thp = m.get("thp", "")
    if not thp:
        return []
    if thp != "madvise":
        return [f"* Transparent huge pages: `{thp}` (vpcontact asks for none "
                "in this mode)."]
    return ["* Transparent huge pages: `madvise` (only memory that asks gets "
            "them). vpcontact asks for them for its heap only with "
            "`VPCONTACT_HUGE_PAGES=1` (it then restarts itself with "
            "`GLIBC_TUNABLES=glibc.malloc.hugetlb=1`, "
            "`include/vpcontact/app/huge_pages.h`): the rows named *huge "
            "pages* (`--huge-pages`). Commits from ef9ea16 to 426233a asked "
            "by default; the other runs and the peer have 4 KiB pages, as "
            "the system gives them."]


def settings_of_head(rows):
    """The words of the machine section for HEAD's other settings."""
    words = [text for label, text in (
        (HUGE_PAGES, "with its heap in huge pages"),
        (ONE_THREAD, "with one thread on 1 rank")) if any(
            r["commit"].endswith(label) for r in rows)]
    return f" (also {' and '.join(words)})" if words else ""


def untimed_in_other(r):
    """A row of vpcontact with *other* = the part of its time per step that
    no other column holds: timer names the grouping does not know and the
    work between the timer's sections (the program times its phases, not
    every pass of a step). The phases then add up to the time per step, as
    the peer's do."""
    if r.get("code") != "vpcontact" or not isinstance(
            r.get("per_step_ms"), (int, float)):
        return r
    named = sum(r[p + "_ms"] for p in PHASES if p != "other"
                and isinstance(r.get(p + "_ms"), (int, float)))
    return dict(r, other_ms=max(0., r["per_step_ms"] - named))


def write_csv(path, rows):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v)
                        for k, v in r.items()})


def read_csv(path):
    """The rows with numbers as numbers (an empty cell stays '')."""
    rows = []
    for r in csv.DictReader(open(path)):
        for k, v in r.items():
            if k in MACHINE or k in ("phases", "log", "status", "code",
                                     "algebra", "solver", "path"):
                continue
            try:
                r[k] = float(v) if "." in v or "e" in v else int(v)
            except ValueError:
                pass
        rows.append(r)
    return rows


def sibling_rows(csv_path, name):
    """The rows of the CSV @p name beside @p csv_path (another benchmark's
    figures for a section of the page), [] where there is none."""
    path = os.path.join(os.path.dirname(os.path.abspath(csv_path)), name)
    return read_csv(path) if os.path.exists(path) else []


def fmt(x):
    """A figure to three significant digits (all of its whole part); '–'
    where there is none."""
    if x in ("", None) or (isinstance(x, float) and math.isnan(x)):
        return "–"
    return f"{x:.0f}" if abs(x) >= 100 else f"{x:.3g}"


def head(r):
    """The commit the benchmark ran from (a CSV of before --against has
    only the one commit column)."""
    return r.get("head") or r["commit"]


def is_head(r):
    return r["commit"] == head(r)


# The labels bench.py gives HEAD's build run in another setting: its heap
# in huge pages (--huge-pages), one thread per rank (--one-thread).
HUGE_PAGES = " huge pages"
ONE_THREAD = " one thread"


def head_setting(r):
    """Whether the row is HEAD's build run in another setting (bench.py
    --huge-pages or --one-thread), not an earlier commit."""
    return r["commit"].endswith((HUGE_PAGES, ONE_THREAD))


def short(r):
    """The solver part of the run's name."""
    return {"CG with AMG": "CG + AMG", "lu": "MUMPS LU",
            "gamg": "CG + GAMG"}.get(r["solver"], r["solver"])


def config(r):
    """The run's back-end and solver, as in 'Trilinos, Cholesky'."""
    return f"{r['algebra']}, {short(r)}"


def name(r):
    """The run's name with the commit of its binary, as in 'vpcontact
    211b1ab, Trilinos, Cholesky'."""
    return (f"vpcontact {r['commit']}, {config(r)}" if r["code"] ==
            "vpcontact" else f"DOLFINx peer, {short(r)}")


def order(r):
    """vpcontact before the peer, Trilinos before PETSc, direct before AMG,
    HEAD before earlier commits."""
    return (r["code"] != "vpcontact", r["algebra"] != "Trilinos",
            r["path"] != "direct", not is_head(r), r["commit"])


def key(r):
    return (r["code"], r["algebra"], r["solver"], int(r["ranks"]))


def medians(rows, key=key):
    """{(size, key): the run with the median total time over the rounds}."""
    runs = {}
    for r in rows:
        if r["status"] == "ok":
            runs.setdefault((int(r["size"]), key(r)), []).append(r)
    return {k: sorted(v, key=lambda r: r["total_s"])[len(v) // 2]
            for k, v in runs.items()}


def ratio(a, b):
    return a / b if a not in ("", None) and b not in ("", None, 0) else ""


def percent(x):
    return f"{100 * x:.1f} %" if x not in ("", None) else "–"


def pair(run_a, run_b):
    """'total ratio (per-step ratio)' of two runs, or '–'."""
    if not run_a or not run_b:
        return "–"
    return (f"{fmt(ratio(run_a['total_s'], run_b['total_s']))} "
            f"({fmt(ratio(run_a['per_step_ms'], run_b['per_step_ms']))})")


def damage(r):
    """The damage solves per step: the slowest rank where the program gives
    them by rank, else rank 0's."""
    return r.get("damage_solve_max_ms") or r.get("damage_solve_ms", "")


def cost_table(best):
    lines = ["| cells | ranks | run | dofs | total [s] | per step [ms] | " +
             " | ".join(t for _, t in PHASE_TITLES) +
             " | memory rank 0 [MB] | memory all ranks [MB] | private "
             "memory all ranks [MB] |",
             "|" + "---|" * (9 + len(PHASE_TITLES))]
    for (size, k), r in sorted(best.items(), key=lambda i: (
            i[0][0], i[0][1][3], order(i[1]))):
        cells = [fmt(r.get(p + "_ms")) for p, _ in PHASE_TITLES]
        if r.get("damage_solve_min_ms") not in ("", None):  # by rank
            cells[PHASE_TITLES.index(("damage_solve", "damage solve"))] = (
                f"{fmt(r['damage_solve_min_ms'])}–"
                f"{fmt(r['damage_solve_max_ms'])}")
        lines.append(f"| {size}² | {k[3]} | {name(r)} | {r['dofs']} | "
                     f"{fmt(r['total_s'])} | {fmt(r['per_step_ms'])} | " +
                     " | ".join(cells) + f" | {fmt(r.get('mem_rank0_mb', ''))}"
                     f" | {fmt(r.get('mem_all_mb', ''))}"
                     f" | {fmt(r.get('mem_private_mb', ''))} |")
    return lines


def advice(best, sizes):
    """Per size: the fastest run on 1 and on 2 ranks and the one with the
    least memory, among the program's."""
    lines = []
    for size in sizes:
        mine = [r for (s, k), r in best.items() if s == size
                and k[0] == "vpcontact"]
        if not mine:
            continue
        parts = []
        for ranks in (1, 2):
            rs = [r for r in mine if int(r["ranks"]) == ranks]
            if rs:
                r = min(rs, key=lambda r: r["total_s"])
                parts.append(f"fastest on {ranks} rank{'s' * (ranks > 1)}: "
                             f"{config(r)} ({fmt(r['total_s'])} s)")
        withmem = [r for r in mine if r.get("mem_all_mb") != ""]
        if withmem:
            r = min(withmem, key=lambda r: r["mem_all_mb"])
            parts.append(f"least memory: {config(r)} on {r['ranks']} "
                         f"rank{'s' * (int(r['ranks']) > 1)} "
                         f"({fmt(r['mem_all_mb'])} MB)")
        lines.append(f"* {size}²: " + "; ".join(parts) + ".")
    return lines


def time_split(best, size):
    """Where a step's time goes on the largest mesh: the share of the
    displacement solve, the damage solves and the assembly in each run."""
    lines = ["| run | ranks | per step [ms] | displacement solve | "
             "damage solves | assembly | the rest |", "|---|---|---|---|---|---|---|"]
    for (s, k), r in sorted(best.items(), key=lambda i: (
            i[0][1][3], order(i[1]))):
        step = r.get("per_step_ms")
        if s != size or step in ("", None, 0):
            continue
        shares = [ratio(r.get(p + "_ms"), step) for p in
                  ("solve", "damage_solve", "assembly")]
        if any(x == "" for x in shares):
            continue
        lines.append(f"| {name(r)} | {k[3]} | {fmt(step)} | " + " | ".join(
            f"{100 * x:.0f} %" for x in shares + [1 - sum(shares)]) + " |")
    return lines


def versus(now, then, slower_marks):
    """'HEAD / earlier = ratio' of one figure, the ratio in bold where HEAD
    takes longer (counted in slower_marks)."""
    if now in ("", None) or then in ("", None) or not (now or then):
        return "–"
    if not then:  # a phase the earlier commit did not have
        slower_marks.append(True)
        return f"**{fmt(now)} / 0**"
    r = f"{now / then:.2f}"  # slower: above 1.00 as shown
    slower_marks.append(float(r) > 1)
    return f"{fmt(now)} / {fmt(then)} = " + (f"**{r}**" if float(r) > 1
                                              else r)


def against_section(every):
    """Each phase per step of every configuration that HEAD and an earlier
    commit (--against) both ran, side by side, and the ratio."""
    head_run = next(iter(every.values()), None)
    now = head(head_run) if head_run else ""
    earlier = sorted({k[4] for _, k in every if k[4] != now})
    if not earlier:
        return ["This run compared no earlier commit; `scripts/bench "
                "--against COMMIT` adds one."]
    lines = [
        f"Time per step in ms of HEAD ({now}) / the earlier commit = the "
        "ratio, **bold** where HEAD takes longer (or, in the last column, "
        "needs more memory), for every configuration "
        "both ran in this benchmark (each earlier commit's run right after "
        "HEAD's in every round). Each commit's timer names are grouped as "
        "above; a name the grouping does not know counts as *other* (the "
        "CSV's column *phases* keeps every name). Configurations an earlier "
        "commit does not offer are listed under *Runs not in the tables*.",
        "", "| cells | ranks | run | against | per step | " +
        " | ".join(t for _, t in PHASE_TITLES) + " | memory all ranks |",
        "|" + "---|" * (6 + len(PHASE_TITLES))]
    marks = {c: [] for c in earlier}
    for (size, k), r in sorted(every.items(), key=lambda i: (
            i[0][0], i[0][1][3], order(i[1]))):
        if r["code"] != "vpcontact" or not is_head(r):
            continue
        for commit in earlier:
            old = every.get((size, k[:4] + (commit,)))
            if not old:
                continue
            cells = [versus(r.get(f), old.get(f), marks[commit]) for f in
                     ["per_step_ms"] + [p + "_ms" for p, _ in PHASE_TITLES]
                     + ["mem_all_mb"]]
            scene = ("" if old.get("scene") == r.get("scene") else
                     " (its scene file differs)")
            lines.append(f"| {size}² | {k[3]} | {config(r)} | {commit}"
                         f"{scene} | " + " | ".join(cells) + " |")
    lines.append("")
    lines += [f"* Against {c}: HEAD takes longer in {sum(m)} of the "
              f"{len(m)} figures compared." for c, m in marks.items()]
    return lines


def introduction(m, rows, csv_link):
    """The page's title, what it measures and the section *Machine and
    runs*."""
    steps = int(m["steps"])
    rounds = max(int(r["round"]) for r in rows)
    return [
        "# Performance", "",
        "What the displacement solvers of vpcontact cost on the paper scene "
        "on 1 and 2 MPI ranks, next to an independent DOLFINx implementation "
        "of the same scheme (the peer), all measured in one run of "
        "`scripts/bench` on one machine. This page is that script's output; "
        f"the raw figures are in [{csv_link}]({csv_link}).", "",
        "## Machine and runs", "",
        f"* {m['cpu']}, {m['cores']} cores, {m['memory_gb']} GB, {m['os']}; "
        f"deal.II {m['dealii']}, PETSc {m['petsc'] or '–'}, DOLFINx "
        f"{m['dolfinx'] or '–'}"
        + (f"; OpenBLAS with its {m['blas']} kernels" if m.get("blas")
           else "")
        + f"; vpcontact at commit {head(m)}"
        + settings_of_head(rows)
        + "".join(f" and at {c}" for c in sorted(
            {r["commit"] for r in rows
             if not is_head(r) and not head_setting(r)}))
        + f"; measured {m['date']}.",
        f"* Scene: `prm/paper_fig1.prm` (Tresca friction, gradient damage, "
        f"the paper's law) on N x N cells, {steps} steps over T = 1; "
        "vpcontact writes the fields (column *output*) and estimates its "
        "error (column *error estimate*) every 10 steps, as the scene sets "
        "them; the peer does neither.",
        "* vpcontact: `Solver/Linear algebra` = Trilinos or PETSc; the "
        "direct path is `Solver/Linear solver = Cholesky` (CHOLMOD, one "
        "process; run with the Trilinos package) or "
        "`MUMPS`, the AMG path `CG with AMG` (ML or GAMG, the rigid motions "
        "as near null space). The damage solves use the default "
        "`Solver/Damage preconditioner` (the program's region solver, "
        "CG over the free nodes). 2 ranks are "
        "`mpirun -np 2`, one core each; 1 rank uses deal.II's threads on "
        "both cores.",
        "* Peer: `peer.py --solver lu` (MUMPS LU, factorized once) and "
        "`--solver gamg` (CG + PETSc GAMG), after a warm-up run that "
        "compiles its forms.",
    ] + partial_line(rows) + blas_line(m) + huge_page_line(m) + [
        "* *total*: the run's own clock from start to end (vpcontact's "
        "timer table, the peer's `t_total`). *per step*: (total − mesh and "
        "dof set-up) / steps, split by phase in ms per step (rank 0's "
        "timers; the damage solve as min–max over the ranks where the "
        "program reports it by rank). vpcontact's *other* is the rest of "
        "its step, outside the timer's named phases: the damage step's "
        "passes before its first solve, the start vector and the update of "
        "the displacement, the friction sets, the initial state at t = 0. "
        "The peer's timers "
        "split less finely: its *assembly* is all its assembly, its *other* "
        "holds the stress update. *memory*: peak resident set, rank 0 "
        "as vpcontact prints it, and summed over the ranks from "
        "`/usr/bin/time -v`. *private memory*: the peak of the ranks' "
        "anonymous memory (heap, stacks, anonymous maps) summed over them, "
        "sampled every 0.1 s from `/proc` (`scripts/bench_process.py`): "
        "the resident set without the pages mapped from files, the "
        "libraries' code and symbol tables among them, which the page cache "
        "holds once for every process of the machine that maps them.",
        f"* Each run is the median of {rounds} rounds by total time"
        + (" (of an even number, the slower of the middle two)."
           if rounds % 2 == 0 else ".") if rounds > 1 else
        "* One round: the machine's speed can drift by tens of per cent "
        "between runs; `--rounds 3` reports medians.",
    ] + spread_line(rows) + [""]


def partial_line(rows):
    """For a run of part of the configurations (--configs), which ran."""
    head_rows = [r for r in rows if is_head(r)]
    names = sorted({config_name(r) for r in head_rows})
    if len(names) >= ALL_CONFIGS:
        return []
    return ["* Only these configurations ran (`--configs`): "
            + "; ".join(names) + ". Which solver to pick and the goals "
            "that need the others are left out."]


def spread_line(rows):
    """How far the rounds of one configuration lay apart on the largest
    mesh, where the goals are measured: for each code (vpcontact, the
    peer), the configuration whose slowest round took the most over its
    fastest. A ratio between two runs on the page can move by as much
    between benchmarks."""
    largest = max(int(r["size"]) for r in rows)
    runs = {}
    for r in rows:
        if r["status"] == "ok" and int(r["size"]) == largest:
            runs.setdefault(key(r) + (r["commit"],), []).append(r)
    widest = {}
    for same in runs.values():
        totals = [r["total_s"] for r in same]
        spread = max(totals) / min(totals)
        code = same[0]["code"]
        if len(same) > 1 and spread > widest.get(code, (0,))[0]:
            widest[code] = (spread, same[0], totals)
    parts = [f"{'vpcontact' if code == 'vpcontact' else 'the peer'}'s up "
             f"to {100 * (spread - 1):.0f} % ({name(r)}, {r['ranks']} "
             f"rank{'s' * (int(r['ranks']) > 1)}: "
             + " / ".join(f"{t:.1f}" for t in totals) + " s)"
             for code, (spread, r, totals) in sorted(widest.items(),
                                                     reverse=True)]
    return ([f"* Spread between the rounds at {largest}², slowest over "
             "fastest total of one configuration: " + "; ".join(parts)
             + ". A ratio of two configurations on this page moves by up "
             "to as much between benchmarks."] if parts else [])


def runs_not_in_tables(rows):
    """The section that names the runs that failed or were skipped, one
    line per reason."""
    reasons = {}
    for r in rows:
        if r["status"] != "ok":
            reasons.setdefault(r["status"], []).append(
                f"{name(r)} on {r['ranks']} rank{'s' * (int(r['ranks']) > 1)}"
                + ("" if r["status"].startswith("skipped") else
                   f" at {r['size']}² (round {r['round']})"))
    notes = [f"* {'; '.join(runs)}: {status}"
             for status, runs in reasons.items()]
    return ["", "## Runs not in the tables", ""] + notes if notes else []


# What a run without --configs runs: vpcontact's four paths with either
# package and the peer's three (scripts/bench.py's plan()).
ALL_CONFIGS = 11


def config_name(r):
    """The name by which scripts/bench's --configs selects the run of
    @p r, as in 'vpcontact Trilinos Cholesky, 1 rank', 'peer gamg, 2
    ranks'."""
    algebra = r["algebra"] + " " if r["code"] == "vpcontact" else ""
    ranks = int(r["ranks"])
    return f"{r['code']} {algebra}{r['solver']}, {ranks} rank{'s' * (ranks > 1)}"


def run_options(rows):
    """The options of scripts/bench that ran @p rows: the sizes and the
    rounds where they are not the default, and for a part of the
    configurations (--configs, --one-thread, --huge-pages) the names of
    those that ran, so that the command on the page runs the same set
    again. An --against commit runs what it offers of that set, or the
    part of it that ran."""
    def names(selected):
        return "|".join(sorted({config_name(r) for r in selected}))

    sizes = sorted({int(r["size"]) for r in rows})
    options = (" [SIZES]" if sizes == [128, 256, 512] else
               "".join(f" {n}" for n in sizes))
    rounds = max(int(r.get("round") or 1) for r in rows)
    if rounds > 1:
        options += f" --rounds {rounds}"
    head = [r for r in rows if str(r.get("commit")) == str(r.get("head"))]
    if len({config_name(r) for r in head}) < ALL_CONFIGS:
        options += f" --configs '{names(head)}'"
    for commit in sorted({str(r.get("commit")) for r in rows} -
                         {str(r.get("head")) for r in rows}):
        selected = [r for r in rows if str(r.get("commit")) == commit]
        which = names(selected)
        if commit.endswith(ONE_THREAD):
            options += f" --one-thread '{which}'"
        elif commit.endswith(" huge pages"):
            options += f" --huge-pages '{which}'"
        elif {config_name(r) for r in selected} < {
                config_name(r) for r in head
                if not config_name(r).startswith("peer")}:
            options += f" --against '{commit}:{which}'"
        else:
            options += f" --against {commit}"
    return options


def regenerating(rows, csv_link, out, csv_path):
    """The section *Regenerating*: the command and its options. A page
    other than doc/performance.md (another machine's) names its own --out
    and --csv, so that the command rewrites it rather than that page."""
    minutes = sum(r.get("process_wall_s") or 0 for r in rows) / 60
    command = "scripts/bench" + run_options(rows)
    if os.path.abspath(out) != os.path.join(ROOT, "doc", "performance.md"):
        command += "".join(f" --{o} {os.path.relpath(os.path.abspath(p), ROOT)}"
                           for o, p in (("out", out), ("csv", csv_path)))
    return [
        "", "## Regenerating", "",
        f"`{command}` runs this set again (it took {fmt(minutes)} minutes; "
        "without sizes, 128 256 512) and rewrites this page and "
        f"`{csv_link}`. Options: `--steps N` (default 100), `--rounds R`, "
        "`--no-peer`, `--out FILE` (the page; the CSV goes to "
        "figures/bench.csv beside it), `--quick` (16² and 32², 10 steps, "
        "into /tmp/vpcontact_bench), `--configs REGEX` (only the runs "
        "whose name matches, as in `'Trilinos Cholesky, 1 rank'` or "
        "`'AMG, 2 ranks'`), `--against COMMIT[:REGEX]` (repeatable: "
        "builds vpcontact at COMMIT in a temporary git worktree under the "
        "work folder, runs each configuration it offers, or those whose "
        "name matches REGEX, right after HEAD's and fills the section "
        "*Phases against earlier commits*; the worktree is removed at the "
        "end), `--huge-pages [REGEX]` (HEAD's build again with "
        "`VPCONTACT_HUGE_PAGES=1`, its heap in transparent huge pages, "
        "compared in the same section), `--one-thread [REGEX]` (HEAD's "
        "build again on 1 rank with `DEAL_II_NUM_THREADS=1`, compared in "
        "the same section and in the speed-up goals). "
        "`scripts/bench_report.py CSV PAGE` "
        "rewrites the page from the CSV alone. Run it with nothing else "
        "busy on the machine."]


def head_sections(best, sizes, algebras):
    """The sections on HEAD's runs alone: which solver to pick, the ratios
    against the peer, the growth with the mesh and the shares of a step."""
    import bench_tables  # noqa: E402  (it imports this module)
    # A run of part of the configurations (--configs) cannot say which to
    # pick, nor one size how the time grows.
    every_path = len({k for _, k in best}) >= ALL_CONFIGS
    pick = [
        "## Which to pick", "",
    ] + advice(best, sizes) + [
        "* `Cholesky` runs on one process only; `MUMPS` is the direct "
        "solver on several ranks. Both factorize once per stick set and "
        "reuse the factors in every step.",
        "* `CG with AMG` stores no factors; it is the solver meant for "
        "meshes finer than those above and for more ranks.", ""]
    growth = [
        "", "## Growth with the mesh", "",
        "Factor by which the time per step grows per 4x unknowns "
        "(4 where it grows like the unknowns).", "",
    ] + bench_tables.growth_table(best, sizes)
    return (pick if every_path else []) + [
        "## Against the peer", "",
        "Ratios of wall time, total (per step in brackets); below 1 "
        "vpcontact takes less. Memory: peak resident set summed over the "
        "ranks; in brackets the same of the private memory.", "",
    ] + bench_tables.ratio_table(best, sizes, algebras) + (
        growth if len(sizes) > 1 else []) + [
        "", f"## Where the time goes at {max(sizes)}²", "",
        "Shares of a step. The displacement solve of CG with AMG is a "
        "number of AMG cycles over the whole displacement block: products "
        "with the matrix on its finest level and in CG (from the patterns "
        "of the matrix's repeated rows, RowPatternMatrix in "
        "[design.md](design.md)), ML's or GAMG's products on the coarser "
        "levels and between them, bound by the memory bandwidth; a "
        "factorization's solve is a pair "
        "of triangular substitutions over factors many times the size of "
        "the matrix. The damage solves are several CG solves per step, one "
        "for each active set the bound iteration tries "
        "([damage.md](damage.md)).", "",
    ] + time_split(best, max(sizes))


def write_report(out, csv_path, rows):
    import bench_goals  # noqa: E402  (it imports this module)
    import adaptive_run_report  # noqa: E402  (next to this file)
    import bench_solvers_report  # noqa: E402  (next to this file)
    import bench_3d_report  # noqa: E402  (it imports this module)
    import bench_setup_report  # noqa: E402  (it imports this module)
    rows = [untimed_in_other(r) for r in rows]
    ok = [r for r in rows if r["status"] == "ok"] or rows
    m = ok[0]
    # The tables of HEAD against the peer and the goals take HEAD's runs;
    # the costs and the phases against earlier commits take every commit's.
    best = medians([r for r in rows if is_head(r)])
    every = medians(rows, key=lambda r: key(r) + (r["commit"],))
    earlier = sorted({r["commit"] for r in rows if not is_head(r)})
    sizes = sorted({int(r["size"]) for r in rows})
    algebras = [a for a in ("Trilinos", "PETSc")
                if any(k[1] == a for _, k in best)]
    csv_link = os.path.relpath(os.path.abspath(csv_path),
                               os.path.dirname(os.path.abspath(out)))
    text = introduction(m, rows, csv_link) + [
        "## What each solver costs", "",
    ] + cost_table(every) + [
        "", "## Phases against earlier commits", "",
    ] + against_section(every) + [""] + head_sections(
        best, sizes, algebras) + [
        "", f"## Against the project's goals at {max(sizes)}²", "",
        "The goals the project set itself for this program against the "
        "peer, the figures of this run, and what limits them.", "",
    ] + bench_goals.goals(best, sizes, algebras, every) + (
        bench_3d_report.scene_3d(csv_path)
        + bench_setup_report.setup_scaling(csv_path)
        + bench_solvers_report.solver_choice(csv_path)
        + adaptive_run_report.adaptation_cost(csv_path))
    text += runs_not_in_tables(rows) + regenerating(rows, csv_link, out,
                                                    csv_path)
    with open(out, "w") as f:
        f.write("\n".join(text) + "\n")
    # The decisions of the rule on own kernels go into the design page
    # beside the report of doc/ (not for a report elsewhere, as --quick's).
    design = os.path.join(os.path.dirname(os.path.abspath(out)), "design.md")
    if earlier and os.path.abspath(out) == os.path.join(ROOT, "doc",
                                                        "performance.md"):
        import bench_decisions  # noqa: E402  (it imports this module)
        bench_decisions.rewrite_design(every, design)
    if len(text) > 150:
        print(f"note: {out} has {len(text)} lines")


def main():
    csv_path = (sys.argv[1] if len(sys.argv) > 1 else
                os.path.join(ROOT, "doc", "figures", "bench.csv"))
    out = (sys.argv[2] if len(sys.argv) > 2 else
           os.path.join(ROOT, "doc", "performance.md"))
    write_report(out, csv_path, read_csv(csv_path))
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
