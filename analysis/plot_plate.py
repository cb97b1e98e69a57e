#!/usr/bin/python3
"""Plot the plate study (the Gray-Monaghan-Swift oscillating cantilever plate): the tip's transverse
displacement against the thin-plate motion over the first periods, the main case over the whole run,
its energy ledger, and the measured and linearised periods (modes.csv) against (dp / H)^2 with their
Richardson limits (from summary.json) and the thin-plate and Timoshenko periods.

Usage: /usr/bin/python3 analysis/plot_plate.py OUT_DIR
Reads OUT_DIR/cases.csv, OUT_DIR/<case>-tip.csv and OUT_DIR/<case>-energy.csv; writes
OUT_DIR/plate-figures.png.
"""
import json
import math
import os
import sys

from plotting import finish_axes, read_columns, read_table, save_atomically  # selects the Agg backend first

import matplotlib.pyplot as plt  # noqa: E402


def number(row, key):
    try:
        return float(row[key])
    except (KeyError, ValueError):
        return math.nan


METHOD_LABELS = {"very_weak_sph": "very weak SPH", "updated_lagrangian_sph": "UL-SPH",
                 "total_lagrangian_sph": "TL-SPH"}


def label(case):
    method = METHOD_LABELS.get(case["method"], case["method"])
    return f"{method}, H/dp = {case['H_over_dp']}, V_f = {case['V_f']}"


def first_periods(ax, out_dir, cases, thin, periods=3.0):
    """Tip displacement over the tip's thin-plate amplitude V_f c0 / omega, against t / T_thin."""
    omega = 2 * math.pi / thin
    shown = [c for c in cases if c["H_over_dp"] == cases[0]["H_over_dp"]]
    for k, case in enumerate(shown):
        tip = read_columns(os.path.join(out_dir, f"{case['case']}-tip.csv"))
        if tip is None:
            continue
        scale = number(case, "tip_start_velocity [m/s]") / omega
        t = [x / thin for x in tip["t [s]"] if x / thin <= periods]
        u = [y / scale for y in tip["u_y [m]"][: len(t)]]
        ax.plot(t, u, f"C{k}-", label=label(case))
    t = [periods * i / 600 for i in range(601)]
    ax.plot(t, [math.sin(2 * math.pi * x) for x in t], "k--", lw=1.5, label="thin plate")
    ax.set_xlabel("t / T_thin")
    ax.set_ylabel("tip u_y / (v_tip(0) / omega_thin)")
    ax.set_title("tip displacement over the first periods")


def whole_run(ax, out_dir, case):
    tip = read_columns(os.path.join(out_dir, f"{case['case']}-tip.csv"))
    if tip is None:
        return
    ax.plot(tip["t [s]"], tip["u_y [m]"], "C0-", lw=0.7, label=f"{label(case)}: u_y")
    ax.plot(tip["t [s]"], tip["u_x [m]"], "C1-", lw=0.7, label="u_x")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("tip displacement [m]")
    ax.set_title(f"{case['case']}: {number(case, 'periods_run'):.1f} periods, T = {number(case, 'period [s]'):.4f} s")


def ledger(ax, out_dir, case):
    energy = read_columns(os.path.join(out_dir, f"{case['case']}-energy.csv"))
    if energy is None or "balance [J]" not in energy:
        return
    t = energy["t [s]"]
    e0 = energy["kinetic [J]"][0] + energy["strain [J]"][0]
    for k, name in enumerate(("kinetic [J]", "strain [J]", "internal [J]", "viscous_dissipation [J]",
                              "artificial_stress_work [J]")):
        ax.plot(t, [x / e0 for x in energy[name]], f"C{k}-", lw=0.8, label=name.split(" ")[0])
    b0 = energy["balance [J]"][0]
    ax.plot(t, [(b - b0) / e0 for b in energy["balance [J]"]], "k-", lw=1.2,
            label=f"balance drift (largest {number(case, 'energy_drift'):.2g})")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("energy / E(0)")
    ax.set_title(f"{case['case']}: energy ledger")


def extrapolated_period(out_dir, key):
    """A Richardson limit the driver wrote to summary.json's figures, or None."""
    path = os.path.join(out_dir, "summary.json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        summary = json.load(f)
    value = summary.get("figures", {}).get(key)
    return value if isinstance(value, (int, float)) else None


def convergence(ax, out_dir, cases, thin, timoshenko):
    """Period against (dp / H)^2: a second-order method approaches the axis on a straight line."""
    colour = 0
    for method, prefix, marker in (("updated_lagrangian_sph", "ulsph", "o"), ("total_lagrangian_sph", "tlsph", "D")):
        sph = [c for c in cases if c["method"] == method]
        factors = sorted({c["V_f"] for c in sph}, key=float)
        first = colour
        for vf in factors:
            rows = sorted([c for c in sph if c["V_f"] == vf], key=lambda c: int(c["H_over_dp"]))
            ax.plot([int(c["H_over_dp"]) ** -2 for c in rows], [number(c, "period [s]") for c in rows],
                    f"C{colour}{marker}-",
                    label=f"{METHOD_LABELS[method]}, V_f = {vf} (H/dp = {', '.join(c['H_over_dp'] for c in rows)})")
            colour += 1 if colour != 1 else 2  # C2 is the linearised series
        limit = extrapolated_period(out_dir, f"{prefix}_extrapolated_period [s]")
        if limit is not None and sph:
            ax.plot([0], [limit], f"C{first}*", ms=12, label=f"{METHOD_LABELS[method]} Richardson limit {limit:.4f} s")
    modes_path = os.path.join(out_dir, "modes.csv")
    if os.path.exists(modes_path):
        modes = [m for m in read_table(modes_path) if math.isfinite(number(m, "first_period [s]"))]
        modes.sort(key=lambda m: int(m["H_over_dp"]))
        ax.plot([int(m["H_over_dp"]) ** -2 for m in modes], [number(m, "first_period [s]") for m in modes], "C2^-",
                label="linearised about rest (no artificial terms)")
        linear_limit = extrapolated_period(out_dir, "linearised_extrapolated_period [s]")
        if linear_limit is not None:
            ax.plot([0], [linear_limit], "C2*", ms=12, label=f"linearised Richardson limit {linear_limit:.4f} s")
    for c in cases:
        if c["method"] == "very_weak_sph":
            ax.plot([int(c["H_over_dp"]) ** -2], [number(c, "period [s]")], "ks",
                    label=f"very weak SPH, V_f = {c['V_f']}")
    ax.axhline(thin, color="k", ls="--", lw=1, label=f"thin plate {thin:.4f} s")
    ax.axhline(timoshenko, color="gray", ls=":", lw=1.5, label=f"Timoshenko {timoshenko:.4f} s")
    ax.set_xlim(left=-0.002)
    ax.set_xlabel("(dp / H)^2")
    ax.set_ylabel("period [s]")
    ax.set_title("period against resolution")


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    out_dir = sys.argv[1]
    cases = read_table(os.path.join(out_dir, "cases.csv"))
    thin = number(cases[0], "thin_period [s]")
    timoshenko = number(cases[0], "timoshenko_period [s]")
    fig, axes = plt.subplots(2, 2, figsize=(14, 9))
    first_periods(axes[0][0], out_dir, cases, thin)
    whole_run(axes[0][1], out_dir, cases[0])
    ledger(axes[1][0], out_dir, cases[0])
    convergence(axes[1][1], out_dir, cases, thin, timoshenko)
    finish_axes([axes[0][0], axes[0][1], axes[1][0], axes[1][1]])
    fig.tight_layout()
    save_atomically(fig, os.path.join(out_dir, "plate-figures.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
