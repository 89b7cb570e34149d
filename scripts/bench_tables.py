"""The tables of doc/performance.md that set runs side by side: the program
against the peer at each size, and the growth of the time per step with
the mesh; written by bench_report.py from the rows of scripts/bench."""
import math

from bench_report import damage, fmt, name, order, pair, ratio, short


def memory_ratio(mine, peer):
    """Peak resident set over the ranks, vpcontact / peer, and in brackets
    the same of the private memory where both runs have it."""
    if not (mine and peer):
        return "–"
    text = fmt(ratio(mine["mem_all_mb"], peer["mem_all_mb"]))
    if "" not in (mine.get("mem_private_mb", ""),
                  peer.get("mem_private_mb", "")):
        text += (" (private "
                 f"{fmt(ratio(mine['mem_private_mb'], peer['mem_private_mb']))})")
    return text


def ratio_table(best, sizes, algebras):
    lines = ["| cells | vpcontact back-end | best serial: vpcontact / peer | "
             "AMG 1 rank / peer GAMG 1 rank | AMG 2 ranks / peer GAMG 2 "
             "ranks | peak memory, AMG 1 rank: vpcontact / peer | peak "
             "memory, AMG 2 ranks: vpcontact / peer | vpcontact AMG "
             "speed-up 1 → 2 ranks | its damage solves 1 → 2 ranks | peer "
             "GAMG speed-up 1 → 2 ranks |", "|" + "---|" * 10]
    peer = "DOLFINx/PETSc"
    for size in sizes:
        def get(code, algebra, solver, ranks):
            return best.get((size, (code, algebra, solver, ranks)))
        serial_peer = [r for (s, k), r in best.items()
                       if s == size and k[0] == "peer" and k[3] == 1]
        best_peer = min(serial_peer, key=lambda r: r["total_s"], default=None)
        g1, g2 = get("peer", peer, "gamg", 1), get("peer", peer, "gamg", 2)
        # The best serial runs need the direct paths of both programs
        # (a run of part of the configurations may lack them).
        direct = {k[0] for (s, k), _ in best.items() if s == size and
                  k[3] == 1 and k[2] in ("Cholesky", "MUMPS", "lu")}
        for algebra in algebras:
            serial = [r for (s, k), r in best.items() if s == size and
                      k[0] == "vpcontact" and k[1] == algebra and k[3] == 1]
            if not serial:
                continue
            fastest = min(serial, key=lambda r: r["total_s"])
            a1 = get("vpcontact", algebra, "CG with AMG", 1)
            a2 = get("vpcontact", algebra, "CG with AMG", 2)
            memory = [memory_ratio(a, g) for a, g in ((a1, g1), (a2, g2))]
            best_serial = (f"{pair(fastest, best_peer)}: {short(fastest)} / "
                           f"{short(best_peer)}"
                           if best_peer and direct == {"vpcontact", "peer"}
                           else "–")
            lines.append(
                f"| {size}² | {algebra} | {best_serial} | "
                f"{pair(a1, g1)} | {pair(a2, g2)} | {memory[0]} | {memory[1]}"
                f" | {pair(a1, a2)} | "
                f"{fmt(ratio(damage(a1), damage(a2))) if a1 and a2 else '–'}"
                f" | {pair(g1, g2)} |")
    return lines


def growth_table(best, sizes):
    """Time per step growth per 4x unknowns, (t_b / t_a)^(ln 4 / ln(n_b /
    n_a)): 4 where the cost grows like the unknowns."""
    pairs = list(zip(sizes, sizes[1:]))
    if len(sizes) > 2:
        pairs.append((sizes[0], sizes[-1]))
    lines = ["| run | ranks | " + " | ".join(
        f"{a}² → {b}²" for a, b in pairs) + " |",
        "|---|---|" + "---|" * len(pairs)]
    any_run = {k: r for (_, k), r in best.items()}
    keys = sorted(any_run, key=lambda k: (order(any_run[k]), k[3]))
    for k in keys:
        cells = []
        for a, b in pairs:
            ra, rb = best.get((a, k)), best.get((b, k))
            cells.append(fmt((rb["per_step_ms"] / ra["per_step_ms"]) ** (
                math.log(4) / math.log(rb["dofs"] / ra["dofs"])))
                if ra and rb else "–")
        lines.append(f"| {name(any_run[k])} | {k[3]} | " + " | ".join(cells)
                     + " |")
    return lines
