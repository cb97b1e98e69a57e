"""tradeoff.txt: which configuration is cheapest for 10 %, 1 % and 0.1 % error, from the CSV rows."""
from collections import Counter

from .pareto import cheapest_per_target, pareto_front

TARGETS = (0.1, 0.01, 0.001)


def cost(row):
    return row["wall_s"]


def error(row):
    return row["error"]


def ok_rows(rows):
    return [r for r in rows if r["status"] == "ok"]


def describe(row):
    parts = [row["problem"], row["method"], row["resolution"]]
    if row["kernel"] != "-":
        parts.append(f"{row['kernel']} (support {row['support_ratio']})")
    parts += [row["integrator"], f"dt fraction {row['dt_fraction']:g}"]
    return "  ".join(parts)


def _target_lines(rows, indent):
    lines = []
    for target, best in cheapest_per_target(rows, TARGETS, cost, error):
        label = f"<= {100 * target:g} %"
        if best is None:
            lines.append(f"{indent}{label:>9}: none of these configurations reached it")
        else:
            lines.append(f"{indent}{label:>9}: {best['wall_s']:.3g} s, {best['peak_mib']:.0f} MiB, error "
                         f"{best['error']:.2e}: {describe(best)}")
    return lines


def report_text(rows):
    ok = ok_rows(rows)
    others = Counter(r["status"] for r in rows if r["status"] != "ok")
    lines = [f"Speed-accuracy sweep: {len(rows)} points, {len(ok)} ok"
             + "".join(f", {n} {status}" for status, n in sorted(others.items()))
             + f"; {sum(r['wall_s'] for r in rows):.0f} s of driver wall time in all.",
             "Cost: wall time of one driver process on one core (OMP_NUM_THREADS=1). Error: each problem's",
             "own relative error against its exact solution (error_measure in tradeoff.csv), so errors of",
             "different problems are comparable only as orders of magnitude. Starting a driver costs 5 to",
             "30 ms depending on the machine, so among the smallest runs such differences are noise.",
             "",
             "Cheapest configuration reaching each target, over all problems:"]
    lines += _target_lines(ok, "  ")
    lines += ["", "Per problem:"]
    for problem in sorted({r["problem"] for r in ok}):
        mine = [r for r in ok if r["problem"] == problem]
        lines.append(f"  {problem} ({mine[0]['error_measure']}):")
        lines += _target_lines(mine, "    ")
    front = pareto_front(ok, cost, error)
    lines += ["", f"Pareto front over all problems ({len(front)} points, cheapest first):"]
    lines += [f"  {r['wall_s']:9.3g} s  {r['error']:.2e}  {describe(r)}" for r in front]
    failed = [r for r in rows if r["status"] != "ok"]
    if failed:
        lines += ["", "Points without a usable error (kept in the CSV with their status and exit code):"]
        lines += [f"  {r['status']} (exit {r['exit_code']:g}): {r['config_id']}" for r in failed]
    return "\n".join(lines) + "\n"
