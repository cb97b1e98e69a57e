#!/usr/bin/python3
"""The oscillating plate side by side: PySPH's own example against mfwave's `plate`, one thread each.

One command, same machine, same invocation (docs/performance.md shows its output):

    /usr/bin/python3 benchmarks/peers/plate_pysph.py --build build/release            # rates, t = 0.05 s
    /usr/bin/python3 benchmarks/peers/plate_pysph.py --build build/release --period   # and both periods

The case is Gray, Monaghan and Swift's plate (L x H = 0.2 x 0.02, E = 2e6, nu = 0.3975, rho = 1000,
V_f = 0.05) at dp = 0.002 (ten particles across), with PySPH's example settings: cubic spline,
h = 1.3 dp, Monaghan viscosity alpha = beta = 1, XSPH 0.5, artificial stress epsilon = 0.3 (n = 4),
a predictor-corrector, no kernel-gradient correction, dt = 1e-5. mfwave runs that case twice:
at PySPH's fixed dt (the same work per step: the ratio of particle-steps per second is the speed
ratio) and with its own step criteria (Courant 0.3 with the viscous term and the force criterion:
the time to solution a user gets by default). A third mfwave run is not PySPH's method: the
total-Lagrangian SPH on the same particles (docs/theory/total-lagrangian-sph.md), for its time to
solution and period beside the others. What differs and cannot be made equal:
  - the particles: PySPH's plate is a node lattice of 11 rows (edge to edge 0.02) from x = -L/4 to L,
    its first quarter held between 3 layers of wall particles above, below and behind (1,386 plate
    + 207 wall); mfwave's is cell-centred, 10 rows from x = 0 to L, clamped by 3 columns of fixed
    particles at x < 0 (1,000 + 30). Rates count the plate's particles only, each code's own.
  - the time of a run: PySPH's "Run took" (its integration loop, after code generation and set-up)
    and mfwave's run time of the case (the time loop with its observers, after set-up).
Periods: the tip's transverse displacement (PySPH: the middle particle of the last column; mfwave:
the centroid of the last column), zero crossings with 2 % hysteresis after the first half period,
the same function for both (mfwave's own analysis in lib/numerics/Oscillation.cpp does the same).

When PySPH (Debian's python3-pysph) is not installed the script says so and runs mfwave alone.
Everything runs with OMP_NUM_THREADS=1; PySPH with --no-openmp.
"""

import argparse
import csv
import importlib.util
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

THIN_PLATE_LIMIT = 0.2552  # s: the converged plane-strain continuum value the issue names (docs/performance.md)
PYSPH_DT = 1e-5
PYSPH_ROWS, PYSPH_COLUMNS_IN_PLATE = 11, 126


def one_thread_env():
    env = dict(os.environ)
    env["OMP_NUM_THREADS"] = "1"
    return env


def oscillation_period(times, values, hysteresis=0.02):
    """Mean period from zero crossings armed by |u| > hysteresis max|u| (lib/numerics/Oscillation.cpp)."""
    largest = max((abs(u) for u in values), default=0.0)
    if not largest > 0:
        return float("nan")
    threshold = hysteresis * largest
    crossings, armed, last_zero = [], 0, -1.0
    for k, u in enumerate(values):
        if k > 0:
            before = values[k - 1]
            if (before < 0 <= u) or (before > 0 >= u):
                w = before / (before - u)
                last_zero = times[k - 1] + w * (times[k] - times[k - 1])
        if abs(u) > threshold:
            side = 1 if u > 0 else -1
            if armed != 0 and side != armed and last_zero >= 0:
                crossings.append(last_zero)
            armed = side
    if len(crossings) < 2:
        return float("nan")
    return 2 * (crossings[-1] - crossings[0]) / (len(crossings) - 1)


def pysph_example():
    spec = importlib.util.find_spec("pysph")
    if spec is None or not spec.submodule_search_locations:
        return None
    path = os.path.join(list(spec.submodule_search_locations)[0], "examples", "solid_mech", "oscillating_plate.py")
    return path if os.path.exists(path) else None


def run_pysph(example, end_time, period, work):
    """Runs PySPH's example in `work`; returns a dict of its figures."""
    out = os.path.join(work, "pysph")
    command = [sys.executable, example, "--tf", str(end_time), "--no-openmp", "-d", out]
    command += ["--pfreq", "50"] if period else ["--disable-output"]
    started = time.perf_counter()
    result = subprocess.run(command, cwd=work, env=one_thread_env(), capture_output=True, text=True)
    process_wall = time.perf_counter() - started
    if result.returncode != 0:
        raise SystemExit(f"PySPH's example failed (exit {result.returncode}):\n{result.stderr[-2000:]}")
    text = result.stdout + result.stderr
    found = re.search(r"Run took:\s*([0-9.eE+-]+)", text)
    if found is None:
        raise SystemExit("PySPH's output has no 'Run took' line; its log:\n" + text[-2000:])
    run = float(found.group(1))
    steps = round(end_time / PYSPH_DT)
    plate = PYSPH_ROWS * PYSPH_COLUMNS_IN_PLATE
    figures = {"code": "PySPH", "variant": "example (dt = 1e-5)", "particles": plate, "steps": steps,
               "dt": PYSPH_DT, "run": run, "process_wall": process_wall,
               "rate": plate * steps / run, "period": float("nan")}
    if period:
        from pysph.solver.utils import get_files, iter_output
        times, values, y0 = [], [], None
        for solver_data, array in iter_output(get_files(out), "plate"):
            y = float(array.y[array.amplitude_idx[0]])
            y0 = y if y0 is None else y0
            times.append(float(solver_data["t"]))
            values.append(y - y0)
        figures["period"] = oscillation_period(times, values)
    return figures


def run_mfwave(build, end_time, fixed_step, work, label, method="updated_lagrangian_sph"):
    driver = os.path.join(build, "drivers", "plate")
    if not os.access(driver, os.X_OK):
        raise SystemExit(f"no plate driver at {driver}: build it (cmake --build {build} --target plate)")
    scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "scenes", "plate.toml")
    out = os.path.join(work, "mfwave-" + label)
    settings = ["geometry.spacing=0.002", "study.resolutions=[10]", "study.small_velocity_factor=0",
                "study.very_weak_sph=false", "study.linearised_modes=false", "study.velocity_factor=0.05",
                f"study.updated_lagrangian_sph={str(method == 'updated_lagrangian_sph').lower()}",
                f"study.total_lagrangian_sph={str(method == 'total_lagrangian_sph').lower()}",
                "method.kernel=cubic_spline", "method.smoothing_length_ratio=1.3",
                "method.kernel_gradient_correction=false", "method.viscosity_alpha=1", "method.viscosity_beta=1",
                "method.xsph=0.5", "method.artificial_stress=true", "method.artificial_stress_epsilon=0.3",
                "method.artificial_stress_exponent=4", "integrator.name=predictor_corrector",
                f"integrator.end_time={end_time}", "output.vtk=false", "output.png=false"]
    if fixed_step:
        settings.append(f"integrator.time_step={fixed_step}")
    command = [driver, "--scene", scene, "--out", out]
    for s in settings:
        command += ["--set", s]
    started = time.perf_counter()
    result = subprocess.run(command, env=one_thread_env(), capture_output=True, text=True)
    process_wall = time.perf_counter() - started
    if result.returncode != 0:
        # A run the method's guards stopped (exit 3: it blew up) is a result, not a script failure.
        print(f"mfwave's plate, {label}: exit {result.returncode}:\n{result.stderr[-1500:]}")
        return None
    with open(os.path.join(out, "cases.csv"), newline="") as f:
        case = next(csv.DictReader(f))
    particles = int(case["particles"]) - int(case["fixed_particles"])
    steps = int(case["steps"])
    run = float(case["run [s]"])
    times, values = [], []
    with open(os.path.join(out, case["case"] + "-tip.csv"), newline="") as f:
        for row in csv.DictReader(f):
            times.append(float(row["t [s]"]))
            values.append(float(row["u_y [m]"]))
    return {"code": "mfwave", "variant": label + " (" + case["case"] + ")", "particles": particles, "steps": steps,
            "dt": float(case["mean_dt [s]"]), "run": run, "process_wall": process_wall,
            "rate": particles * steps / run, "period": oscillation_period(times, values)}


def format_row(r):
    period = r["period"]
    error = "" if period != period else f"{100 * (period / THIN_PLATE_LIMIT - 1):+.1f} %"
    shown = "-" if period != period else f"{period:.4f}"
    return (f"| {r['code']} | {r['variant']} | {r['particles']:,} | {r['steps']:,} | {r['dt']:.3g} | "
            f"{r['run']:.2f} | {r['rate']:.3g} | {shown} | {error} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", default="build/release", help="mfwave build folder (with drivers/plate)")
    parser.add_argument("--end-time", type=float, default=0.05, help="simulated time of the rate runs [s]")
    parser.add_argument("--period", action="store_true",
                        help="run to 0.35 s (more than one period) and report both periods: about 10 minutes")
    parser.add_argument("--out", default="out/peers/plate", help="folder for peers.csv")
    parser.add_argument("--without-pysph", action="store_true", help="run mfwave's side only (the script's own test)")
    args = parser.parse_args()
    end_time = 0.35 if args.period else args.end_time
    if not end_time > 0:
        raise SystemExit("--end-time: must be positive")

    rows = []
    with tempfile.TemporaryDirectory(prefix="mfwave-peers-") as work:
        example = None if args.without_pysph else pysph_example()
        if args.without_pysph:
            print("--without-pysph: PySPH's side is skipped.")
        elif example is None:
            print("PySPH is not installed (Debian: apt-get install python3-pysph): its side is skipped.")
        else:
            shutil.copy(example, work)
            # The first run generates and compiles PySPH's Cython code (cached under ~/.pysph);
            # "Run took" excludes it, and a warm-up run keeps the compiler off the measured run.
            run_pysph(os.path.join(work, os.path.basename(example)), 2 * PYSPH_DT, False, work)
            rows.append(run_pysph(os.path.join(work, os.path.basename(example)), end_time, args.period, work))
        same_dt = run_mfwave(args.build, end_time, PYSPH_DT, work, "at PySPH's dt = 1e-5")
        own = run_mfwave(args.build, end_time, 0, work, "own step criteria")
        rows += [r for r in (same_dt, own) if r is not None]
        # Not PySPH's method: the total-Lagrangian SPH on mfwave's particles (corrected reference
        # kernels, no artificial terms, central differences), for the time to solution and period.
        total = run_mfwave(args.build, end_time, 0, work, "total-Lagrangian SPH", "total_lagrangian_sph")
        rows += [total] if total is not None else []

    print(f"\nOscillating plate, dp = 0.002 (10 across), V_f = 0.05, to t = {end_time} s, one thread each")
    print("| code | run | plate particles | steps | dt [s] | run [s] | particle-steps/s | period [s] | vs 0.2552 s |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(format_row(r))
    pysph = rows[0] if rows and rows[0]["code"] == "PySPH" else None
    if pysph is not None and same_dt is not None:
        print(f"\nspeed ratio (particle-steps/s, same dt): {same_dt['rate'] / pysph['rate']:.1f} x")
    per_particle = lambda r: r["run"] / r["particles"]  # noqa: E731 - time to solution per particle
    for r in (own, total):
        if pysph is not None and r is not None:
            print(f"time to solution per particle, {r['variant']}: {per_particle(pysph) / per_particle(r):.1f} x"
                  f" faster than PySPH (steps of {r['dt']:.3g} s against {PYSPH_DT:g} s)")

    os.makedirs(args.out, exist_ok=True)
    target = os.path.join(args.out, "peers.csv")
    fields = ["code", "variant", "particles", "steps", "dt", "run", "process_wall", "rate", "period"]
    with tempfile.NamedTemporaryFile("w", dir=args.out, delete=False, newline="", suffix=".tmp") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    os.replace(f.name, target)
    print(f"\nwritten: {target}")


if __name__ == "__main__":
    main()
