"""The section *The 3D scenes* of doc/performance.md, from bench_3d.csv
beside the CSV of the 2D runs (scripts/bench_3d writes it)."""
from bench_report import PHASE_TITLES, fmt, sibling_rows


def steps_text(steps):
    return f"{steps} step" + ("" if str(steps) == "1" else "s")


def other_sittings(rows, m):
    """A sentence for each scene whose first row was measured in another
    sitting than the first row of all (bench_3d --scenes replaces only the
    scenes it runs), so that the header does not claim those rows."""
    text = ""
    for scene in dict.fromkeys(r.get("scene") or "paper" for r in rows):
        f = next(r for r in rows if (r.get("scene") or "paper") == scene)
        if (f["date"], f["cpu"], f["steps"]) != (m["date"], m["cpu"],
                                                 m["steps"]):
            text += (f" The *{scene}* rows: {steps_text(f['steps'])}, "
                     "measured at "
                     f"commit {f['commit']} on {f['date']} ({f['cpu']}).")
    return text


def scene_3d(csv_path):
    """The section of the 3D paper scene from bench_3d.csv beside the
    CSV of the 2D runs (scripts/bench_3d), if there is one."""
    rows = [r for r in sibling_rows(csv_path, "bench_3d.csv") if r["status"] == "ok"
            or r["status"].startswith("stopped after")]
    if not rows:
        return []
    m = rows[0]
    stopped = [r for r in rows if r["status"] != "ok"]
    # The rows after the first of each scene ran an earlier commit's
    # executable in the same sitting (--against).
    firsts = {}
    for r in rows:
        firsts.setdefault(r.get("scene") or "paper", id(r))
    commits = sorted({r["commit"] for r in rows if id(r) not in
                      firsts.values()} - {m["commit"]})
    side_by_side = (
        f" Rows of commit {', '.join(commits)} ran the executable of that "
        "earlier commit right after this one's (`--against`), for "
        "comparison on the same machine in the same sitting." if commits
        else "")
    lines = [
        "", "## The 3D scenes", "",
        "`prm/paper_fig1_3d.prm` (*paper*: the unit cube, Tresca friction "
        "on z = 0, gradient damage, the paper's law) and "
        "`prm/paper_fig1_3d_slip.prm` (*slip*: the same without damage and "
        "with a friction bound low enough for the contact face to slip) on "
        "N × N × N cells (column *N*), "
        f"{steps_text(m['steps'])} of k = 0.01 with `CG with AMG` (Trilinos "
        "ML), no field output, measured by `scripts/bench_3d` at commit "
        f"{m['commit']} on {m['date']} ({m['cpu']}). Time per step in ms, "
        "split as above; *AS its*: friction active-set iterations per "
        "step (one where a node changes set reassembles the matrix and "
        "rebuilds AMG)." + side_by_side + other_sittings(rows, m), "",
        "| scene | commit | N | ranks | dofs | total [s] | per step [ms] | " +
        " | ".join(t for _, t in PHASE_TITLES) +
        " | CG its per step | AS its per step | memory rank 0 [MB] | "
        "memory all ranks [MB] | private memory all ranks [MB] |",
        "|" + "---|" * (12 + len(PHASE_TITLES))]
    for r in rows:
        lines.append(
            f"| {r.get('scene') or 'paper'}"
            f"{' (stopped)' if r in stopped else ''} | {r['commit']} | "
            f"{r['cells_per_side']} | "
            f"{r['ranks']} | {r['dofs'] or '–'} | "
            f"{fmt(r['total_s'])} | {fmt(r['per_step_ms'])} | " +
            " | ".join(fmt(r.get(p + "_ms")) for p, _ in PHASE_TITLES) +
            f" | {fmt(r['linear_its'])} | {fmt(r['active_set_its'])} | "
            f"{fmt(r['mem_rank0_mb'])} | {fmt(r['mem_all_mb'])} | "
            f"{fmt(r.get('mem_private_mb', ''))} |")
    lines += comparisons(rows)
    for r in stopped:
        lines += ["", f"*{r.get('scene')}, {r['commit']} (stopped)*: "
                  f"{r['status']}; " + (
                      "its time per step is the mean wall time of the steps "
                      "it finished (statistics.csv), without the split by "
                      "phase." if r.get("per_step_ms") else
                      "its first step took longer than the time allowed, so "
                      "it has no figures.")]
    return lines


def comparisons(rows):
    """A line per row of an earlier commit (--against) that finished, with
    its time per step and memory against the first row of the same scene
    and ranks, which ran the commit measured (bench_3d writes that one
    first in each scene)."""
    lines = []
    heads = {}
    for r in rows:
        key = (r.get("scene") or "paper", r["ranks"])
        head = heads.setdefault(key, r)
        if head is r or r["commit"] == head["commit"]:
            continue
        if r["status"] != "ok" or head["status"] != "ok":
            continue
        lines += ["", f"*{key[0]}, {r['ranks']} ranks, "
                  f"{head['commit']} against {r['commit']}*: time per step "
                  f"{fmt(head['per_step_ms'])} / {fmt(r['per_step_ms'])} "
                  f"ms = {float(head['per_step_ms']) / float(r['per_step_ms']):.3g}, "
                  f"peak memory over the ranks {fmt(head['mem_all_mb'])} / "
                  f"{fmt(r['mem_all_mb'])} MB = "
                  f"{float(head['mem_all_mb']) / float(r['mem_all_mb']):.3g}."]
    return lines
