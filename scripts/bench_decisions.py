"""The decisions of doc/design.md's rule on the program's own kernels, from a
benchmark with --against: for each phase of each configuration that HEAD and
an earlier commit both ran on the largest mesh, which code is faster, by how
much, and what share of the run it would save. bench_report.py calls
rewrite_design() to put the table between the markers of doc/design.md."""
import os
import re

import bench_report as report

BEGIN = "<!-- begin: written by scripts/bench -->"
END = "<!-- end: written by scripts/bench -->"
SPEED_UP = 1.5  # the rule: at least 1.5 times faster in its own phase
SHARE = 0.10    # and saving at least 10 % of the whole run


def decision(now, then, run, run_then):
    """The rule applied to one phase: HEAD takes `now` ms per step, the
    earlier commit `then`, HEAD's whole step `run`, the earlier one's
    `run_then`. Where HEAD is faster, whether HEAD's code would pass the
    rule against the earlier code (so that a kernel of HEAD's own that
    replaced a library call shows its measurement)."""
    if then is None or now is None:
        return "–", "not timed by both"
    if not then:
        return "–", "a phase the earlier commit does not have"
    if now <= then:
        if not now:
            return "–", "HEAD no slower: keep"
        share = (then - now) / run_then
        passes = then / now >= SPEED_UP and share >= SHARE
        return f"{then / now:.2f}", (
            "HEAD no slower: keep"
            + (f" (HEAD's code passes the rule: saves {share:.0%} of the "
               "earlier step)" if passes else ""))
    faster, share = now / max(then, 1e-12), (now - then) / run
    verdict = ("earlier code passes the rule: bring it back"
               if faster >= SPEED_UP and share >= SHARE else
               "earlier code faster, below the rule "
               f"({SPEED_UP}x and {SHARE:.0%}): keep HEAD's")
    return f"{then / now:.2f}", f"{verdict}; saves {share:.0%} of a step"


def number(value):
    return float(value) if value not in ("", None) else None


def table(every):
    """Rows of the decisions at the largest size of the benchmark."""
    head_run = next(iter(every.values()), None)
    if head_run is None:
        return ["No benchmark run is on record."]
    now_commit = report.head(head_run)
    sizes = [size for size, _ in every]
    size = max(sizes)
    lines = [f"At {size}² cells, per step (HEAD {now_commit} / the earlier "
             "commit; *speed* is HEAD's speed relative to the earlier "
             "code, above 1 where HEAD is faster):", "",
             "| run | against | phase | HEAD ms | earlier ms | speed | "
             "decision |", "|---|---|---|---|---|---|---|"]
    for (s, k), r in sorted(every.items(), key=lambda i: report.order(i[1])):
        if s != size or r["code"] != "vpcontact" or not report.is_head(r):
            continue
        for (s2, k2), old in every.items():
            if (s2 != size or k2[:4] != k[:4] or report.is_head(old)
                    or report.head_setting(old)):
                continue
            run = number(r.get("per_step_ms")) or 1.
            run_then = number(old.get("per_step_ms")) or 1.
            for phase, title in report.PHASE_TITLES:
                now = number(r.get(phase + "_ms"))
                then = number(old.get(phase + "_ms"))
                if not now and not then:
                    continue
                speed, verdict = decision(now, then, run, run_then)
                lines.append(
                    f"| {report.config(r)}, {k[3]} rank"
                    f"{'s' * (int(k[3]) > 1)} | {k2[4]} | {title} | "
                    f"{report.fmt(now)} | {report.fmt(then)} | {speed} | "
                    f"{verdict} |")
    return lines


def rewrite_design(every, design=None):
    """Put the table between the markers of doc/design.md (nothing else in
    the file changes); a design page without the markers is left alone."""
    design = design or os.path.join(report.ROOT, "doc", "design.md")
    if not os.path.exists(design):
        return
    text = open(design).read()
    pattern = re.compile(re.escape(BEGIN) + ".*?" + re.escape(END), re.S)
    if not pattern.search(text):
        print(f"note: {design} has no markers for the decisions")
        return
    block = "\n".join([BEGIN, ""] + table(every) + ["", END])
    with open(design, "w") as f:
        f.write(pattern.sub(lambda _: block, text))
    print(f"wrote the decisions into {design}")
