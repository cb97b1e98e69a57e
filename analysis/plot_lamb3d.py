#!/usr/bin/python3
"""Plot the lamb3d (or lamb2d) study: the paper's Fig. 1-4 with the published scheme (vertical
velocity at the load centre and at the receiver against the exact half-space response, with and
without deconvolution, with the stronger filter), the scene's variant at every spacing at each
receiver, and the accuracy-cost trade of both variants (error against wall time, against spacing).
The exact responses: in 3-D Pekeris' integrated over the square on the surface and an f-k
integration below the centre; in 2-D Cagniard-de Hoop for the strip everywhere.

Usage: /usr/bin/python3 analysis/plot_lamb3d.py OUT_DIR
Reads OUT_DIR/cases.csv, OUT_DIR/<case>-probes.csv, OUT_DIR/exact.csv and the program's name from
OUT_DIR/summary.json; writes OUT_DIR/<program>-figures.png and, when there is more than one
spacing, OUT_DIR/<program>-cost.png (program = lamb3d or lamb2d).
"""
import json
import math
import os
import sys

from plotting import finish_axes, read_columns, read_table, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402

PROBES = ("centre", "receiver", "buried")
PAPER_PROBES = ("centre", "receiver")  # the paper's Fig. 1 and 2
TITLES = {"centre": "load centre", "receiver": "receiver 2 units from the centre",
          "buried": "1 unit below the load centre"}


def exact_curve(ax, fine, data, probe):
    source = fine if fine is not None and f"{probe}_exact" in fine else data
    if source is not None and f"{probe}_exact" in source:
        ax.plot(source["t [s]"], source[f"{probe}_exact"], "k-", lw=2, label="exact")


def curve(ax, data, probe, column, style, label, **kw):
    if data is not None and f"{probe}_{column}" in data:
        ax.plot(data["t [s]"], data[f"{probe}_{column}"], style, label=label, **kw)


def spacing_cases(cases, variant):
    rows = [c for c in cases if c["variant"] == variant and c["case"] not in ("strong_filter", "free_block")]
    return sorted(rows, key=lambda c: -float(c["spacing [m]"]))


def figures(out_dir, cases, program):
    fine = read_columns(os.path.join(out_dir, "exact.csv"))
    main_variant = cases[0]["variant"]
    dx0 = float(cases[0]["spacing [m]"])
    published = [c for c in spacing_cases(cases, "published") if float(c["spacing [m]"]) == dx0]
    paper = read_columns(os.path.join(out_dir, f"{published[0]['case']}-probes.csv")) if published else None
    strong = read_columns(os.path.join(out_dir, "strong_filter-probes.csv"))
    rows = (2 if paper is not None else 0) + (2 if main_variant != "published" else 0)
    fig, axes = plt.subplots(rows, 2, figsize=(13, 4.3 * rows), squeeze=False)
    used = []
    r = 0
    if paper is not None:
        for col, probe in enumerate(PAPER_PROBES):
            ax = axes[r][col]
            exact_curve(ax, fine, paper, probe)
            curve(ax, paper, probe, "reported", "C0-", "published, deconvolved")
            if probe == "receiver":
                curve(ax, paper, probe, "raw", "C1--", "published, without deconvolution")
            ax.set_title(f"Fig. {col + 1}: {TITLES[probe]} (published scheme, dx = {dx0:g})")
            used.append(ax)
        ax = axes[r + 1][0]
        exact_curve(ax, fine, paper, "centre")
        curve(ax, paper, "centre", "reported", "C0-", "deconvolved (eq. 35)")
        curve(ax, paper, "centre", "raw", "C1--", "without deconvolution")
        ax.set_title("Fig. 3: load centre, with and without deconvolution")
        used.append(ax)
        ax = axes[r + 1][1]
        if strong is not None:
            exact_curve(ax, fine, strong, "centre")
            curve(ax, strong, "centre", "reported", "C2-", "strong filter, deconvolved")
            curve(ax, strong, "centre", "raw", "C3--", "strong filter, raw")
            curve(ax, paper, "centre", "reported", "C0:", "paper filter, deconvolved")
            ax.set_title("Fig. 4: load centre, stronger filter (alpha = 0.5 per step)")
            used.append(ax)
        else:
            ax.set_visible(False)
        r += 2
    if main_variant != "published":
        axes[r + 1][1].set_visible(False)
        for i, probe in enumerate(PROBES):
            ax = axes[r + i // 2][i % 2]
            exact_curve(ax, fine, None, probe)
            for i, c in enumerate(spacing_cases(cases, main_variant)):
                data = read_columns(os.path.join(out_dir, f"{c['case']}-probes.csv"))
                curve(ax, data, probe, "reported", f"C{i}-", f"{main_variant}, dx = {float(c['spacing [m]']):g}")
            ax.set_title(f"{main_variant} variant: {TITLES[probe]}")
            used.append(ax)
    for ax in used:
        ax.set(xlabel="t", ylabel="vertical velocity (along the load)")
    finish_axes(used)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, f"{program}-figures.png"))


def cost(out_dir, cases, program):
    variants = []
    for c in cases:
        if c["variant"] not in variants:
            variants.append(c["variant"])
    if max(len(spacing_cases(cases, v)) for v in variants) < 2:
        return
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
    markers = {"centre": "o", "receiver": "s", "buried": "^"}
    for vi, variant in enumerate(variants):
        rows = spacing_cases(cases, variant)
        style = "-" if vi == 0 else "--"
        for pi, probe in enumerate(PROBES):
            key = f"{probe}_reported_relative_l2"
            if key not in rows[0] or rows[0][key] == "":
                continue
            colour = f"C{len(PROBES) * vi + pi}"
            wall = [float(c["wall [s]"]) for c in rows]
            dx = [float(c["spacing [m]"]) for c in rows]
            err = [float(c[key]) for c in rows]
            label = f"{variant}, {probe}"
            if len(rows) > 1 and err[-1] > 0 and err[-2] > 0:
                label += f" (order {math.log(err[-2] / err[-1]) / math.log(dx[-2] / dx[-1]):.2f})"
            axes[0].loglog(wall, err, markers[probe] + style, color=colour, label=label)
            axes[1].loglog(dx, err, markers[probe] + style, color=colour, label=label)
            if vi == 0:
                for c in rows:
                    axes[0].annotate(f"dx = {float(c['spacing [m]']):g}", (float(c["wall [s]"]), float(c[key])),
                                     textcoords="offset points", xytext=(4, -12), fontsize=7)
    for c in cases:
        if c["case"] == "free_block":
            for probe in PROBES:
                if c.get(f"{probe}_reported_relative_l2", "") == "":
                    continue
                axes[0].loglog([float(c["wall [s]"])], [float(c[f"{probe}_reported_relative_l2"])],
                               markers[probe], color="k", mfc="none", ms=12,
                               label=f"{c['variant']}, {probe}: larger free block, no dashpots")
    dx_all = sorted({float(c["spacing [m]"]) for c in cases})
    if len(dx_all) > 1:
        ref = [0.05 * (d / dx_all[0]) ** 2 for d in dx_all]
        axes[1].loglog(dx_all, ref, "k:", label="dx^2")
    axes[0].set(xlabel="wall time [s] (assembly + run)", ylabel="relative L2 error of the vertical velocity, 0 <= t <= 6",
                title="accuracy against cost")
    axes[1].set(xlabel="spacing dx (h = dx)", ylabel="relative L2 error of the vertical velocity", title="convergence")
    finish_axes(axes)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, f"{program}-cost.png"))


def main(out_dir):
    table = os.path.join(out_dir, "cases.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_lamb3d: no {table}: run the lamb3d or lamb2d driver first")
    cases = read_table(table)
    program = "lamb3d"
    summary = os.path.join(out_dir, "summary.json")
    if os.path.exists(summary):
        with open(summary, encoding="utf-8") as f:
            program = json.load(f).get("program", program)
    figures(out_dir, cases, program)
    cost(out_dir, cases, program)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
