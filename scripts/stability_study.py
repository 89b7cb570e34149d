#!/usr/bin/python3
"""Run every stiff and extreme scene of prm/stiff/ and write doc/stability.md:
one row per case with its parameters, outcome, steps, iterations, damage
range, whether the bounds held, and run time, all measured in this run.

Usage: stability_study.py VPCONTACT_EXECUTABLE   (run from the repository root)
"""
import csv
import glob
import os
import re
import subprocess
import sys
import time

executable = sys.argv[1]
rows = []
for prm in sorted(glob.glob("prm/stiff/*.prm")):
    name = os.path.basename(prm)[:-4]
    with open(prm) as f:
        text = f.read()
    comment = " ".join(l[2:].strip() for l in text.splitlines()
                       if l.startswith("#"))
    settings = "; ".join(
        m.group(1).strip() + " = " + m.group(2).strip()
        for m in re.finditer(r"^\s*set ([^=\n]+)=(.*)$", text, re.M)
        if "Directory" not in m.group(1) and (
            m.group(1).strip() not in ("Law", "Model", "Contact boundary ids")
            or m.group(2).strip() == "maxwell"))
    start = time.time()
    run = subprocess.run([executable, prm], capture_output=True, text=True)
    seconds = time.time() - start
    output = run.stdout + run.stderr

    row = {"case": name, "parameters": settings, "seconds": seconds}
    if run.returncode != 0:
        message = output[output.find("Error:"):].split("\n")[0]
        row.update(outcome="stopped: " + message[7:], steps="0")
    else:
        with open(f"results/stiff/{name}/statistics.csv") as f:
            stats = list(csv.DictReader(f))
        last = stats[-1]

        def largest(column):
            values = [float(r[column]) for r in stats[1:] if r.get(column)]
            return max(values) if values else None

        def smallest(column):
            values = [float(r[column]) for r in stats[1:] if r.get(column)]
            return min(values) if values else None

        bounds = largest("damage_bound_violation")
        row.update(
            outcome="ran to the end",
            steps=last["step"],
            linear=f"{largest('linear_iterations'):.0f}",
            friction=(f"{largest('active_set_iterations'):.0f}"
                      if largest("active_set_iterations") is not None else "-"),
            damage_its=(f"{largest('damage_iterations'):.0f}"
                        if largest("damage_iterations") is not None else "-"),
            zeta=(f"[{smallest('damage_min'):.3g}, {largest('damage_max'):.3g}]"
                  if bounds is not None else "-"),
            bounds=("yes (0)" if bounds == 0 else
                    "-" if bounds is None else f"NO ({bounds:g})"),
            u_max=f"{float(last['u_max']):.4g}",
            nan="yes" if "nan" in open(
                f"results/stiff/{name}/statistics.csv").read().lower() else "no")
    row["comment"] = comment
    rows.append(row)
    print(f"{name}: {row['outcome'][:70]} ({seconds:.1f} s)")

with open("doc/stability.md", "w") as out:
    out.write("""# Stability on stiff and extreme cases

Every case of the scene specification's table, as a scene in `prm/stiff/`
(the paper scene, 32 x 32 cells, 100 steps, unless the case changes it).
This page is written by `scripts/stability_study`, which runs them all and
measures every figure below; the test suite runs each case on a small mesh
(`tests/stiff/`, and `tests/bad_input/maxwell_step_too_large` for the case
that is refused).

Columns: steps done; the largest number, over the steps, of CG iterations
(per linear solve; the implicit case sums its Newton solves), of Tresca
active-set iterations and of damage bound iterations; the range of the
damage over all nodes and steps; whether 0 <= zeta <= 1 held at every node
after every step (the recorded violation); |u|max at the last step; whether
any NaN appeared in the statistics; wall time on one core of this machine
(2 cores, Debian 12, deal.II 9.4 release build).

| case | changed parameters | outcome | steps | CG its | friction its | damage its | zeta range | bounds held | abs(u) max [m] | NaN | time [s] |
|---|---|---|---|---|---|---|---|---|---|---|---|
""")
    for r in rows:
        if r["outcome"] == "ran to the end":
            out.write(f"| {r['case']} | {r['parameters']} | {r['outcome']} | "
                      f"{r['steps']} | {r['linear']} | {r['friction']} | "
                      f"{r['damage_its']} | {r['zeta']} | {r['bounds']} | "
                      f"{r['u_max']} | {r['nan']} | {r['seconds']:.1f} |\n")
        else:
            out.write(f"| {r['case']} | {r['parameters']} | {r['outcome']} | "
                      f"0 | - | - | - | - | - | - | no | "
                      f"{r['seconds']:.1f} |\n")
    out.write("\n## The cases\n\n")
    for r in rows:
        out.write(f"* **{r['case']}**: {r['comment']}\n")
    out.write(open("doc/stability_notes.md").read())
print("wrote doc/stability.md")
