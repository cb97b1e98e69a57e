#!/usr/bin/python3
"""Plot the stability atlas (analysis/stability_atlas.cpp, docs/studies/stability-atlas.md).

atlas.png: one row per dimension. Left: the SPH methods (very weak SPH published, consistent,
Galerkin; updated-Lagrangian SPH plain and corrected), one row per method and kernel, one column
per h / dx. Right: RK collocation (one row per basis order, one column per a / dx) and, in 1-D,
RB collocation (a_r / dx). The colour is the central-difference step limit as a Courant number
c_p dt / dx; a cell with growing modes (omega^2 < 0 somewhere) is black and says "grow", a support
the method cannot build is grey. The number in a cell is the Courant number.
ppw.png: the same layout, coloured by the worst points per wavelength for the atlas' phase error
(P and S, axis and diagonal); white: the error is never that small.
poisson.png: c_s dt / dx at the central-difference limit (left) and the S-wave points per
wavelength (right) against Poisson's ratio, per method, in 2-D (solid) and 3-D (dashed).
jitter.png: irregular clouds, one column per dimension. Top: the growth measure
max(-omega^2_min / omega^2_max, |Im omega^2| / |omega^2|_max), worst over the seeds, against the jitter
(points at 1e-12 are stable; the dotted line is the tolerance); bottom: the quadratic-field residual.
One line per method and support.

Usage: /usr/bin/python3 analysis/plot_stability_atlas.py OUT_DIR
"""
import math
import os
import sys

from plotting import read_table, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SPH = ["vwsph_published", "vwsph_consistent", "vwsph_galerkin", "ulsph", "ulsph_corrected"]
SHORT = {"vwsph_published": "vw-pub", "vwsph_consistent": "vw-con", "vwsph_galerkin": "vw-gal",
         "ulsph": "ul", "ulsph_corrected": "ul-cor", "rkcm": "RK", "rbcm": "RB"}
COLOURS = {"finite_difference": "black", "vwsph_published": "tab:red", "vwsph_consistent": "tab:blue",
           "vwsph_galerkin": "tab:cyan", "rkcm": "tab:green", "rbcm": "tab:olive", "ulsph": "tab:orange",
           "ulsph_corrected": "tab:purple"}


def number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def grid(rows, keys, knob_values, field):
    """Matrix of `field` over (row key, knob value), plus the status of each cell."""
    values = np.full((len(keys), len(knob_values)), math.nan)
    status = np.full((len(keys), len(knob_values)), "", dtype=object)
    for r in rows:
        key = (r["method"], r["family"])
        if key not in keys:
            continue
        i, j = keys.index(key), knob_values.index(number(r["value"]))
        values[i, j] = number(r[field])
        status[i, j] = r["status"].split(":")[0]
    return values, status


def heat(ax, rows, keys, labels, field, title, cmap, vmin, vmax, fmt):
    knob_values = sorted({number(r["value"]) for r in rows if (r["method"], r["family"]) in keys})
    if not keys or not knob_values:
        ax.set_visible(False)
        return None
    values, status = grid(rows, keys, knob_values, field)
    shown = np.where(status == "ok", values, math.nan)
    image = ax.imshow(shown, cmap=cmap, vmin=vmin, vmax=vmax, aspect="auto")
    for i in range(len(keys)):
        for j in range(len(knob_values)):
            if status[i, j] == "growing":
                ax.add_patch(plt.Rectangle((j - 0.5, i - 0.5), 1, 1, color="black"))
                ax.text(j, i, "grow", ha="center", va="center", color="white", fontsize=6)
            elif status[i, j] != "ok":
                ax.add_patch(plt.Rectangle((j - 0.5, i - 0.5), 1, 1, color="0.8"))
            elif not math.isnan(values[i, j]):
                ax.text(j, i, fmt(values[i, j]), ha="center", va="center", fontsize=6)
    ax.set_xticks(range(len(knob_values)))
    ax.set_xticklabels([f"{v:g}" for v in knob_values], fontsize=7)
    ax.set_yticks(range(len(keys)))
    ax.set_yticklabels(labels, fontsize=7)
    ax.set_title(title, fontsize=9)
    return image


def layout(atlas, field, name, cmap, vmin, vmax, fmt, colour_label, out_dir):
    dims = sorted({int(r["dimension"]) for r in atlas})
    fig, axes = plt.subplots(len(dims), 2, figsize=(14, 4.2 * len(dims)), squeeze=False,
                             gridspec_kw={"width_ratios": [2.2, 1]})
    image = None
    for row, d in enumerate(dims):
        rows = [r for r in atlas if int(r["dimension"]) == d]
        fd = [r for r in rows if r["method"] == "finite_difference"]
        sph_keys = sorted({(r["method"], r["family"]) for r in rows if r["method"] in SPH},
                          key=lambda k: (SPH.index(k[0]), k[1]))
        extra = f"; finite difference: {fmt(number(fd[0][field]))}" if fd else ""
        im = heat(axes[row][0], rows, sph_keys, [f"{SHORT[m]} {f}" for m, f in sph_keys], field,
                  f"{d}-D SPH: h / dx{extra}", cmap, vmin, vmax, fmt)
        image = image or im
        col_keys = sorted({(r["method"], r["family"]) for r in rows if r["method"] in ("rkcm", "rbcm")})
        im = heat(axes[row][1], rows, col_keys, [f"{SHORT[m]} {f}" for m, f in col_keys], field,
                  f"{d}-D collocation: a / dx (RK), a_r / dx (RB)", cmap, vmin, vmax, fmt)
        image = image or im
    if image is not None:
        fig.colorbar(image, ax=axes, shrink=0.6, label=colour_label)
    save_atomically(fig, os.path.join(out_dir, name))


def poisson_plot(poisson, out_dir):
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for d, style in ((2, "-"), (3, "--")):
        rows = [r for r in poisson if int(r["dimension"]) == d and r["status"] == "ok"]
        for method in COLOURS:
            mine = [r for r in rows if r["method"] == method]
            if not mine:
                continue
            nu = [number(r["poisson"]) for r in mine]
            label = f"{method} {d}-D"
            axes[0].plot(nu, [number(r["cs_courant"]) for r in mine], style, marker="o", color=COLOURS[method],
                         label=label)
            axes[1].plot(nu, [number(r["ppw_s_axis"]) for r in mine], style, marker="o", color=COLOURS[method],
                         label=label)
    axes[0].set_yscale("log")
    axes[0].set_ylabel("c_s dt / dx at the central-difference limit")
    axes[1].set_ylabel("S-wave points per wavelength (axis)")
    for ax in axes:
        ax.set_xlabel("Poisson's ratio")
        ax.grid(True, which="both", alpha=0.3)
    axes[1].legend(fontsize=6, ncol=2)
    save_atomically(fig, os.path.join(out_dir, "poisson.png"))


def jitter_plot(jitter, out_dir):
    dims = sorted({int(r["dimension"]) for r in jitter})
    if not dims:
        return
    fig, axes = plt.subplots(2, len(dims), figsize=(5 * len(dims), 8), squeeze=False)
    styles = ["-", "--", ":"]
    for col, d in enumerate(dims):
        rows = [r for r in jitter if int(r["dimension"]) == d and r["status"] in ("ok", "growing")]
        for method in COLOURS:
            supports = sorted({number(r["value"]) for r in rows if r["method"] == method})
            for k, value in enumerate(supports):
                mine = [r for r in rows if r["method"] == method and number(r["value"]) == value]
                fractions = sorted({number(r["jitter"]) for r in mine})
                growth, residual = [], []
                for f in fractions:
                    at = [r for r in mine if number(r["jitter"]) == f]
                    growth.append(max(max(-number(r["omega2_min_over_max"]), number(r["imaginary_ratio"]), 1e-12)
                                      for r in at))
                    residual.append(max(max(number(r["quadratic_residual"]), 1e-16) for r in at))
                label = f"{SHORT.get(method, method)} {mine[0]['knob']}={value:g}"
                style = styles[k % len(styles)]
                axes[0][col].plot(fractions, growth, style, marker="o", color=COLOURS[method], label=label)
                axes[1][col].plot(fractions, residual, style, marker="o", color=COLOURS[method], label=label)
        axes[0][col].axhline(1e-9, color="grey", linestyle=":", linewidth=1)
        axes[0][col].set_title(f"{d}-D")
        axes[0][col].set_ylabel("growth: max(-omega2_min, |Im omega2|) / omega2_max")
        axes[1][col].set_ylabel("quadratic residual / c_p^2")
        for row in (0, 1):
            axes[row][col].set_yscale("log")
            axes[row][col].set_xlabel("jitter / dx")
            axes[row][col].grid(True, which="both", alpha=0.3)
    legend = {}  # every method and support of every panel, once
    for ax in axes[0]:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            legend.setdefault(label, handle)
    fig.legend(list(legend.values()), list(legend.keys()), loc="lower center", ncol=6, fontsize=7)
    fig.subplots_adjust(bottom=0.16, hspace=0.3, wspace=0.35)
    save_atomically(fig, os.path.join(out_dir, "jitter.png"))


def main(out_dir):
    paths = {n: os.path.join(out_dir, n + ".csv") for n in ("atlas", "poisson")}
    for path in paths.values():
        if not os.path.exists(path):
            sys.exit(f"plot_stability_atlas: no {path}: run the stability_atlas tool first")
    atlas = read_table(paths["atlas"])
    layout(atlas, "cd_courant", "atlas.png", "viridis", 0, 2, lambda v: f"{v:.2f}",
           "central-difference limit c_p dt / dx", out_dir)
    layout(atlas, "ppw_worst", "ppw.png", "magma_r", 4, 40, lambda v: f"{v:.0f}",
           "points per wavelength, worst line (1 % phase error)", out_dir)
    poisson_plot(read_table(paths["poisson"]), out_dir)
    jitter_path = os.path.join(out_dir, "jitter.csv")
    if os.path.exists(jitter_path):
        jitter_plot(read_table(jitter_path), out_dir)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
