"""tradeoff.png: error against wall time, log-log, one colour per method and one marker per problem;
the Pareto front over all points (black staircase), each problem's own front (grey, dotted) and the
10 %, 1 %, 0.1 % targets (dashed)."""
import math

import matplotlib.pyplot as plt
from matplotlib.lines import Line2D

from ..plotting import save_atomically
from .pareto import pareto_front
from .report import TARGETS, cost, error, ok_rows

MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*"]
LARGEST_SHOWN = 10.0   # errors above this (blown-up runs) would squash the axis


def staircase(ax, front, **style):
    """Below and left of the line, no configuration of the sweep is both that cheap and that accurate."""
    xs, ys = [front[0]["wall_s"]], [front[0]["error"]]
    for r in front[1:]:
        xs += [r["wall_s"], r["wall_s"]]
        ys += [ys[-1], r["error"]]
    ax.plot(xs, ys, **style)


def plot(rows, png):
    ok = ok_rows(rows)
    # Runs that finished with an error of 100 % or more: shown hollow, outside every front.
    inaccurate = [r for r in rows if r["status"] == "inaccurate" and math.isfinite(r["error"])
                  and r["error"] <= LARGEST_SHOWN]
    shown = ok + inaccurate
    methods = sorted({r["method"] for r in shown})
    problems = sorted({r["problem"] for r in shown})
    colours = {m: plt.get_cmap("tab10")(k % 10) for k, m in enumerate(methods)}
    markers = {p: MARKERS[k % len(MARKERS)] for k, p in enumerate(problems)}

    fig, ax = plt.subplots(figsize=(11.5, 6.5))
    for r in ok:
        ax.scatter(r["wall_s"], r["error"], s=26, color=colours[r["method"]], marker=markers[r["problem"]],
                   alpha=0.75, linewidths=0)
    for r in inaccurate:
        ax.scatter(r["wall_s"], r["error"], s=26, facecolors="none", edgecolors=colours[r["method"]],
                   marker=markers[r["problem"]], linewidths=1.0)
    for problem in problems:
        front = pareto_front([r for r in ok if r["problem"] == problem], cost, error)
        if len(front) > 1:
            staircase(ax, front, color="grey", lw=0.9, ls=":", zorder=2)
    front = pareto_front(ok, cost, error)
    if front:
        staircase(ax, front, color="black", lw=1.4, zorder=3)
        ax.scatter([r["wall_s"] for r in front], [r["error"] for r in front], s=70, facecolors="none",
                   edgecolors="black", lw=1.0, zorder=4)
    for t in TARGETS:
        ax.axhline(t, color="grey", ls="--", lw=0.8)
        ax.annotate(f"{100 * t:g} %", (1, t), xycoords=("axes fraction", "data"), ha="right", va="bottom",
                    fontsize=8, color="grey")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of the driver process on one core [s]")
    ax.set_ylabel("relative error against the exact solution (each problem's own norm)")
    hidden = len(rows) - len(shown)
    ax.set_title(f"Speed-accuracy trade: {len(ok)} configurations, {len(inaccurate)} with error >= 100 % (hollow)"
                 + (f"; {hidden} unstable or blown up, not shown" if hidden else ""), fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    handles = [Line2D([], [], ls="", marker="o", color=colours[m], label=m) for m in methods]
    handles += [Line2D([], [], ls="", marker=markers[p], color="dimgrey", label=p) for p in problems]
    handles.append(Line2D([], [], color="black", marker="o", mfc="none", label="Pareto front, all points"))
    handles.append(Line2D([], [], color="grey", ls=":", label="Pareto front of each problem"))
    ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save_atomically(fig, png)
    plt.close(fig)
