#!/usr/bin/python3
"""Every shipped scene through the one program (issue 47): `mfwave check` validates it, `mfwave plan
--json` predicts it, and `mfwave run` runs it (shortened), each with exit 0; bad input exits 2 naming
the key; `mfwave methods --json` lists the catalogue.

    /usr/bin/python3 tests/tools/mfwave_scenes_test.py --mfwave BUILD/drivers/mfwave --scenes data/scenes

A scene added to data/scenes without an entry in QUICK fails the test: every shipped scene must run.
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

# The shortened run of each shipped scene: a short end time or the study's smallest cases (the
# figures of the full runs are the studies' own tests and pages).
QUICK = {
    "lamb3d.toml": ["--set", "study.compare_published=false", "--set", "integrator.end_time=1",
                    "--set", "study.error_window=1", "--set", "output.vtk=false"],
    "lamb3d_quarter.toml": ["--set", "study.compare_published=false", "--set", "integrator.end_time=1",
                            "--set", "study.error_window=1", "--set", "output.vtk=false"],
    "lamb2d_inclined.toml": ["--set", "study.spacings=[0.25]", "--set", "integrator.end_time=1",
                             "--set", "study.error_window=1"],
    "lamb2d_halfplane.toml": ["--set", "study.spacings=[0.25]", "--set", "integrator.end_time=1",
                              "--set", "study.error_window=1"],
    "layered_cavity.toml": ["--set", "geometry.spacing=0.25", "--set", "integrator.end_time=1",
                            "--set", "output.png=false", "--set", "output.vtk=false"],
    "lamb2d.toml": ["--set", "study.compare_published=false", "--set", "integrator.end_time=1",
                    "--set", "study.error_window=1", "--set", "output.vtk=false"],
    "block-ricker.toml": ["--set", "integrator.end_time=0.1", "--set", "output.png=false", "--set", "output.vtk=false"],
    "wave1d.toml": ["--set", "study.cells=[32, 64]"],
    "bar1d.toml": ["--set", "study.nodes=[21, 41]"],
    "plane2d.toml": ["--set", "study.cells=[8, 12]"],
    "bar1d-sph.toml": ["--set", "study.spacings=[0.02]", "--set", "geometry.spacing=0.02"],
    "plate.toml": ["--set", "geometry.spacing=0.006666666666666667", "--set", "integrator.end_time=0.2",
                   "--set", "study.resolutions=[3]", "--set", "study.convergence_end_time=0.1",
                   "--set", "output.png=false", "--set", "output.vtk=false"],
    "rings.toml": ["--set", "geometry.spacing=0.002", "--set", "method.smoothing_length_ratio=1.3",
                   "--set", "integrator.end_time=2e-5", "--set", "output.png=false", "--set", "output.vtk=false"],
    "planewave.toml": ["--set", "study.cells=16"],
    "spectra.toml": ["--set", "study.dimensions=[1]", "--set", "study.cells_1d=64", "--set", "simulation.cells=16",
                     "--set", "simulation.steps=256"],
    "stability-atlas.toml": ["--set", "study.dimensions=[1]", "--set", 'study.kernels=["cubic_spline"]',
                             "--set", "study.smoothing_length_ratios=[1.3]", "--set", 'study.ulsph_kernels=["cubic_spline"]',
                             "--set", "study.ulsph_smoothing_length_ratios=[1.3]", "--set", "study.rk_orders=[2]",
                             "--set", "study.rk_support_ratios=[2.5]", "--set", "study.rb_shape_ratios=[3.0]",
                             "--set", "study.poisson_ratios=[0.25]", "--set", "jitter.dimensions=[1]"],
    "collocation-dispersion.toml": [],
    "collocation-stability.toml": [],
}

PLAN_KEYS = ["particles", "memory_bytes", "stable_step", "steps", "wall_seconds", "phase_error"]


def run(command):
    env = dict(os.environ)
    env.pop("DISPLAY", None)
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env)
    return done.returncode, done.stdout


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--mfwave", required=True)
    parser.add_argument("--scenes", required=True)
    parser.add_argument("--only", default="")
    args = parser.parse_args()
    failures = []

    code, out = run([args.mfwave, "methods", "--json"])
    methods = json.loads(out) if code == 0 else []
    names = [m["name"] for m in methods]
    if code != 0 or len(names) != 7 or len(set(names)) != 7:
        failures.append(f"mfwave methods --json: exit {code}, names {names}")

    scenes = sorted(glob.glob(os.path.join(args.scenes, "*.toml")))
    for scene in scenes:
        name = os.path.basename(scene)
        if args.only and args.only not in name:
            continue
        if name not in QUICK:
            failures.append(f"{name}: no quick settings in mfwave_scenes_test.py (every shipped scene must run)")
            continue
        code, out = run([args.mfwave, "check", scene])
        if code != 0 or "the scene is valid" not in out:
            failures.append(f"mfwave check {name}: exit {code}\n{out}")
        code, out = run([args.mfwave, "plan", scene, "--json"])
        try:
            plan = json.loads(out)
            missing = [k for k in PLAN_KEYS if k not in plan]
        except ValueError:
            plan, missing = None, PLAN_KEYS
        if code != 0 or missing:
            failures.append(f"mfwave plan {name} --json: exit {code}, missing {missing}\n{out}")
        with tempfile.TemporaryDirectory() as folder:
            code, out = run([args.mfwave, "run", scene, "--quiet", "--out", folder] + QUICK[name])
            summary = os.path.join(folder, "summary.json")
            if code != 0 or not os.path.exists(summary):
                failures.append(f"mfwave run {name}: exit {code}, summary.json {os.path.exists(summary)}\n{out}")
            else:
                print(f"{name}: check, plan and run pass")

    # Bad input: exit 2, the key named, nothing run.
    lamb = os.path.join(args.scenes, "lamb3d.toml")
    block = os.path.join(args.scenes, "block-ricker.toml")
    for command, key in [
        ([args.mfwave, "plan", lamb, "--set", "method.name=vwsph"], "method.name"),
        ([args.mfwave, "check", block, "--set", "method.name=reproducing_kernel"], "load[0].type"),
        ([args.mfwave, "run", lamb, "--set", "study.spacings=[0.3]", "--quiet"], "study.spacings"),
        ([args.mfwave], "subcommand is required"),
        ([args.mfwave, "plan", os.path.join(args.scenes, "no-such-scene.toml")], "no-such-scene.toml"),
    ]:
        code, out = run(command)
        if code != 2 or key not in out:
            failures.append(f"{' '.join(command[1:])}: exit {code} (want 2 naming {key})\n{out}")
    if failures:
        print("\n\n".join(failures))
        print(f"0 passed, {len(failures)} failed")
        return 1
    print("mfwave: every shipped scene checks, plans and runs; bad input exits 2 naming the key")
    return 0


if __name__ == "__main__":
    sys.exit(main())
