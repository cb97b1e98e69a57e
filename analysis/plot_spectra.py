#!/usr/bin/python3
"""Plot the FFT dispersion spectra of the spectra tool.

Top row: phase speed over c against |k| dx in 2-D for P and S, one colour per method, solid along
the lattice axis and dashed along the diagonal (the published very weak SPH is left out where it
has no real frequency). Bottom left: points per wavelength for a 1 % phase error per method and
dimension (axis, P). Bottom right: the simulated spectral peaks (markers) on the symbol with the
integrator's relation (lines) and on the symbol alone (thin), in omega dx / c_p.

Usage: /usr/bin/python3 analysis/plot_spectra.py OUT_DIR
Reads OUT_DIR/spectra.csv, accuracy.csv, simulation.csv; writes OUT_DIR/spectra.png.
"""
import math
import os
import sys

from plotting import finish_axes, read_table, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402

COLOURS = {"finite_difference": "black", "vwsph_published": "tab:red", "vwsph_consistent": "tab:blue",
           "vwsph_galerkin": "tab:cyan",
           "rkcm": "tab:green", "rbcm": "tab:olive", "ulsph": "tab:orange", "ulsph_corrected": "tab:purple"}
STYLES = {"axis": "-", "diagonal": "--"}


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def main(out_dir):
    paths = {name: os.path.join(out_dir, name + ".csv") for name in ("spectra", "accuracy", "simulation")}
    for path in paths.values():
        if not os.path.exists(path):
            sys.exit(f"plot_spectra: no {path}: run the spectra tool first")
    spectra, accuracy, simulation = (read_table(paths[n]) for n in ("spectra", "accuracy", "simulation"))

    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    for column, polarisation in enumerate(("P", "S")):
        ax = axes[0][column]
        curves = {}
        for r in spectra:
            if r["dimension"] == "2" and r["polarisation"] == polarisation:
                curves.setdefault((r["method"], r["direction"]), []).append(
                    (number(r["kdx"]), number(r["phase_speed"])))
        for (method, direction), points in curves.items():
            xs = [p[0] for p in points if math.isfinite(p[1])]
            ys = [p[1] for p in points if math.isfinite(p[1])]
            if method == "vwsph_published" or not xs:
                continue  # no real frequency over most of the band (docs/studies/vwsph-dispersion.md)
            ax.plot(xs, ys, STYLES[direction], color=COLOURS.get(method, "grey"),
                    label=method if direction == "axis" else None)
        ax.axhline(1, color="grey", lw=0.5)
        ax.set_xlim(0, math.pi * math.sqrt(2))
        ax.set_ylim(0.4, 1.3)
        ax.set_xlabel("|k| dx")
        ax.set_ylabel(f"phase speed / c ({polarisation})")
        ax.set_title(f"2-D, {polarisation} waves (solid: axis, dashed: diagonal)")
        finish_axes([ax])

    ax = axes[1][0]
    methods = [m for m in COLOURS if any(r["method"] == m for r in accuracy)]
    width = 0.25
    for i, dimension in enumerate(("1", "2", "3")):
        values = []
        for m in methods:
            rows = [r for r in accuracy if r["method"] == m and r["dimension"] == dimension
                    and r["direction"] == "axis" and r["polarisation"] == "P"]
            values.append(number(rows[0]["ppw"]) if rows else None)
        xs = [j + (i - 1) * width for j in range(len(methods))]
        bars = [v if v is not None and math.isfinite(v) else 0 for v in values]
        ax.bar(xs, bars, width, label=f"{dimension}-D")
        for x, v in zip(xs, values):
            if v is None or not math.isfinite(v):
                ax.text(x, 1, "not run" if v is None else "never", rotation=90, ha="center", va="bottom", fontsize=7)
    ax.set_xticks(range(len(methods)))
    ax.set_xticklabels(methods, rotation=25, ha="right", fontsize=8)
    ax.set_ylabel("points per wavelength for 1 % (axis, P)")
    ax.set_title("resolution needed for a 1 % phase error")
    finish_axes([ax])

    ax = axes[1][1]
    shown = set()
    for r in simulation:
        if r["direction"] != "axis" or r["polarisation"] != "P":
            continue
        method = r["method"]
        colour = COLOURS.get(method, "grey")
        k = number(r["kdx"])
        ax.plot(k, number(r["omega_measured"]), "o", ms=3, color=colour,
                label=method if method not in shown else None)
        shown.add(method)
    by_method = {}
    for r in simulation:
        if r["direction"] == "axis" and r["polarisation"] == "P":
            by_method.setdefault(r["method"], []).append(
                (number(r["kdx"]), number(r["omega_expected"]), number(r["omega_symbol"])))
    for method, rows in by_method.items():
        rows.sort()
        ax.plot([x[0] for x in rows], [x[1] for x in rows], "-", lw=1, color=COLOURS.get(method, "grey"))
        ax.plot([x[0] for x in rows], [x[2] for x in rows], ":", lw=0.8, color=COLOURS.get(method, "grey"))
    ax.set_xlabel("|k| dx")
    ax.set_ylabel("omega dx / c_p (dx = c_p = 1)")
    ax.set_title("2-D runs, axis, P: peaks o, symbol + integrator -, symbol :")
    finish_axes([ax])

    fig.tight_layout()
    png = os.path.join(out_dir, "spectra.png")
    save_atomically(fig, png)
    print(f"plot_spectra: wrote {png}")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
