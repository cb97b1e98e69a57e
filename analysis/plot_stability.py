#!/usr/bin/python3
"""Plot the stability study: c*dt_crit against support size, ours (von Neumann, eigenvalues,
bisection) beside the published Luo-Liu-Huang Tables 1 and 2 (read as c*dt).

Usage: /usr/bin/python3 analysis/plot_stability.py OUT_DIR
Reads OUT_DIR/stability.csv; writes OUT_DIR/stability.png.
"""
import csv
import math
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def value(text):
    x = float(text)
    return math.nan if x == 0 else x  # 0 marks "unconditionally unstable"


def main(out_dir):
    table = os.path.join(out_dir, "stability.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_stability: no {table}: run the stability tool first")
    with open(table) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for ax, method, label in zip(axes, ("rkcm", "rbcm"), ("a / h (RK support radius)", "a_r / h (IMQ shape)")):
        sel = [r for r in rows if r["method"] == method]
        x = [float(r["ratio"]) for r in sel]
        for key, style, name in (("von_neumann_c_dt", "o-", "von Neumann (ours)"),
                                 ("eigen_c_dt", "s-", "eigenvalues, constrained bar (ours)"),
                                 ("bisection_c_dt", "x--", "bisection on runs (ours)"),
                                 ("published_predicted_c_dt", "^:", "published predicted"),
                                 ("published_numerical_c_dt", "v:", "published numerical")):
            ax.plot(x, [value(r[key]) for r in sel], style, label=name)
        for r in sel:
            if float(r["eigen_c_dt"]) == 0:
                ax.annotate("unstable\n(complex pair)", (float(r["ratio"]), 0.2), ha="center", fontsize=8)
        ax.set_xlabel(label)
        ax.set_ylabel("c * dt_crit [m]")
        ax.set_title(method.upper())
    finish_axes(axes)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "stability.png"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
