"""The section of doc/performance.md on the cost of adapting the mesh during
a run, from doc/figures/adaptive_run.csv (scripts/adaptive_run_study), for
scripts/bench_report.py."""
from bench_report import sibling_rows


def pct(v):
    return f"{100 * float(v):.1f} %"


def adaptation_cost(csv_path):
    """The share of each adapting run spent on its adaptations, split into
    marking, transfer (with p4est's repartitioning) and the setup on the new
    mesh, if adaptive_run.csv exists beside the CSV of the 2D runs."""
    rows = sibling_rows(csv_path, "adaptive_run.csv")
    if not rows:
        return []
    lines = [
        "", "## Adapting the mesh during a run", "",
        "The runs of `prm/convergence/paper_fig1_adaptive_run.prm` "
        "([adaptivity.md](adaptivity.md)): the share of the run's time "
        "(without the comparison with the reference) its "
        "mesh adaptations took (the timer's *Mesh adaptation*), split into "
        "marking the cells, the transfer of the state (with p4est's "
        "repartitioning and the wait for the fields being written in the "
        "background) and the setup of every physics object and solver on "
        "the new mesh. Measured by `scripts/adaptive_run_study` "
        f"{rows[0]['measured']}.", "",
        "*adaptations*: those before the first step and those during the "
        "run.", "",
        "| run | adaptations | cells at the end | run time [s] | adaptation, "
        "share of the run | marking | transfer | setup |",
        "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['run']} | {r['adaptations']} | {r['cells']} | "
                     f"{float(r['wall_time']):.3g} | {pct(r['share_all'])} | "
                     f"{pct(r['share_marking'])} | "
                     f"{pct(r['share_transfer'])} | {pct(r['share_setup'])} |")
    return lines
