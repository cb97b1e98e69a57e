#!/usr/bin/python3
"""Every study driver gives bitwise the same outputs with 1 and with 2 OpenMP threads.

    /usr/bin/python3 tests/tools/determinism_test.py --build BUILD --scenes data/scenes

Runs each driver's small case (the sizes of the study tests) twice, OMP_NUM_THREADS=1 and 2, and
compares the two output folders: CSV files cell by cell and summary.json figure by figure with
scripts/compare-outputs.py (timing and memory columns excluded), every other file (VTK frames, .pvd
collections, scene.resolved.toml) byte for byte. Exits 1 naming every difference.
"""
import argparse
import filecmp
import importlib.util
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
COMPARE = os.path.join(HERE, "..", "..", "scripts", "compare-outputs.py")

RUNS = [
    ("wave1d", "wave1d", "wave1d.toml", ["--set", "study.cells=[32, 64]",
                                         "--set", 'study.integrators=["central_difference", "newmark", "arkode"]']),
    ("bar1d", "bar1d", "bar1d.toml", ["--set", "study.nodes=[21, 41]"]),
    ("plane2d", "plane2d", "plane2d.toml", ["--set", "study.cells=[8, 12]"]),
    ("planewave", "planewave", "planewave.toml", []),
    ("planewave-ulsph", "planewave", "planewave.toml", ["--set", "study.method=updated_lagrangian_sph",
                                                             "--set", "study.gradient_correction=true"]),
    ("wavefield", "wavefield", "block-ricker.toml", []),
    ("bar1d-sph", "bar1d-sph", "bar1d-sph.toml", ["--set", "study.spacings=[0.02, 0.01]", "--set", "geometry.spacing=0.01"]),
    ("lamb3d", "lamb3d", "lamb3d.toml", ["--set", "study.spacings=[0.5]", "--set", "output.every=11"]),
    # lamb3d's spectral elements at N = 2: 343 elements, above the one-thread threshold of 64.
    ("lamb3d-sem", "lamb3d", "lamb3d.toml", ["--set", "method.name=spectral_element", "--set", "method.order=2",
                                             "--set", "study.spacings=[0.5]", "--set", "output.every=11"]),
    # lamb2d by each method at a spacing where its parallel loops run on both threads (the UL-SPH from
    # 2,048 particles: 2,145 at 0.25; the spectral elements from 64 elements: 128 at 0.25).
    ("lamb2d", "lamb2d", "lamb2d.toml", ["--set", "study.spacings=[0.25]", "--set", "output.every=11"]),
    ("lamb2d-rk", "lamb2d", "lamb2d.toml", ["--set", "method.name=reproducing_kernel", "--set", "study.spacings=[0.5]",
                                            "--set", "geometry.spacing=0.5", "--set", "output.every=11"]),
    ("lamb2d-ulsph", "lamb2d", "lamb2d.toml", ["--set", "method.name=updated_lagrangian_sph",
                                               "--set", "study.spacings=[0.25]", "--set", "output.every=11"]),
    ("lamb2d-sem", "lamb2d", "lamb2d.toml", ["--set", "method.name=spectral_element", "--set", "study.spacings=[0.25]",
                                             "--set", "output.every=11"]),
    ("planewave-sem", "planewave", "planewave.toml", ["--set", "study.method=spectral_element",
                                                      "--set", "study.cells=64"]),
    ("plate", "plate", "plate.toml", ["--set", "geometry.spacing=0.006666666666666667", "--set", "integrator.end_time=2",
                                      "--set", "study.resolutions=[3, 4]", "--set", "study.convergence_end_time=0.5",
                                      "--set", "output.png=false", "--set", "output.every=4000"]),
    ("rings", "rings", "rings.toml", ["--set", "geometry.spacing=0.002", "--set", "method.smoothing_length_ratio=1.3",
                                      "--set", "output.png=false", "--set", "output.every=2000"]),
]


def load_compare():
    spec = importlib.util.spec_from_file_location("compare_outputs", COMPARE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def run(build, scenes, driver, scene, extra, out, threads):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    env.pop("DISPLAY", None)  # no PNG pictures: the renderer is not part of the arithmetic
    command = [os.path.join(build, "drivers", driver), "--quiet", "--scene", os.path.join(scenes, scene),
               "--out", out] + extra
    done = subprocess.run(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if done.returncode != 0:
        raise SystemExit(f"{driver} ({threads} threads) exited {done.returncode}:\n{done.stdout}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True)
    parser.add_argument("--scenes", required=True)
    args = parser.parse_args()
    compare = load_compare()
    root = tempfile.mkdtemp(prefix="mfwave-determinism-")
    problems = []
    try:
        for name, driver, scene, extra in RUNS:
            one, two = os.path.join(root, name + "-1"), os.path.join(root, name + "-2")
            run(args.build, args.scenes, driver, scene, extra, one, 1)
            run(args.build, args.scenes, driver, scene, extra, two, 2)
            found = compare.compare_run(one, two)
            files = 0
            for dirpath, _, names in os.walk(one):
                for f in names:
                    files += 1
                    if f.endswith(".csv") or f == "summary.json":
                        continue
                    rel = os.path.relpath(os.path.join(dirpath, f), one)
                    other = os.path.join(two, rel)
                    if os.path.exists(other) and not filecmp.cmp(os.path.join(dirpath, f), other, shallow=False):
                        found.append(f"{rel}: differs byte for byte")
            print(f"{name}: {files} files, " + ("identical" if not found else f"{len(found)} differences"))
            problems += [f"{name}: {p}" for p in found]
    finally:
        shutil.rmtree(root, ignore_errors=True)
    for p in problems:
        print("   ", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
