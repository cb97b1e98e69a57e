#!/usr/bin/python3
"""Plot the wave1d study: error against dx and against wall time, one line per integrator.

Usage: /usr/bin/python3 analysis/plot_wave1d.py OUT_DIR
Reads OUT_DIR/convergence.csv and the finest-resolution probe CSVs; writes OUT_DIR/wave1d.png.
"""
import csv
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def main(out_dir):
    table = os.path.join(out_dir, "convergence.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_wave1d: no {table}: run the wave1d driver first")
    rows = {}
    with open(table) as f:
        for r in csv.DictReader(f):
            rows.setdefault(r["integrator"], []).append(r)

    fig, (ax_dx, ax_cost, ax_probe) = plt.subplots(1, 3, figsize=(15, 4.5))
    for name, series in rows.items():
        dx = [float(r["dx [m]"]) for r in series]
        err = [float(r["relative_l2_error"]) for r in series]
        wall = [max(float(r["wall_time [s]"]), 1e-6) for r in series]
        ax_dx.loglog(dx, err, "o-", label=name)
        ax_cost.loglog(wall, err, "o-", label=name)
        probe = os.path.join(out_dir, f"{name}-{series[-1]['cells']}-probe.csv")
        if os.path.exists(probe):
            with open(probe) as f:
                reader = csv.reader(f)
                header = next(reader)
                data = [(float(a), float(b)) for a, b in reader]
            ax_probe.plot([d[0] for d in data], [d[1] for d in data], label=name)
            ax_probe.set_ylabel(header[1])
            ax_probe.set_xlabel(header[0])
    dx_all = sorted({float(r["dx [m]"]) for s in rows.values() for r in s})
    if dx_all:
        first = list(rows.values())[0]
        e0 = float(first[-1]["relative_l2_error"])
        d0 = float(first[-1]["dx [m]"])
        ax_dx.loglog(dx_all, [e0 * (d / d0) ** 2 for d in dx_all], "k--", lw=0.8, label="slope 2")
    ax_dx.set_xlabel("dx [m]")
    ax_dx.set_ylabel("relative L2 error at the end time")
    ax_dx.set_title("convergence at fixed CFL")
    ax_cost.set_xlabel("wall time [s]")
    ax_cost.set_title("error against cost")
    ax_probe.set_title("displacement at the quarter point (finest run)")
    finish_axes((ax_dx, ax_cost, ax_probe))
    fig.tight_layout()
    png = os.path.join(out_dir, "wave1d.png")
    save_atomically(fig, png)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
