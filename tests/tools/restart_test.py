#!/usr/bin/python3
"""A run stopped by SIGTERM or killed by SIGKILL, then restarted with --restart, ends with the same
outputs as a run that never stopped (issue 20).

    /usr/bin/python3 tests/tools/restart_test.py --build BUILD --scenes data/scenes [--only NAME]

For each case: a reference run with --checkpoint-every; then the same run signalled as soon as a
checkpoint of a chosen time loop (a study case) exists, which must end with 143 (SIGTERM: the
step finished, a checkpoint written, the outputs flushed) or die by SIGKILL, and be restarted with
`--restart FOLDER` alone (its scene comes from the folder's scene.resolved.toml) to exit 0. The
restarted folder must hold the reference's outputs: every CSV cell and summary figure with
scripts/compare-outputs.py (timing columns excluded), every other file (VTK frames, .pvd) byte for
byte, and the newest checkpoint of every time loop byte for byte (the whole state: solution,
integrator history, observers' buffers). The restart must really have gone on from the middle of
the interrupted loop (its summary's resumed_from_step lies strictly inside the case).

Then the damaged checkpoints: a flipped byte in, or a truncation of, a loop's newest checkpoint is
skipped with a message naming the file and the run goes on from the one before, with the same
outputs; a restart of another scene is refused with exit 2 naming --restart.
"""
import argparse
import filecmp
import glob
import importlib.util
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
COMPARE = os.path.join(HERE, "..", "..", "scripts", "compare-outputs.py")

# name, driver, scene, extra arguments, steps between checkpoints, and the interruptions to try:
# (signal, the time loop whose first checkpoint triggers it).
WAVE1D = ["--set", "study.cells=[1024]", "--set", 'study.integrators=["central_difference", "newmark", "arkode"]',
          "--set", "integrator.end_time=4"]
CASES = [
    # Linear second order: central difference (loop 0), Newmark (loop 1), ARKODE's fixed-step RK4 (loop 2).
    ("wave1d", "wave1d", "wave1d.toml", WAVE1D, 500,
     [(signal.SIGTERM, 0), (signal.SIGKILL, 1), (signal.SIGTERM, 2)]),
    # Constrained Newmark on the reproducing-kernel collocation of the bar (its coefficients d, d', d'').
    ("bar1d", "bar1d", "bar1d.toml", ["--set", "study.nodes=[81, 161]", "--set", "integrator.end_time=300"], 300,
     [(signal.SIGKILL, 0), (signal.SIGTERM, 1)]),
    # The UL-SPH (first order, leapfrog at the method's own step rule; the neighbour skin), with VTK frames.
    ("bar1d-sph", "bar1d-sph", "bar1d-sph.toml", ["--set", "study.spacings=[0.002, 0.001]"], 100,
     [(signal.SIGTERM, 1), (signal.SIGKILL, 1)]),
    ("rings", "rings", "rings.toml", ["--set", "geometry.spacing=0.002", "--set", "output.png=false",
                                      "--set", "integrator.end_time=2e-4"], 100,
     [(signal.SIGKILL, 0), (signal.SIGTERM, 1)]),
    # The very weak SPH on the 2-D Lamb problem: the energy ledger with its filter loss, transmitting
    # faces (implicit dashpots), probes with deconvolution, VTK frames of the first case.
    # The kill goes to loop 1 (published_0.25, 561 steps in about 40 ms): loop 3 (281 steps in 5 ms)
    # could end before the signal arrived on a loaded machine.
    ("lamb2d", "lamb2d", "lamb2d.toml", ["--set", "study.spacings=[0.5, 0.25]", "--set", "integrator.end_time=40"], 100,
     [(signal.SIGTERM, 0), (signal.SIGKILL, 1)]),
]

NOTES_OF_A_RESTART = ("time loop ", "checkpoint skipped")


def load_compare():
    spec = importlib.util.spec_from_file_location("compare_outputs", COMPARE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def command(build, driver, args):
    return [os.path.join(build, "drivers", driver), "--quiet"] + args


def environment():
    env = dict(os.environ, OMP_NUM_THREADS="1")
    env.pop("DISPLAY", None)
    return env


def run(build, driver, args, expect=0):
    done = subprocess.run(command(build, driver, args), env=environment(), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    if done.returncode != expect:
        raise AssertionError(f"{driver} {' '.join(args)} exited {done.returncode}, expected {expect}:\n{done.stdout}")
    return done.stdout


def interrupted_run(build, driver, args, folder, sig, loop):
    """Starts the run, signals it once loop `loop` has written a checkpoint, returns its exit status."""
    process = subprocess.Popen(command(build, driver, args), env=environment(), stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    pattern = os.path.join(folder, f"checkpoint-{loop:04d}-*.mfwc")
    deadline = time.monotonic() + 300
    while not glob.glob(pattern):
        if process.poll() is not None:
            raise AssertionError(f"{driver} ended ({process.returncode}) before loop {loop} wrote a checkpoint:\n"
                                 + process.stdout.read())
        if time.monotonic() > deadline:
            process.kill()
            raise AssertionError(f"{driver}: no checkpoint of loop {loop} within 300 s")
        time.sleep(0.005)
    process.send_signal(sig)
    output, _ = process.communicate(timeout=300)
    return process.returncode, output


def checkpoint_arrays(path):
    """The named arrays of a checkpoint file (lib/io/checkpoint/Checkpoint.hpp, format 1)."""
    import struct
    data = open(path, "rb").read()
    at = 8 + 4 + 4 + 8
    def take(fmt):
        nonlocal at
        value = struct.unpack_from(fmt, data, at)
        at += struct.calcsize(fmt)
        return value
    def text():
        (n,) = take("<Q")
        nonlocal at
        at += n
        return data[at - n:at]
    text()
    take("<qd")
    (count,) = take("<Q")
    arrays = {}
    for _ in range(count):
        name = text().decode()
        (n,) = take("<Q")
        arrays[name] = take(f"<{n}d")
    return arrays


def newest_per_loop(folder):
    newest = {}
    for path in sorted(glob.glob(os.path.join(folder, "checkpoint-*.mfwc"))):
        newest[os.path.basename(path)[11:15]] = path  # sorted: the last of a loop is its newest
    return newest


def same_outputs(compare, reference, restarted):
    """The differences between a reference folder and a restarted one (empty when identical)."""
    found = [p for p in compare.compare_run(reference, restarted)
             if ".mfwc" not in p and not p.startswith("summary notes")]
    notes = lambda folder: [n for n in json.load(open(os.path.join(folder, "summary.json")))["notes"]
                            if not n.startswith(NOTES_OF_A_RESTART)]
    if notes(reference) != notes(restarted):
        found.append(f"summary notes: {notes(reference)} -> {notes(restarted)}")
    for dirpath, _, names in os.walk(reference):
        for f in names:
            if f.endswith((".csv", ".mfwc")) or f == "summary.json":
                continue
            rel = os.path.relpath(os.path.join(dirpath, f), reference)
            other = os.path.join(restarted, rel)
            if os.path.exists(other) and not filecmp.cmp(os.path.join(dirpath, f), other, shallow=False):
                found.append(f"{rel}: differs byte for byte")
    ref_newest, new_newest = newest_per_loop(reference), newest_per_loop(restarted)
    if sorted(ref_newest) != sorted(new_newest):
        found.append(f"time loops with checkpoints: {sorted(ref_newest)} -> {sorted(new_newest)}")
    for loop, path in ref_newest.items():
        if loop in new_newest and not filecmp.cmp(path, new_newest[loop], shallow=False):
            a, b = checkpoint_arrays(path), checkpoint_arrays(new_newest[loop])
            differing = sorted(k for k in set(a) | set(b) if a.get(k) != b.get(k))
            found.append(f"newest checkpoint of loop {loop}: {os.path.basename(path)} and "
                         f"{os.path.basename(new_newest[loop])} differ in {differing}")
    return found


def resumed_inside(folder):
    """Whether some case of the restarted run went on from a step strictly inside it."""
    cases = json.load(open(os.path.join(folder, "summary.json"))).get("cases", [])
    return any(0 < c.get("resumed_from_step", -1) < c["steps"] for c in cases)


def check_case(compare, build, scenes, root, case):
    name, driver, scene, extra, every, interruptions = case
    base = ["--scene", os.path.join(scenes, scene)] + extra + ["--checkpoint-every", str(every)]
    problems = []
    reference = os.path.join(root, name + "-reference")
    run(build, driver, base + ["--out", reference])
    for sig, loop in interruptions:
        label = f"{name}, {signal.Signals(sig).name} in loop {loop}"
        folder = os.path.join(root, f"{name}-{signal.Signals(sig).name.lower()}-{loop}")
        status, output = interrupted_run(build, driver, base + ["--out", folder], folder, sig, loop)
        expected = 128 + sig if sig == signal.SIGTERM else -sig
        if status != expected:
            problems.append(f"{label}: exit {status}, expected {expected}:\n{output}")
            continue
        if sig == signal.SIGTERM and f"--restart {folder}" not in output:
            problems.append(f"{label}: the interrupted run does not say how to go on:\n{output}")
        run(build, driver, ["--restart", folder, "--checkpoint-every", str(every)])
        if not resumed_inside(folder):
            problems.append(f"{label}: the restart did not go on from inside a case (the interruption came too late)")
        found = same_outputs(compare, reference, folder)
        problems += [f"{label}: {p}" for p in found]
        print(f"{label}: exit {status}, restarted: " + ("identical" if not found else f"{len(found)} differences"))

    # Damaged checkpoints, on a copy of the reference: the last loop's newest one flipped, then
    # truncated; each is skipped (named) and the loop goes on from the one before.
    for damage in ("flipped", "truncated"):
        label = f"{name}, newest checkpoint {damage}"
        folder = os.path.join(root, f"{name}-{damage}")
        shutil.copytree(reference, folder)
        newest = newest_per_loop(folder)
        victim = newest[sorted(newest)[-1]]
        data = bytearray(open(victim, "rb").read())
        if damage == "flipped":
            data[len(data) // 2] ^= 0x10
        else:
            data = data[: len(data) - 100]
        open(victim, "wb").write(bytes(data))
        output = run(build, driver, ["--restart", folder, "--checkpoint-every", str(every)])
        if os.path.basename(victim) not in output:
            problems.append(f"{label}: the restart did not name the damaged file:\n{output}")
        if not resumed_inside(folder):
            problems.append(f"{label}: the restart did not go on from the checkpoint before the damaged one")
        found = same_outputs(compare, reference, folder)
        problems += [f"{label}: {p}" for p in found]
        print(f"{label}: skipped and restarted from the one before: " +
              ("identical" if not found else f"{len(found)} differences"))

    # Another scene's checkpoints: refused, exit 2, the folder left as it was.
    folder = os.path.join(root, f"{name}-other-scene")
    shutil.copytree(reference, folder)
    before = open(os.path.join(folder, "scene.resolved.toml")).read()
    output = run(build, driver, base + ["--restart", folder, "--set", "integrator.cfl=0.45"], expect=2)
    if "--restart" not in output or "another scene" not in output:
        problems.append(f"{name}, another scene: the refusal does not say why:\n{output}")
    if open(os.path.join(folder, "scene.resolved.toml")).read() != before:
        problems.append(f"{name}, another scene: the refused restart rewrote scene.resolved.toml")
    print(f"{name}, another scene's checkpoints: refused with exit 2")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True)
    parser.add_argument("--scenes", required=True)
    parser.add_argument("--only", help="run only the case of this name")
    args = parser.parse_args()
    compare = load_compare()
    root = tempfile.mkdtemp(prefix="mfwave-restart-")
    problems = []
    try:
        for case in CASES:
            if args.only and case[0] != args.only:
                continue
            try:
                problems += check_case(compare, args.build, args.scenes, root, case)
            except AssertionError as e:
                problems.append(f"{case[0]}: {e}")
    finally:
        shutil.rmtree(root, ignore_errors=True)
    for p in problems:
        print("   ", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
