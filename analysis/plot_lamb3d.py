#!/usr/bin/python3
"""Plot the lamb3d study: the paper's Fig. 1-4 (vertical velocity at the load centre and at the
receiver against the exact half-space response, with and without deconvolution, and with the
stronger filter) and the accuracy-cost trade (error against wall time).

Usage: /usr/bin/python3 analysis/plot_lamb3d.py OUT_DIR
Reads OUT_DIR/cases.csv and OUT_DIR/<case>-probes.csv; writes OUT_DIR/lamb3d-figures.png and,
when the study has more than one spacing, OUT_DIR/lamb3d-cost.png.
"""
import csv
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def read_table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return rows


def read_probes(out_dir, case):
    path = os.path.join(out_dir, "exact.csv" if case == "exact" else f"{case}-probes.csv")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        reader = csv.reader(f)
        header = next(reader)
        columns = list(zip(*[[float(x) for x in row] for row in reader]))
    return {name: list(col) for name, col in zip(header, columns)}


def panel(ax, data, probe, title, series, fine=None):
    t = data["t [s]"]
    if fine is not None and f"{probe}_exact" in fine:
        ax.plot(fine["t [s]"], fine[f"{probe}_exact"], "k-", lw=2, label="exact (Pekeris, integrated)")
    elif f"{probe}_exact" in data:
        ax.plot(t, data[f"{probe}_exact"], "k-", lw=2, label="exact (Pekeris, integrated)")
    for column, style, label in series:
        key = f"{probe}_{column}"
        if key in data:
            ax.plot(t, data[key], style, label=label)
    ax.set(xlabel="t", ylabel="vertical velocity v_z", title=title)


def figures(out_dir, cases):
    names = [c["case"] for c in cases]
    paper = read_probes(out_dir, "paper")
    strong = read_probes(out_dir, "strong_filter") if "strong_filter" in names else None
    fine = read_probes(out_dir, "exact")
    fig, axes = plt.subplots(2, 2, figsize=(13, 9))
    axes = axes.ravel()
    panel(axes[0], paper, "centre", "Fig. 1: load centre", [("deconvolved", "C0-", "very weak SPH, deconvolved")], fine)
    panel(axes[1], paper, "receiver", "Fig. 2: receiver 2 units from the centre",
          [("deconvolved", "C0-", "very weak SPH, deconvolved"), ("raw", "C1--", "without deconvolution")], fine)
    panel(axes[2], paper, "centre", "Fig. 3: load centre, with and without deconvolution",
          [("deconvolved", "C0-", "deconvolved (eq. 35)"), ("raw", "C1--", "without deconvolution")], fine)
    if strong is not None:
        panel(axes[3], strong, "centre", "Fig. 4: load centre, stronger filter",
              [("deconvolved", "C2-", "strong filter, deconvolved"), ("raw", "C3--", "strong filter, raw")], fine)
        axes[3].plot(paper["t [s]"], paper["centre_deconvolved"], "C0:", label="paper filter, deconvolved")
    else:
        axes[3].set_visible(False)
    finish_axes([a for a in axes if a.get_visible()])
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "lamb3d-figures.png"))


def cost(out_dir, cases):
    spacing_cases = [c for c in cases if c["case"] == "paper" or c["case"].startswith("spacing_")]
    if len(spacing_cases) < 2:
        return
    spacing_cases.sort(key=lambda c: -float(c["spacing [m]"]))
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.8))
    colours = {("centre", "deconvolved"): "C0", ("centre", "raw"): "C1",
               ("receiver", "deconvolved"): "C3", ("receiver", "raw"): "C2"}
    for probe, marker in (("centre", "o"), ("receiver", "s")):
        key = f"{probe}_deconvolved_relative_l2"
        if key not in cases[0] or cases[0][key] == "":
            continue
        wall = [float(c["wall [s]"]) for c in spacing_cases]
        dx = [float(c["spacing [m]"]) for c in spacing_cases]
        for kind, style in (("deconvolved", "-"), ("raw", "--")):
            err = [float(c[f"{probe}_{kind}_relative_l2"]) for c in spacing_cases]
            colour = colours[(probe, kind)]
            axes[0].loglog(wall, err, marker + style, color=colour, label=f"{probe}, {kind}")
            axes[1].loglog(dx, err, marker + style, color=colour, label=f"{probe}, {kind}")
        for c in cases:
            if c["case"] == "free_block":
                axes[0].loglog([float(c["wall [s]"])], [float(c[key])], marker, color="k", mfc="none", ms=12,
                               label=f"{probe}, deconvolved, larger free block (no dashpots)")
    for c in spacing_cases:
        axes[0].annotate(f"dx = {float(c['spacing [m]']):g}",
                         (float(c["wall [s]"]), float(c["centre_deconvolved_relative_l2"])),
                         textcoords="offset points", xytext=(4, -12), fontsize=8)
    axes[0].set(xlabel="wall time [s] (assembly + run)", ylabel="relative L2 error of v_z, 0 <= t <= 6",
                title="accuracy against cost")
    axes[1].set(xlabel="spacing dx (h = dx)", ylabel="relative L2 error of v_z", title="convergence")
    finish_axes(axes)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "lamb3d-cost.png"))


def main(out_dir):
    table = os.path.join(out_dir, "cases.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_lamb3d: no {table}: run the lamb3d driver first")
    cases = read_table(table)
    figures(out_dir, cases)
    cost(out_dir, cases)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
