"""tradeoff.txt: per problem, which configuration is cheapest for 10 %, 3 %, 1 % and 0.1 % error (at the
worst receiver and, for the Lamb problems, at each receiver), with its wall time and peak memory, and
the problem's Pareto front. Errors of different problems are different norms, so nothing is ranked
across problems."""
import math
from collections import Counter

from .pareto import cheapest_per_target, pareto_front
from .points import SHARED_PROBLEMS

TARGETS = (0.1, 0.03, 0.01, 0.001)


def cost(row):
    return row["wall_s"]


def error(row):
    return row["error"]


def ok_rows(rows):
    return [r for r in rows if r["status"] == "ok"]


def receiver_errors(row):
    """{receiver: relative L2} for drivers that score several receivers; {} otherwise."""
    found = {}
    for item in (row.get("receiver_errors") or "").split(";"):
        name, _, value = item.partition("=")
        try:
            found[name] = float(value)
        except ValueError:
            continue
    return found


def describe(row):
    parts = [row["problem"], row["method"], row["resolution"]]
    if row["kernel"] != "-":
        parts.append(f"{row['kernel']} (support {row['support_ratio']})")
    parts += [row["integrator"], f"dt fraction {row['dt_fraction']:g}"]
    return "  ".join(parts)


def _target_lines(rows, indent, error_of=error):
    lines = []
    for target, best in cheapest_per_target(rows, TARGETS, cost, error_of):
        label = f"<= {100 * target:g} %"
        if best is None:
            lines.append(f"{indent}{label:>9}: none of these configurations reached it")
        else:
            lines.append(f"{indent}{label:>9}: {best['wall_s']:.3g} s, {best['peak_mib']:.0f} MiB, error "
                         f"{error_of(best):.2e}: {describe(best)}")
    return lines


def _problem_lines(problem, mine):
    methods = sorted({r["method"] for r in mine})
    lines = [f"  {problem} ({mine[0]['error_measure']}); {len(mine)} points, methods: {', '.join(methods)}"]
    lines += _target_lines(mine, "    ")
    receivers = sorted({name for r in mine for name in receiver_errors(r)})
    for name in receivers:
        lines.append(f"    at the probe '{name}' alone:")
        lines += _target_lines(mine, "      ", lambda r, n=name: receiver_errors(r).get(n, math.nan))
    front = pareto_front(mine, cost, error)
    lines.append(f"    Pareto front ({len(front)} points, cheapest first):")
    lines += [f"      {r['wall_s']:9.3g} s  {r['peak_mib']:6.0f} MiB  {r['error']:.2e}  {describe(r)}" for r in front]
    return lines


def report_text(rows):
    ok = ok_rows(rows)
    others = Counter(r["status"] for r in rows if r["status"] != "ok")
    lines = [f"Speed-accuracy sweep: {len(rows)} points, {len(ok)} ok"
             + "".join(f", {n} {status}" for status, n in sorted(others.items()))
             + f"; {sum(r['wall_s'] for r in rows):.0f} s of driver wall time in all.",
             "Cost: wall time and peak memory of one driver process on one core (OMP_NUM_THREADS=1).",
             "Error: each problem's own relative error against its exact solution (error_measure in",
             "tradeoff.csv); different problems use different norms, so configurations are compared within",
             "a problem only. Starting a driver costs 5 to 30 ms depending on the machine, so among the",
             "smallest runs such differences are noise."]
    problems = sorted({r["problem"] for r in ok})
    shared = [p for p in SHARED_PROBLEMS if p in problems]
    single = [p for p in problems if p not in shared]
    if shared:
        lines += ["", "Problems several methods solve (the cheapest configuration per target answers which method):"]
        for problem in shared:
            lines += _problem_lines(problem, [r for r in ok if r["problem"] == problem])
    if single:
        lines += ["", "Problems one method solves (its settings against each other):"]
        for problem in single:
            lines += _problem_lines(problem, [r for r in ok if r["problem"] == problem])
    failed = [r for r in rows if r["status"] != "ok"]
    if failed:
        lines += ["", "Points without a usable error (kept in the CSV with their status and exit code):"]
        lines += [f"  {r['status']} (exit {r['exit_code']:g}): {r['config_id']}" for r in failed]
    return "\n".join(lines) + "\n"
