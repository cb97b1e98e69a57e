#!/usr/bin/python3
"""Plot a run's probe time series (probes.csv) and energy ledger (energy.csv), if present.

Usage: /usr/bin/python3 analysis/plot_probes.py OUT_DIR
Writes OUT_DIR/probes.png. Column headers carry the units and become the axis labels.
"""
import csv
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header, data = rows[0], [[float(x) for x in r] for r in rows[1:] if r]
    return header, list(zip(*data))


def main(out_dir):
    probes = os.path.join(out_dir, "probes.csv")
    energy = os.path.join(out_dir, "energy.csv")
    if not os.path.exists(probes):
        sys.exit(f"plot_probes: no {probes}: the scene has no [[probe]] or the run did not finish")
    panels = 2 if os.path.exists(energy) else 1
    fig, axes = plt.subplots(1, panels, figsize=(6.5 * panels, 4.2), squeeze=False)
    header, columns = read(probes)
    for name, values in zip(header[1:], columns[1:]):
        axes[0][0].plot(columns[0], values, label=name)
    axes[0][0].set_xlabel(header[0])
    axes[0][0].set_title("probes")
    if panels == 2:
        header, columns = read(energy)
        for name, values in zip(header[1:], columns[1:]):
            axes[0][1].plot(columns[0], values, label=name)
        axes[0][1].set_xlabel(header[0])
        axes[0][1].set_title("energy")
    finish_axes(axes[0])
    fig.tight_layout()
    png = os.path.join(out_dir, "probes.png")
    save_atomically(fig, png)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
