#!/usr/bin/python3
"""Plot the bar1d study: the profiles u(x, T), v(x, T) of the coarsest and finest runs against the
exact solution, and the convergence of the relative L2 errors in h.

Usage: /usr/bin/python3 analysis/plot_bar1d.py OUT_DIR
Reads OUT_DIR/convergence.csv and OUT_DIR/nodes-N-profile.csv; writes OUT_DIR/bar1d.png.
"""
import csv
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def main(out_dir):
    table = os.path.join(out_dir, "convergence.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_bar1d: no {table}: run the bar1d driver first")
    _, rows = read(table)
    nodes = [int(r[0]) for r in rows]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    for n, style in ((nodes[0], "-"), (nodes[-1], "--")):
        _, prof = read(os.path.join(out_dir, f"nodes-{n}-profile.csv"))
        x = [p[0] for p in prof]
        axes[0].plot(x, [p[1] for p in prof], style, label=f"RKCM, Ns = {n}")
        axes[1].plot(x, [p[3] for p in prof], style, label=f"RKCM, Ns = {n}")
    axes[0].plot(x, [p[2] for p in prof], "k:", label="exact")
    axes[1].plot(x, [p[4] for p in prof], "k:", label="exact")
    axes[0].set(xlabel="x [m]", ylabel="u(x, T) [m]", title="displacement at the end time")
    axes[1].set(xlabel="x [m]", ylabel="v(x, T) [m/s]", title="velocity at the end time")
    h = [r[1] for r in rows]
    axes[2].loglog(h, [r[5] for r in rows], "o-", label="relative L2 error of u")
    axes[2].loglog(h, [r[7] for r in rows], "s-", label="relative L2 error of v")
    axes[2].loglog(h, [rows[-1][5] * (hh / h[-1]) for hh in h], "k:", label="h^1")
    axes[2].loglog(h, [rows[-1][7] * (hh / h[-1]) ** (1 / 3) for hh in h], "k--", label="h^(1/3)")
    axes[2].set(xlabel="h [m]", ylabel="relative L2 error at T", title="convergence")
    finish_axes(axes)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "bar1d.png"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
