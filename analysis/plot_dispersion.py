#!/usr/bin/python3
"""Plot the dispersion study like Luo-Liu-Huang Fig. 2: normalised phase speed and group speed
against kh, one line per support size, one row per method / basis order.

Usage: /usr/bin/python3 analysis/plot_dispersion.py OUT_DIR
Reads OUT_DIR/dispersion.csv; writes OUT_DIR/dispersion.png.
"""
import csv
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def main(out_dir):
    table = os.path.join(out_dir, "dispersion.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_dispersion: no {table}: run the dispersion tool first")
    curves = {}
    with open(table) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            group = "RKCM m = " + r["order"] if r["method"] == "rkcm" else "RBCM (IMQ)"
            curves.setdefault(group, {}).setdefault(r["ratio"], []).append(
                (float(r["kh"]), float(r["phase_speed"]), float(r["group_speed"])))
    fig, axes = plt.subplots(len(curves), 2, figsize=(12, 3.6 * len(curves)), squeeze=False)
    for (group, lines), (ax_p, ax_g) in zip(curves.items(), axes):
        ratio_name = "a_r/h" if group.startswith("RBCM") else "a/h"
        for ratio, data in lines.items():
            ax_p.plot([d[0] for d in data], [d[1] for d in data], label=f"{ratio_name} = {ratio}")
            ax_g.plot([d[0] for d in data], [d[2] for d in data], label=f"{ratio_name} = {ratio}")
        ax_p.set_ylim(0, 1.6)
        ax_g.set_ylim(-1.5, 2)
        ax_p.set_title(f"{group}: phase speed")
        ax_g.set_title(f"{group}: group speed")
        ax_p.set_ylabel("c_phase / c")
        ax_g.set_ylabel("c_group / c")
        for ax in (ax_p, ax_g):
            ax.set_xlabel("kh")
            ax.axhline(1, color="k", lw=0.6)
        finish_axes((ax_p, ax_g))
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "dispersion.png"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
