#!/usr/bin/python3
"""Tables and plot of the convergence study (scripts/convergence).

Reads RESULTS/{uniform,adaptive,smooth_uniform}/convergence.csv (written by
vpcontact; the last is optional) and
writes DOC/convergence_tables.md (the two tables in Markdown) and
DOC/figures/convergence.png (summed error of Theorem 2 against run time,
log-log, uniform and adaptive on the same axes).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def table(rows, title):
    head = ("| cycle | cells | dofs | h | k | steps | run time [s] | "
            "cumulative [s] | max‖ε(e_u)‖ | order | max‖e_σ‖ | order | "
            "max‖e_ζ‖ | order | max sum | order | sum at T |\n")
    lines = [f"**{title}**\n\n", head, "|" + "---|" * 17 + "\n"]
    for r in rows:
        def g(key, fmt="{:.3e}"):
            return fmt.format(float(r[key])) if r[key] else ""
        lines.append(
            f"| {r['cycle']} | {r['cells']} | {r['dofs']} | {g('h')} | "
            f"{g('k')} | {r['steps']} | {g('wall_time', '{:.2f}')} | "
            f"{g('cumulative_wall_time', '{:.2f}')} | {g('error_u')} | "
            f"{g('error_u_order', '{:.2f}')} | {g('error_stress')} | "
            f"{g('error_stress_order', '{:.2f}')} | {g('error_damage')} | "
            f"{g('error_damage_order', '{:.2f}')} | {g('error_sum')} | "
            f"{g('error_sum_order', '{:.2f}')} | {g('final_error_sum')} |\n")
    return "".join(lines) + "\n"


def main(results, doc):
    uniform = read(os.path.join(results, "uniform", "convergence.csv"))
    adaptive = read(os.path.join(results, "adaptive", "convergence.csv"))
    with open(os.path.join(doc, "convergence_tables.md"), "w") as f:
        f.write("<!-- Written by scripts/convergence from "
                "results/convergence/*/convergence.csv; do not edit. -->\n"
                "# Convergence tables of the paper scene\n\n"
                "Errors against the reference run "
                "(prm/convergence/paper_fig1_reference.prm: 256 x 256 cells, "
                "k = 0.0015625), largest over the common times (every 0.05 s "
                "where the run has a step), in the norms of Theorem 2; "
                "orders against the previous row in h = (|Ω|/cells)^(1/2). "
                "Run time: the run on that mesh (setup, all steps, "
                "indicators), without the comparison; cumulative: all "
                "cycles so far. See convergence.md.\n\n")
        f.write(table(uniform, "Uniform refinement, h and k halved together"))
        f.write(table(adaptive, "Adaptive refinement (k halved when the "
                                "equivalent h halves)"))
        smooth = os.path.join(results, "smooth_uniform", "convergence.csv")
        if os.path.exists(smooth):
            f.write(table(read(smooth),
                          "Smooth variant (prm/convergence/smooth_*.prm, "
                          "reference 128 x 128 cells, k = 0.003125), uniform "
                          "refinement"))

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for rows, label, marker in ((uniform, "uniform (h, k halved)", "o"),
                                (adaptive, "adaptive, run on the mesh", "s")):
        ax.loglog([float(r["wall_time"]) for r in rows],
                  [float(r["error_sum"]) for r in rows],
                  marker=marker, label=label)
    ax.loglog([float(r["cumulative_wall_time"]) for r in adaptive],
              [float(r["error_sum"]) for r in adaptive], "s--",
              mfc="none", label="adaptive, all cycles so far")
    for r in uniform:
        ax.annotate(f"{int(r['cells'])}", (float(r["wall_time"]),
                                           float(r["error_sum"])),
                    textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xlabel("run time [s] (1 core)")
    ax.set_ylabel("max_n (‖ε(e_u)‖ + ‖e_σ‖ + ‖e_ζ‖)")
    ax.set_title("Paper scene: error against run time")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    os.makedirs(os.path.join(doc, "figures"), exist_ok=True)
    fig.savefig(os.path.join(doc, "figures", "convergence.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
