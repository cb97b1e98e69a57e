#!/usr/bin/python3
"""Plot the bar1d-sph study: stress and velocity profiles at the end time of the coarsest and finest
cases against the exact solution (two bars meeting at +-v0), and the convergence of the L1 errors in dx.

Usage: /usr/bin/python3 analysis/plot_bar1d_sph.py OUT_DIR
Reads OUT_DIR/cases.csv and OUT_DIR/profile-<dx>.csv; writes OUT_DIR/bar1d-sph.png.
"""
import csv
import math
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def profile_name(dx_text):
    # The driver writes the spacing with C++'s default stream format (6 significant digits).
    return f"profile-{float(dx_text):.6g}.csv"


def main(out_dir):
    table = os.path.join(out_dir, "cases.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_bar1d_sph: no {table}: run the bar1d-sph driver first")
    _, rows = read(table)
    dx = [float(r[0]) for r in rows]
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.2))
    picks = [0, len(rows) - 1] if len(rows) > 1 else [0]
    for k, style in zip(picks, ("-", "--")):
        _, prof = read(os.path.join(out_dir, profile_name(rows[k][0])))
        x = [float(p[0]) for p in prof]
        axes[0].plot(x, [float(p[3]) for p in prof], style, label=f"SPH, dx = {dx[k]:g}")
        axes[1].plot(x, [float(p[1]) for p in prof], style, label=f"SPH, dx = {dx[k]:g}")
    axes[0].plot(x, [float(p[4]) for p in prof], "k:", label="exact")
    axes[1].plot(x, [float(p[2]) for p in prof], "k:", label="exact")
    axes[0].set(xlabel="x [m]", ylabel="sigma_xx(x, T) [Pa]", title="stress at the end time")
    axes[1].set(xlabel="x [m]", ylabel="v(x, T) [m/s]", title="velocity at the end time")
    axes[2].loglog(dx, [float(r[4]) for r in rows], "o-", label="relative L1 error of v")
    axes[2].loglog(dx, [float(r[6]) for r in rows], "s-", label="relative L1 error of sigma")
    ref = [float(rows[-1][6]) * d / dx[-1] for d in dx]
    axes[2].loglog(dx, ref, "k:", label="slope 1")
    axes[2].set(xlabel="dx [m]", ylabel="relative L1 error", title="convergence in dx")
    finish_axes(axes)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "bar1d-sph.png"))
    if any(math.isnan(float(r[5])) for r in rows[1:]):
        print("note: an order is NaN (a case failed to converge?)")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
