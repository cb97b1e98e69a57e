#!/usr/bin/python3
"""Plot the rings study (two colliding rubber rings by updated-Lagrangian SPH, with and without the
artificial stress): a montage of the particles at the snapshot times, coloured by the fragment they
belong to (two colours = two intact rings), and the energy budget with the rings' rebound and the
zero-energy-mode indicators.

Usage: /usr/bin/python3 analysis/plot_rings.py OUT_DIR
Reads OUT_DIR/cases.csv and, per case, <case>-positions.csv, <case>-energy.csv, <case>-rings.csv;
writes OUT_DIR/rings-montage.png and OUT_DIR/rings-energy.png.
"""
import os
import sys

from plotting import finish_axes, read_columns, read_table, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402

RING_COLOURS = ("tab:blue", "tab:orange")
STRAY_COLOURS = ("tab:red", "tab:green", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan", "black")


def snapshots(path):
    """{time: (x, y, fragment)} in time order."""
    found = {}
    for row in read_table(path):
        t = float(row["t [s]"])
        x, y, f = found.setdefault(t, ([], [], []))
        x.append(float(row["x [m]"]))
        y.append(float(row["y [m]"]))
        f.append(int(row["fragment"]))
    return dict(sorted(found.items()))


def colour(fragment):
    if fragment < 2:
        return RING_COLOURS[fragment]
    return STRAY_COLOURS[(fragment - 2) % len(STRAY_COLOURS)]


def montage(out_dir, cases):
    data = [snapshots(os.path.join(out_dir, f"{c['case']}-positions.csv")) for c in cases]
    columns = max(len(d) for d in data)
    xs = [x for d in data for (px, _, _) in d.values() for x in px]
    ys = [y for d in data for (_, py, _) in d.values() for y in py]
    pad = 0.05 * (max(xs) - min(xs))
    fig, axes = plt.subplots(len(cases), columns, figsize=(2.6 * columns, 2.0 * len(cases) + 0.6), squeeze=False)
    for row, (case, snaps) in enumerate(zip(cases, data)):
        size = max(0.3, 4e-6 / float(case["spacing [m]"]) ** 2 * 0.0025)
        for col, (t, (x, y, f)) in enumerate(snaps.items()):
            ax = axes[row][col]
            ax.scatter(x, y, s=size, c=[colour(k) for k in f], linewidths=0)
            pieces = max(f) + 1
            ax.set_title(f"t = {t * 1e6:.0f} us, {pieces} piece{'s' if pieces != 1 else ''}", fontsize=8)
            ax.set_xlim(min(xs) - pad, max(xs) + pad)
            ax.set_ylim(min(ys) - pad, max(ys) + pad)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
        for col in range(len(snaps), columns):
            axes[row][col].axis("off")
        axes[row][0].set_ylabel(case["case"].replace("_", " "), fontsize=9)
    link = cases[0].get("link_distance [dp]", "1.5")
    fig.suptitle(f"Colliding rings: particles coloured by connected fragment (particles closer than {link} dp joined); "
                 "blue + orange only = both rings intact", fontsize=9)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "rings-montage.png"))
    plt.close(fig)


def energy(out_dir, cases):
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    budget, rebound, zigzag, spacing = axes[0][0], axes[0][1], axes[1][0], axes[1][1]
    styles = ("-", "--", ":", "-.")
    for k, case in enumerate(cases):
        name = case["case"]
        style = styles[k % len(styles)]
        e = read_columns(os.path.join(out_dir, f"{name}-energy.csv"))
        r = read_columns(os.path.join(out_dir, f"{name}-rings.csv"))
        label = name.replace("_", " ")
        if e is not None:
            t = [s * 1e6 for s in e["t [s]"]]
            e0 = e["kinetic [J]"][0] + e["strain [J]"][0]
            for column, c in (("kinetic [J]", "tab:blue"), ("strain [J]", "tab:orange"), ("internal [J]", "tab:green"),
                              ("viscous_dissipation [J]", "tab:red"), ("artificial_stress_work [J]", "tab:purple"),
                              ("balance [J]", "black")):
                budget.plot(t, [v / e0 for v in e[column]], style, color=c,
                            label=f"{column.split(' ')[0].replace('_', ' ')} ({label})")
            zigzag.semilogy(t, [max(z, 1e-12) for z in e["zigzag [-]"]], style, label=label)
            spacing.plot(t, e["min_spacing_ratio [-]"], style, label=label)
        if r is not None:
            t = [s * 1e6 for s in r["t [s]"]]
            v0 = r["vx_left [m/s]"][0]
            rebound.plot(t, [v / v0 for v in r["vx_left [m/s]"]], style, color="tab:blue", label=f"left ring ({label})")
            rebound.plot(t, [-v / v0 for v in r["vx_right [m/s]"]], style, color="tab:orange",
                         label=f"right ring ({label})")
    budget.set_title("energy budget / initial kinetic + strain energy")
    rebound.set_title("centre-of-mass velocity towards the other ring / initial")
    zigzag.set_title("zig-zag indicator")
    spacing.set_title("smallest pair distance / dp")
    for ax in axes.flat:
        ax.set_xlabel("t [us]")
    rebound.axhline(0, color="grey", lw=0.5)
    finish_axes(axes.flat)
    budget.legend(fontsize=6, ncol=2)
    rebound.legend(fontsize=7)
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "rings-energy.png"))
    plt.close(fig)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    cases = read_table(os.path.join(out_dir, "cases.csv"))
    montage(out_dir, cases)
    energy(out_dir, cases)


if __name__ == "__main__":
    main()
