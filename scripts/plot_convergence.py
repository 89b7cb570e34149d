#!/usr/bin/python3
"""Tables and plot of the convergence study (scripts/convergence).

Reads RESULTS/{uniform,adaptive,smooth_uniform,smooth_adaptive}/
convergence.csv (written by vpcontact; the smooth ones are optional) and
writes DOC/convergence_tables.md (every row, errors and error estimate),
the block between the "generated" markers of DOC/convergence.md (the
effectivity of the estimate and the cost of reaching the uniform study's
smallest error) and DOC/figures/convergence.png (summed error of Theorem 2
and its estimate against run time, log-log, uniform and adaptive).
"""
import csv
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

STUDIES = (("uniform", "Paper scene, uniform refinement (h and k halved)"),
           ("adaptive", "Paper scene, adaptive refinement, k from the "
                        "estimate"),
           ("smooth_uniform", "Smooth variant, uniform refinement"),
           ("smooth_adaptive", "Smooth variant, adaptive refinement, k from "
                               "the estimate"))


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def g(r, key, fmt="{:.3e}"):
    return fmt.format(float(r[key])) if r.get(key) else ""


def table(rows, title):
    head = ("| cycle | cells | h | k | steps | run time [s] | "
            "cumulative [s] | max‖ε(e_u)‖ | max‖e_σ‖ | max‖e_ζ‖ | max sum "
            "| order | estimate | order | space | time | effectivity |\n")
    lines = [f"**{title}**\n\n", head, "|" + "---|" * 17 + "\n"]
    for r in rows:
        lines.append(
            f"| {r['cycle']} | {r['cells']} | {g(r, 'h')} | {g(r, 'k')} | "
            f"{r['steps']} | {g(r, 'wall_time', '{:.2f}')} | "
            f"{g(r, 'cumulative_wall_time', '{:.2f}')} | {g(r, 'error_u')} | "
            f"{g(r, 'error_stress')} | {g(r, 'error_damage')} | "
            f"{g(r, 'error_sum')} | {g(r, 'error_sum_order', '{:.2f}')} | "
            f"{g(r, 'estimate')} | {g(r, 'estimate_order', '{:.2f}')} | "
            f"{g(r, 'estimate_space')} | {g(r, 'estimate_time')} | "
            f"{g(r, 'effectivity', '{:.2f}')} |\n")
    return "".join(lines) + "\n"


def effectivity_summary(studies):
    """The effectivity range of each study, all rows and rows >= 1000 cells."""
    lines = ["| study | rows | effectivity, all rows | rows with at least "
             "1000 cells | effectivity there |\n", "|---|---|---|---|---|\n"]
    everything = []
    for name, title, rows in studies:
        eff = [float(r["effectivity"]) for r in rows if r["effectivity"]]
        big = [float(r["effectivity"]) for r in rows
               if r["effectivity"] and int(r["cells"]) >= 1000]
        everything += big
        lines.append(f"| {title} | {len(eff)} | {min(eff):.2f} – "
                     f"{max(eff):.2f} | {len(big)} | "
                     + (f"{min(big):.2f} – {max(big):.2f}" if big else "–")
                     + " |\n")
    lines.append(f"\nOn all {len(everything)} rows with at least 1000 cells "
                 f"the effectivity index lies in [{min(everything):.2f}, "
                 f"{max(everything):.2f}] (target [0.5, 2]: "
                 + ("met" if 0.5 <= min(everything) and max(everything) <= 2
                    else "NOT met") + ").\n")
    return "".join(lines)


def first_below(rows, error):
    for r in rows:
        if float(r["error_sum"]) <= error:
            return r
    return None


def cost_summary(uniform, adaptive):
    """What adaptive cycles pay for the uniform study's errors."""
    finest = uniform[-1]
    lines = ["| target error (sum) | uniform: first run below it | adaptive: "
             "first cycle below it | adaptive, all cycles so far | ratio "
             "(all cycles / uniform run) |\n", "|---|---|---|---|---|\n"]
    targets = sorted({float(r["error_sum"]) for r in uniform[-3:]} | {1.78},
                     reverse=True)
    for target in targets:
        u = first_below(uniform, target * (1 + 1e-12))
        a = first_below(adaptive, target * (1 + 1e-12))
        us = (f"{float(u['error_sum']):.3g} in {float(u['wall_time']):.2f} s "
              f"({u['cells']} cells, k = {float(u['k']):g})" if u
              else "not reached")
        if a:
            ac = (f"{float(a['error_sum']):.3g} in "
                  f"{float(a['wall_time']):.2f} s ({a['cells']} cells, "
                  f"k = {float(a['k']):g})")
            cum = f"{float(a['cumulative_wall_time']):.2f} s"
            ratio = (f"{float(a['cumulative_wall_time']) / float(u['wall_time']):.3f}"
                     if u else "–")
        else:
            ac, cum, ratio = "not reached", "–", "–"
        lines.append(f"| {target:.3g} | {us} | {ac} | {cum} | {ratio} |\n")
    lines.append(f"\nThe uniform study's smallest error is "
                 f"{float(finest['error_sum']):.3g} ({finest['cells']} "
                 f"cells, {float(finest['wall_time']):.1f} s).\n")
    return "".join(lines)


def estimate_cost(results, rows):
    """The share of each run's time spent on the error estimate: the seconds
    of the "Error estimate" line of the timer table that every cycle prints
    (logs results/convergence_<scene>.log), divided by the cycle's run time
    in convergence.csv (which leaves out the comparison with the
    reference)."""
    pattern = re.compile(r"\| Error estimate\s+\|\s+\d+\s+\|\s+(\S+)s\s+\|")
    lines = []
    for scene, name in (("paper_fig1_uniform", "uniform"),
                        ("paper_fig1_adaptive", "adaptive"),
                        ("smooth_uniform", "smooth_uniform"),
                        ("smooth_adaptive", "smooth_adaptive")):
        path = os.path.join(os.path.dirname(results.rstrip("/")),
                            f"convergence_{scene}.log")
        if not os.path.exists(path) or name not in rows:
            continue
        with open(path) as f:
            seconds = [float(m.group(1)) for m in pattern.finditer(f.read())]
        shares = [100 * t / float(r["wall_time"])
                  for t, r in zip(seconds, rows[name])
                  if float(r["wall_time"]) >= 1]
        if shares:
            lines.append(f"| {scene} | {len(shares)} | {min(shares):.1f} – "
                         f"{max(shares):.1f} % |\n")
    if not lines:
        return ""
    return ("| scene | runs of at least 1 s | share of the run time |\n"
            "|---|---|---|\n" + "".join(lines))


def replace_block(path, text):
    with open(path) as f:
        doc = f.read()
    begin = "<!-- BEGIN generated by scripts/convergence -->\n"
    end = "<!-- END generated by scripts/convergence -->"
    pattern = re.escape(begin) + ".*?" + re.escape(end)
    if not re.search(pattern, doc, flags=re.S):
        raise SystemExit(f"{path}: no generated block to replace")
    doc = re.sub(pattern, lambda m: begin + text + end, doc, flags=re.S)
    with open(path, "w") as f:
        f.write(doc)


def plot(uniform, adaptive, doc):
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for rows, label, marker in ((uniform, "uniform (h, k halved)", "o"),
                                (adaptive, "adaptive, run on the mesh", "s")):
        ax.loglog([float(r["wall_time"]) for r in rows],
                  [float(r["error_sum"]) for r in rows],
                  marker=marker, label=label)
    ax.loglog([float(r["cumulative_wall_time"]) for r in adaptive],
              [float(r["error_sum"]) for r in adaptive], "s--",
              mfc="none", label="adaptive, all cycles so far")
    ax.loglog([float(r["wall_time"]) for r in uniform],
              [float(r["estimate"]) for r in uniform], "o:", color="C0",
              mfc="none", alpha=0.6, label="uniform, estimate")
    ax.loglog([float(r["wall_time"]) for r in adaptive],
              [float(r["estimate"]) for r in adaptive], "s:", color="C1",
              mfc="none", alpha=0.6, label="adaptive, estimate")
    for r in uniform:
        ax.annotate(f"{int(r['cells'])}", (float(r["wall_time"]),
                                           float(r["error_sum"])),
                    textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.axhline(float(uniform[-1]["error_sum"]), color="grey", lw=0.8,
               ls="--")
    ax.set_xlabel("run time [s] (1 core)")
    ax.set_ylabel("max_n (‖ε(e_u)‖ + ‖e_σ‖ + ‖e_ζ‖)")
    ax.set_title("Paper scene: error and its estimate against run time")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    os.makedirs(os.path.join(doc, "figures"), exist_ok=True)
    fig.savefig(os.path.join(doc, "figures", "convergence.png"), dpi=120)


def main(results, doc):
    studies = []
    for name, title in STUDIES:
        path = os.path.join(results, name, "convergence.csv")
        if os.path.exists(path):
            studies.append((name, title, read(path)))
    rows = {name: r for name, _, r in studies}
    with open(os.path.join(doc, "convergence_tables.md"), "w") as f:
        f.write("<!-- Written by scripts/convergence from "
                "results/convergence/*/convergence.csv; do not edit. -->\n"
                "# Convergence tables\n\n"
                "Errors against the reference runs (paper scene: "
                "prm/convergence/paper_fig1_reference.prm, 512 x 512 cells, "
                "k = 0.00078125; smooth variant: smooth_reference.prm, "
                "128 x 128, k = 0.003125), largest over the common times "
                "(every 0.05 s where the run has a step), in the norms of "
                "Theorem 2; the error estimate of each run (largest over its "
                "steps) with its space and time parts and the effectivity "
                "index estimate / error; orders against the previous row in "
                "h = (|Ω|/cells)^(1/2). Run time: the run on that mesh "
                "(setup, all steps, the estimate), without the comparison; "
                "cumulative: all cycles so far. See convergence.md.\n\n")
        for _, title, r in studies:
            f.write(table(r, title))
    replace_block(os.path.join(doc, "convergence.md"),
                  "\n**Effectivity of the estimate** (estimate / error "
                  "against the reference):\n\n"
                  + effectivity_summary(studies)
                  + "\n**Cost of an error, uniform against adaptive** "
                  "(paper scene):\n\n"
                  + cost_summary(rows["uniform"], rows["adaptive"])
                  + "\n**Cost of the estimate** (timer line \"Error "
                  "estimate\" of every run):\n\n"
                  + estimate_cost(results, rows) + "\n")
    replace_block(os.path.join(os.path.dirname(doc.rstrip("/")) or ".",
                               "README.md"),
                  "\n" + cost_summary(rows["uniform"], rows["adaptive"])
                  + "\n" + effectivity_summary(studies).splitlines()[-1]
                  + "\n\n")
    plot(rows["uniform"], rows["adaptive"], doc)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
