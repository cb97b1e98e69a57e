"""tradeoff.png: one panel per problem, error against wall time (log-log), one colour per method, that
problem's Pareto front (black staircase) and the 10 %, 3 %, 1 % and 0.1 % targets (dashed); the
problems several methods solve come first. tradeoff-memory.png: the same against peak memory, for
those shared problems. No front is drawn across problems: their errors are different norms."""
import math

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D

from ..plotting import save_atomically
from .pareto import pareto_front
from .points import SHARED_PROBLEMS
from .report import TARGETS, ok_rows

LARGEST_SHOWN = 10.0   # errors above this (blown-up runs) would squash the axis


def staircase(ax, front, x, **style):
    """Below and left of the line, no configuration of the problem is both that cheap and that accurate."""
    xs, ys = [front[0][x]], [front[0]["error"]]
    for r in front[1:]:
        xs += [r[x], r[x]]
        ys += [ys[-1], r["error"]]
    ax.plot(xs, ys, **style)


def _panel(ax, ok, inaccurate, problem, colours, x):
    mine = [r for r in ok if r["problem"] == problem]
    for r in mine:
        ax.scatter(r[x], r["error"], s=24, color=colours[r["method"]], alpha=0.8, linewidths=0)
    for r in (r for r in inaccurate if r["problem"] == problem):
        ax.scatter(r[x], r["error"], s=24, facecolors="none", edgecolors=colours[r["method"]], linewidths=1.0)
    front = pareto_front(mine, lambda r: r[x], lambda r: r["error"])
    if front:
        staircase(ax, front, x, color="black", lw=1.2, zorder=3)
    for t in TARGETS:
        ax.axhline(t, color="grey", ls="--", lw=0.7)
        ax.annotate(f"{100 * t:g} %", (1, t), xycoords=("axes fraction", "data"), ha="right", va="bottom",
                    fontsize=7, color="grey")
    ax.set_xscale("log")
    ax.set_yscale("log")
    methods = sorted({r["method"] for r in mine})
    ax.set_title(f"{problem}: {len(mine)} points, {len(methods)} method{'s' if len(methods) != 1 else ''}",
                 fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(handles=[Line2D([], [], ls="", marker="o", color=colours[m], label=m) for m in methods],
              fontsize=7, loc="best")


def _figure(rows, problems, x, xlabel, png, title):
    ok = ok_rows(rows)
    # Runs that finished with an error of 100 % or more: shown hollow, outside every front.
    inaccurate = [r for r in rows if r["status"] == "inaccurate" and math.isfinite(r["error"])
                  and r["error"] <= LARGEST_SHOWN]
    methods = sorted({r["method"] for r in ok + inaccurate})
    colours = {m: plt.get_cmap("tab10")(k % 10) for k, m in enumerate(methods)}
    columns = min(3, len(problems))
    rows_n = math.ceil(len(problems) / columns)
    fig, axes = plt.subplots(rows_n, columns, figsize=(5.2 * columns, 4.2 * rows_n), squeeze=False)
    for k, problem in enumerate(problems):
        ax = axes[k // columns][k % columns]
        _panel(ax, ok, inaccurate, problem, colours, x)
        ax.set_xlabel(xlabel, fontsize=8)
        ax.set_ylabel("relative error (the problem's own norm)", fontsize=8)
    for k in range(len(problems), rows_n * columns):
        axes[k // columns][k % columns].set_visible(False)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    save_atomically(fig, png)
    plt.close(fig)


def plot(rows, png):
    ok = ok_rows(rows)
    present = sorted({r["problem"] for r in ok})
    shared = [p for p in SHARED_PROBLEMS if p in present]
    problems = shared + [p for p in present if p not in shared]
    if not problems:
        return
    hidden = sum(1 for r in rows if r["status"] not in ("ok", "inaccurate"))
    _figure(rows, problems, "wall_s", "wall time of the driver process on one core [s]", png,
            f"Speed-accuracy trade per problem: {len(ok)} configurations (hollow: error >= 100 %)"
            + (f"; {hidden} unstable or failed, not shown" if hidden else ""))
    if shared:
        _figure(rows, shared, "peak_mib", "peak memory of the driver process [MiB]",
                png.replace(".png", "-memory.png"), "Accuracy against peak memory, problems several methods solve")
