#!/usr/bin/python3
"""Figures of a solid-study run (drivers/solid, docs/studies/geometry.md):

    /usr/bin/python3 analysis/plot_solid.py OUT [--compare OTHER_OUT]

- solid-traces.png: each probe's trace of every case at the finest spacing against the exact one
  (when the scene has a reference);
- solid-errors.png: the relative L2 error of each probe against the spacing, cut cells, staircase
  and RK collocation's nodes, whichever ran (and, with --compare, the other run's, e.g. the
  axis-aligned half-plane);
- solid-record.png: a record section, every probe's trace of the finest cut case (else RK) against its
  distance from the first probe, with the P, S and Rayleigh moveout of the scene's [material] from
  the first load's position.
"""
import argparse
import math
import os
import sys
import tomllib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import read_columns, read_table, save_atomically  # noqa: E402

import matplotlib.pyplot as plt  # noqa: E402


def cases_of(folder):
    return read_table(os.path.join(folder, "cases.csv"))


# The cases' kinds (cases.csv's method and cells columns), their labels and line styles: the very weak
# SPH's cut cells and staircase, RK collocation's nodes, the UL- and TL-SPH's fill.
# (method, cells, label, error-plot marker, trace line)
KINDS = (("very_weak_sph", "cut", "cut cells", "o-", "-"), ("very_weak_sph", "staircase", "staircase", "s:", ":"),
         ("reproducing_kernel", "nodes", "RK collocation", "^-.", "-."),
         ("updated_lagrangian_sph", "fill", "UL-SPH", "v--", "--"), ("total_lagrangian_sph", "fill", "TL-SPH", "d-", "-"))


def of_kind(cases, kind):
    method, cells = kind[0], kind[1]
    return [c for c in cases if c.get("method", "very_weak_sph") == method and c["cells"] == cells]


def finest(cases, kind):
    chosen = of_kind(cases, kind)
    return min(chosen, key=lambda c: float(c["spacing [m]"])) if chosen else None


def probes_of(folder):
    """The scene, and every probe (the [[probe]] entries and the receivers of [[probe_line]]) with its
    position, from the run's receivers.csv."""
    with open(os.path.join(folder, "scene.resolved.toml"), "rb") as f:
        scene = tomllib.load(f)
    receivers = os.path.join(folder, "receivers.csv")
    if not os.path.exists(receivers):
        return scene, scene.get("probe", [])
    probes = []
    for row in read_table(receivers):
        position = [float(v) for k, v in row.items() if k.startswith("x")]
        probes.append({"name": row["name"], "position": position})
    return scene, probes


def traces(folder, cases, probes):
    probes = probes[:6]  # the first few: a record section shows the rest
    has_exact = any(k.endswith("_exact") for k in read_columns(os.path.join(folder, cases[0]["case"] + "-probes.csv")))
    if not has_exact:
        return
    fig, axes = plt.subplots(len(probes), 1, figsize=(7, 2.4 * len(probes)), sharex=True)
    axes = axes if len(probes) > 1 else [axes]
    drawn_exact = False
    for kind in KINDS:
        style = kind[4]
        case = finest(cases, kind)
        if not case:
            continue
        series = read_columns(os.path.join(folder, case["case"] + "-probes.csv"))
        for ax, probe in zip(axes, probes):
            ax.plot(series["t [s]"], series[probe["name"]], style, label=case["case"])
            if not drawn_exact:
                ax.plot(series["t [s]"], series[probe["name"] + "_exact"], "k--", lw=0.8, label="exact")
        drawn_exact = True
    for ax, probe in zip(axes, probes):
        ax.set_ylabel(probe["name"] + " [m/s]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    axes[-1].set_xlabel("t [s]")
    fig.tight_layout()
    save_atomically(fig, os.path.join(folder, "solid-traces.png"))
    plt.close(fig)


def errors(folder, cases, probes, compare):
    if not any(k.endswith("_relative_l2") for k in cases[0]):
        return
    fig, axes = plt.subplots(1, len(probes), figsize=(3.4 * len(probes), 3.2), sharey=True)
    axes = axes if len(probes) > 1 else [axes]
    runs = [(folder, "")] + ([(compare, " (" + os.path.basename(os.path.normpath(compare)) + ")")] if compare else [])
    for run, suffix in runs:
        rows = cases_of(run)
        for kind in KINDS:
            chosen = sorted(of_kind(rows, kind), key=lambda c: float(c["spacing [m]"]))
            if not chosen:
                continue
            label, marker = kind[2], kind[3]
            for ax, probe in zip(axes, probes):
                key = probe["name"] + "_relative_l2"
                ax.loglog([float(c["spacing [m]"]) for c in chosen], [float(c[key]) for c in chosen], marker,
                          label=label + suffix)
    for ax, probe in zip(axes, probes):
        ax.set_title(probe["name"])
        ax.set_xlabel("dx [m]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    axes[0].set_ylabel("relative L2 error")
    fig.tight_layout()
    save_atomically(fig, os.path.join(folder, "solid-errors.png"))
    plt.close(fig)


def record(folder, cases, scene, probes):
    case = next((finest(cases, kind) for kind in KINDS if finest(cases, kind)), cases[0])
    series = read_columns(os.path.join(folder, case["case"] + "-probes.csv"))
    if len(probes) < 2:
        return
    origin = probes[0]["position"]
    distance = [math.dist(p["position"], origin) for p in probes]
    span = max(distance) - min(distance)
    peak = max(max(abs(v) for v in series[p["name"]]) for p in probes) or 1.0
    gain = 0.8 * span / max(len(probes) - 1, 1) / peak
    fig, ax = plt.subplots(figsize=(7, 5))
    t = series["t [s]"]
    for p, d in zip(probes, distance):
        ax.plot(t, [d + gain * v for v in series[p["name"]]], "k", lw=0.7)
        exact = series.get(p["name"] + "_exact")
        if exact:
            ax.plot(t, [d + gain * v for v in exact], "r--", lw=0.5)
    loads = scene.get("load", [])
    material = scene.get("material", {})
    if loads and material:
        source = loads[0].get("position", loads[0].get("centre"))
        history = loads[0].get("time_function", {})
        start = history.get("delay", history.get("start", 0.0))  # the Ricker's peak, a pulse's start
        lam, mu, rho = material["lambda"], material["mu"], material["density"]
        speeds = {"P": math.sqrt((lam + 2 * mu) / rho), "S": math.sqrt(mu / rho)}
        nu = lam / (2 * (lam + mu))
        speeds["R"] = speeds["S"] * (0.862 + 1.14 * nu) / (1 + nu)
        for name, c in speeds.items():
            offsets = [math.dist(p["position"], source) for p in probes]
            ax.plot([start + o / c for o in offsets], distance, ":", lw=1, label=name + " moveout")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("distance from " + probes[0]["name"] + " [m]")
    ax.set_title("record section, " + case["case"])
    ax.legend(fontsize=7)
    fig.tight_layout()
    save_atomically(fig, os.path.join(folder, "solid-record.png"))
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("folder")
    parser.add_argument("--compare", help="another solid run's folder drawn beside on the error plot")
    args = parser.parse_args()
    cases = cases_of(args.folder)
    scene, probes = probes_of(args.folder)
    traces(args.folder, cases, probes)
    errors(args.folder, cases, probes, args.compare)
    record(args.folder, cases, scene, probes)


if __name__ == "__main__":
    main()
