"""Long runs of the 3-D Lamb problem: does each very weak SPH variant stay bounded after the pulse
has left the block? (issue 15, docs/theory/very-weak-sph.md "Why the 3-D runs grow").

Runs build/release/drivers/lamb3d for every configuration below at each spacing to END_TIME with
stability.allow_growth = true (the energy guard records growth instead of stopping), then fits the
growth rate of each run's energy envelope and plots |v_z| at the load centre against time.

    /usr/bin/python3 analysis/lamb3d_long_runs.py OUT_DIR [--spacings 0.5,0.25] [--end-time 300]
        [--lamb3d build/release/drivers/lamb3d] [--only NAME,...]

Writes OUT_DIR/growth_rates.csv (one row per run and case), OUT_DIR/long_runs.png and one output
folder per run. A 50x long run of the study (t = 300) at dx = 0.25 takes about a minute per
configuration on one core; dx = 0.125 about ten.
"""
import argparse
import json
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import finish_axes, read_columns, save_atomically  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCENE = os.path.join(ROOT, "data", "scenes", "lamb3d.toml")

# name -> --set overrides on the shipped scene (the Galerkin variant, no filter). "free faces" runs
# the same block with every face free and no dashpots (the study's free_block case on the scene's
# own box).
OWN_BOX_FREE = ["study.free_block_lower=[-3.5,-3.5,-7.0]", "study.free_block_upper=[3.5,3.5,0.0]"]
CONFIGURATIONS = {
    "galerkin": OWN_BOX_FREE,
    "consistent_filtered": ["method.variant=consistent", "method.smoothing_rate=0.5"],
    "consistent_unfiltered": ["method.variant=consistent", "method.smoothing_rate=0"] + OWN_BOX_FREE,
    "published_paper_filter": ["method.variant=published", "method.smoothing_rate=0.77", "method.smoothing_order=1",
                               "method.smoothing_rate_scales_with_spacing=false"],
    "published_unfiltered": ["method.variant=published", "method.smoothing_rate=0"],
}


def scene_without_free_block(out_dir):
    """The shipped scene without its free_block keys (a --set can change a key, not remove it), so
    only the configurations that ask for a free-faces case run one."""
    path = os.path.join(out_dir, "lamb3d-without-free-block.toml")
    with open(SCENE) as f:
        kept = [line for line in f if not line.lstrip().startswith("free_block_")]
    with open(path + ".tmp", "w") as f:
        f.writelines(kept)
    os.replace(path + ".tmp", path)
    return path


def run(lamb3d, scene, name, sets, dx, end_time, out_dir):
    folder = os.path.join(out_dir, f"{name}_{dx}")
    argv = [lamb3d, "--quiet", "--threads", "1", "--scene", scene, "--out", folder,
            "--set", f"study.spacings=[{dx}]", "--set", f"geometry.spacing={dx}",
            "--set", "study.compare_published=false", "--set", "study.strong_smoothing_rate=0",
            "--set", "output.vtk=false", "--set", "output.png=false", "--set", "output.probe_every=1",
            "--set", f"integrator.end_time={end_time}", "--set", "stability.allow_growth=true"]
    for s in sets:
        argv += ["--set", s]
    print(f"running {name} at dx = {dx} to t = {end_time}", flush=True)
    result = subprocess.run(argv, capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    if result.returncode != 0:
        sys.exit(f"{name} at dx = {dx} failed (exit {result.returncode}):\n{result.stderr}")
    return folder


def envelope_rate(times, energy, window):
    """Growth rate of the amplitude (half the energy's rate) over the last 40 % of the run, from the
    envelope max E over `window` seconds, and the final envelope over the largest energy."""
    env = []
    for k, t in enumerate(times):
        env.append(max(e for s, e in zip(times[:k + 1], energy[:k + 1]) if s >= t - window))
    peak = max(energy)
    start = times[-1] - 0.4 * (times[-1] - times[0])
    points = [(t, math.log(max(e, 1e-300))) for t, e in zip(times, env) if t >= start]
    n = len(points)
    mt = sum(t for t, _ in points) / n
    ml = sum(v for _, v in points) / n
    slope = sum((t - mt) * (v - ml) for t, v in points) / sum((t - mt) ** 2 for t, _ in points)
    return 0.5 * slope, env[-1] / peak


def tail_spectrum(times, velocity, omega_max):
    """What is left after the pulse: over the last two thirds of the run, the dominant angular
    frequency of the centre velocity over omega_max (2 / the stable step), the fraction of its power
    below 0.3 omega_max (waves resolved by at least about 7 points per wavelength), and the largest
    |v| of that resolved part over the last tenth of the run (an FFT low pass of the whole trace)."""
    import numpy as np
    t, v = np.asarray(times), np.asarray(velocity)
    dt = t[1] - t[0]
    late = t > t[-1] / 3
    spectrum = np.abs(np.fft.rfft(v[late] * np.hanning(late.sum()))) ** 2
    omega = 2 * np.pi * np.fft.rfftfreq(late.sum(), dt)
    dominant = omega[np.argmax(spectrum)] / omega_max
    resolved = spectrum[omega < 0.3 * omega_max].sum() / max(spectrum.sum(), 1e-300)
    # zero-phase low pass: a Hann-windowed sinc reaching 20 / cutoff either side, evaluated only where
    # it does not overhang the end of the trace
    cutoff = 0.3 * omega_max
    half = int(math.ceil(20 / (cutoff * dt)))
    k = np.arange(-half, half + 1) * dt
    taps = cutoff / np.pi * np.sinc(cutoff * k / np.pi) * np.hanning(2 * half + 1) * dt
    low = np.convolve(v, taps / taps.sum(), mode="same")
    low[len(v) - half:] = 0
    return dominant, resolved, np.abs(low[(t > 0.9 * t[-1])]).max()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("out_dir")
    parser.add_argument("--spacings", default="0.5,0.25")
    parser.add_argument("--end-time", type=float, default=300)
    parser.add_argument("--lamb3d", default=os.path.join(ROOT, "build", "release", "drivers", "lamb3d"))
    parser.add_argument("--only", default="", help="comma-separated configuration names")
    args = parser.parse_args()
    spacings = [float(s) for s in args.spacings.split(",")]
    names = [n for n in CONFIGURATIONS if not args.only or n in args.only.split(",")]
    os.makedirs(args.out_dir, exist_ok=True)

    scene = scene_without_free_block(args.out_dir)
    rows, curves = [], {}
    for dx in spacings:
        for name in names:
            folder = run(args.lamb3d, scene, name, CONFIGURATIONS[name], dx, args.end_time, args.out_dir)
            for case in sorted(f[:-len("-energy.csv")] for f in os.listdir(folder) if f.endswith("-energy.csv")):
                label = f"{name} (free faces)" if case == "free_block" else name
                e = read_columns(os.path.join(folder, f"{case}-energy.csv"))
                energy = [k + abs(s) for k, s in zip(e["kinetic [J]"], e["strain [J]"])]
                rate, final = envelope_rate(e["t [s]"], energy, 14.0)
                p = read_columns(os.path.join(folder, f"{case}-probes.csv"))
                v = p["centre_raw"]
                peak = max(abs(x) for x in v)
                last = max(abs(x) for s, x in zip(p["t [s]"], v) if s > 0.9 * p["t [s]"][-1]) / peak
                with open(os.path.join(folder, "summary.json")) as f:
                    omega_max = 2 / json.load(f)["figures"][f"{case}_stable_step_estimate"]
                dominant, resolved, low = tail_spectrum(p["t [s]"], v, omega_max)
                rows.append((label, dx, rate, final, last, dominant, resolved, low / peak))
                curves[(label, dx)] = (p["t [s]"], [abs(x) for x in v])
                print(f"  {label:36s} dx = {dx:<6} amplitude growth rate {rate:+.4f} /s, "
                      f"final energy / peak {final:.3g}, final |v| / peak {last:.3g} "
                      f"(dominant {dominant:.2f} omega_max, {resolved:.2g} of the power below 0.3 omega_max, "
                      f"resolved part {low / peak:.3g} of the peak)", flush=True)

    table = os.path.join(args.out_dir, "growth_rates.csv")
    with open(table + ".tmp", "w") as f:
        f.write("configuration,spacing [m],amplitude_growth_rate [1/s],final_energy_over_peak,"
                "final_velocity_over_peak,tail_dominant_omega_over_max,tail_power_below_0.3_omega_max,"
                "final_resolved_velocity_over_peak\n")
        for row in rows:
            f.write(",".join([row[0], str(row[1])] + [f"{x:.6g}" for x in row[2:]]) + "\n")
    os.replace(table + ".tmp", table)
    print(f"wrote {table}")

    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(spacings), figsize=(6.5 * len(spacings), 4.5), squeeze=False)
    for ax, dx in zip(axes[0], spacings):
        for (label, d), (t, v) in curves.items():
            if d == dx:
                ax.semilogy(t, [max(x, 1e-30) for x in v], lw=1, label=label)
        ax.set_title(f"3-D Lamb, dx = {dx}: |v_z| at the load centre")
        ax.set_xlabel("t [s]")
        ax.set_ylim(1e-20, 1e3)
    finish_axes(axes[0])
    fig.tight_layout()
    save_atomically(fig, os.path.join(args.out_dir, "long_runs.png"))


if __name__ == "__main__":
    main()
