#!/usr/bin/python3
"""The 3-D Lamb problem as a quarter (issue 48): data/scenes/lamb3d_quarter.toml, the block x >= 0,
y >= 0 with symmetry planes on x = 0 and y = 0, gives the probe series of the whole block
(data/scenes/lamb3d.toml) to 1e-9 relative at dx = 0.125 and the same fixed time step, with about a
quarter of the particles. Both scenes run without their free_block case (a comparison of the
transmitting faces, not of the planes) and the published cases (the unit test SymmetryPlanesTest
checks every variant's operators).

    /usr/bin/python3 tests/tools/symmetry_quarter_test.py --lamb3d BUILD/drivers/lamb3d --scenes data/scenes
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

TOLERANCE = 1e-9


def without_free_block(source, target):
    with open(source) as f:
        lines = [line for line in f if not line.startswith("free_block_")]
    with open(target, "w") as f:
        f.writelines(lines)


def series(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header = rows[0]
    values = [[float(x) for x in row] for row in rows[1:] if row]
    return header, values


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lamb3d", required=True)
    parser.add_argument("--scenes", required=True)
    parser.add_argument("--spacing", default="0.125")
    parser.add_argument("--time-step", default="0.025")
    args = parser.parse_args()
    failures = []
    with tempfile.TemporaryDirectory() as work:
        runs = {}
        for name in ("lamb3d", "lamb3d_quarter"):
            scene = os.path.join(work, name + ".toml")
            without_free_block(os.path.join(args.scenes, name + ".toml"), scene)
            out = os.path.join(work, "out-" + name)
            command = [args.lamb3d, "--scene", scene, "--out", out, "--quiet", "--threads", "2",
                       "--set", "geometry.spacing=" + args.spacing, "--set", "study.spacings=[" + args.spacing + "]",
                       "--set", "study.compare_published=false", "--set", "output.vtk=false",
                       "--set", "integrator.time_step=" + args.time_step]
            # the scenes give cfl; a fixed step replaces it
            with open(scene) as f:
                text = f.read()
            with open(scene, "w") as f:
                f.write("\n".join(line for line in text.splitlines() if not line.startswith("cfl")) + "\n")
            done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            if done.returncode != 0:
                print(done.stdout)
                sys.exit(name + ": exit " + str(done.returncode))
            with open(os.path.join(out, "summary.json")) as f:
                summary = json.load(f)
            runs[name] = (out, summary)
        case = "galerkin_" + args.spacing
        header, whole = series(os.path.join(runs["lamb3d"][0], case + "-probes.csv"))
        header_q, quarter = series(os.path.join(runs["lamb3d_quarter"][0], case + "-probes.csv"))
        if header != header_q or len(whole) != len(quarter):
            sys.exit("the probe tables differ in shape: %s (%d rows) vs %s (%d rows)" % (header, len(whole), header_q, len(quarter)))
        for j, column in enumerate(header[1:], start=1):
            scale = max(abs(row[j]) for row in whole) or 1.0
            worst = max(abs(a[j] - b[j]) for a, b in zip(whole, quarter)) / scale
            print("%-22s max |quarter - whole| / max |whole| = %.3g" % (column, worst))
            if worst > TOLERANCE:
                failures.append("%s: %.3g > %g" % (column, worst, TOLERANCE))
        particles = {}
        for name, (out, summary) in runs.items():
            with open(os.path.join(out, "cases.csv")) as f:
                rows = list(csv.DictReader(f))
            particles[name] = int(rows[0]["particles"])
            print("%-15s %8d particles, wall %s s" % (name, particles[name], rows[0].get("wall [s]", "?")))
        ratio = particles["lamb3d_quarter"] / particles["lamb3d"]
        print("particles: quarter / whole = %.3f" % ratio)
        if not 0.24 < ratio < 0.28:
            failures.append("the quarter holds %.3f of the whole's particles (expected about a quarter)" % ratio)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("the quarter gives the whole block's probe series")


if __name__ == "__main__":
    main()
