#!/usr/bin/python3
"""Plot the lattice dispersion of the very weak form SPH: normalised phase speed and group speed
against k dx, one row per polarisation (P, S), one colour per variant, solid along the lattice
axis and dashed along the diagonal. One figure per smoothing length ratio h/dx.

Usage: /usr/bin/python3 analysis/plot_vwsph_dispersion.py OUT_DIR
Reads OUT_DIR/vwsph_dispersion.csv; writes OUT_DIR/vwsph_dispersion.png (the first ratio) and
OUT_DIR/vwsph_dispersion_h<ratio>.png for any further ratio.
"""
import csv
import os
import sys

from plotting import finish_axes, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"published": "tab:red", "published_row_sum": "tab:orange", "consistent": "tab:blue"}
LABELS = {"published": "published", "published_row_sum": "published, row sum corrected",
          "consistent": "consistent"}
STYLES = {"axis": "-", "diagonal": "--"}


def main(out_dir):
    table = os.path.join(out_dir, "vwsph_dispersion.csv")
    if not os.path.exists(table):
        sys.exit(f"plot_vwsph_dispersion: no {table}: run the vwsph_dispersion tool first")
    curves = {}  # ratio -> polarisation -> (variant, direction) -> [(kdx, p, g)]
    with open(table) as f:
        for r in csv.DictReader(line for line in f if not line.startswith("#")):
            curves.setdefault(r["h_over_dx"], {}).setdefault(r["polarisation"], {}).setdefault(
                (r["variant"], r["direction"]), []).append(
                (float(r["kdx"]), float(r["phase_speed"]), float(r["group_speed"])))
    for index, (ratio, polarisations) in enumerate(curves.items()):
        fig, axes = plt.subplots(len(polarisations), 2, figsize=(12, 3.8 * len(polarisations)), squeeze=False)
        for (pol, lines), (ax_p, ax_g) in zip(polarisations.items(), axes):
            for (variant, direction), data in lines.items():
                style = dict(color=COLOURS.get(variant, "k"), ls=STYLES.get(direction, ":"),
                             label=f"{LABELS.get(variant, variant)}, {direction}")
                ax_p.plot([d[0] for d in data], [d[1] for d in data], **style)
                ax_g.plot([d[0] for d in data], [d[2] for d in data], **style)
            ax_p.set_ylim(0.4, 1.3)
            ax_g.set_ylim(-0.4, 1.3)
            ax_p.set_title(f"{pol}, h/dx = {ratio}: phase speed")
            ax_g.set_title(f"{pol}, h/dx = {ratio}: group speed")
            ax_p.set_ylabel(f"omega / (k c_{pol.lower()})")
            ax_g.set_ylabel(f"(d omega / dk) / c_{pol.lower()}")
            for ax in (ax_p, ax_g):
                ax.set_xlabel("|k| dx")
                ax.set_xlim(0, 3.1416)
                ax.axhline(1, color="k", lw=0.6)
            finish_axes((ax_p, ax_g))
        fig.tight_layout()
        name = "vwsph_dispersion.png" if index == 0 else f"vwsph_dispersion_h{ratio}.png"
        save_atomically(fig, os.path.join(out_dir, name))
        plt.close(fig)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
