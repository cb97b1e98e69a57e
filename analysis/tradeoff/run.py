"""Runs one point of the speed-accuracy sweep as its own driver process and reads what it reports.

The driver is started by a small launcher process (launch.py) that times it and reaps it
with os.wait4, whose ru_maxrss is that driver's own peak resident memory (no /usr/bin/time).
OMP_NUM_THREADS=1 and --threads 1 keep each point on one core, so that points running side by
side do not compete for cores and the wall times are per-core figures.
"""
import hashlib
import json
import math
import os
import re
import subprocess
import sys
import threading

from .points import ERROR_MEASURES

LAUNCHER = os.path.join(os.path.dirname(os.path.abspath(__file__)), "launch.py")


def slug(point):
    """A folder name for the point: readable, and unique through a hash of the configuration id."""
    readable = re.sub(r"[^A-Za-z0-9.=]+", "_", point.config_id)[:80]
    return f"{readable}-{hashlib.sha1(point.config_id.encode()).hexdigest()[:8]}"


def derived_scene(source, drop, folder):
    """The scene file without the dotted keys in `drop` (a --set can change a key, not remove it).
    Handles what the study scenes hold: [table] headers and one `key = value` per line."""
    if not drop:
        return source
    table, kept = "", []
    with open(source) as f:
        for line in f:
            stripped = line.strip()
            header = re.match(r"^\[\[?([^\]]+)\]\]?", stripped)
            if header:
                table = header.group(1).strip()
            key = re.match(r"^([A-Za-z0-9_]+)\s*=", stripped)
            if key and f"{table}.{key.group(1)}" in drop:
                continue
            kept.append(line)
    os.makedirs(folder, exist_ok=True)
    stem = os.path.splitext(os.path.basename(source))[0]
    path = os.path.join(folder, f"{stem}-without-{hashlib.sha1(' '.join(sorted(drop)).encode()).hexdigest()[:8]}.toml")
    tmp = f"{path}.{threading.get_ident()}.tmp"   # two points may write the same copy at once
    with open(tmp, "w") as f:
        f.writelines(kept)
    os.replace(tmp, path)
    return path


def command_for(point, executable, scene, out_dir):
    argv = [executable, "--quiet", "--threads", "1", "--scene", scene, "--out", out_dir]
    for s in point.sets:
        argv += ["--set", s]
    return argv


def launch(argv, log, timeout, children):
    """Runs argv through launch.py; returns its report {exit_code, wall_s, peak_mib, killed}.
    `children` is a set shared with the caller, which terminates what is in it when interrupted."""
    launcher = [sys.executable, "-I", "-S", LAUNCHER, log, repr(timeout)] + argv
    proc = subprocess.Popen(launcher, stdout=subprocess.PIPE, env=dict(os.environ, OMP_NUM_THREADS="1"), text=True)
    children.add(proc)
    try:
        out, _ = proc.communicate()
    finally:
        children.discard(proc)
    if proc.returncode != 0 or not out.strip():
        raise OSError(f"the launcher failed (exit {proc.returncode}) for {' '.join(argv)}")
    return json.loads(out.strip().splitlines()[-1])


def _number(value):
    """A JSON number, or NaN for null (an unknown value) and anything else."""
    return float(value) if isinstance(value, (int, float)) else math.nan


def read_results(point, out_dir):
    """What the driver wrote, from the canonical record of its last case in summary.json ("cases",
    the same layout for every driver): particles, steps, step used, stable step, the case's primary
    error and its time-loop seconds."""
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    cases = summary.get("cases") or []
    if not cases:
        raise ValueError(f"{point.driver} wrote no cases in summary.json")
    case = cases[-1]
    # Drivers with several receivers (the Lamb studies) record each one's relative L2 error:
    # kept as "name=value;..." so that the report can answer per receiver.
    receivers = [(name[:-len("_relative_l2")], _number(value)) for name, value in (case.get("errors") or {}).items()
                 if name.endswith("_relative_l2") and name != "largest_relative_l2"]
    return {"particles": int(case["particles"]), "steps": int(case["steps"]), "dt": _number(case["dt"]),
            "dt_stable": _number(case["stable_dt"]), "error": _number(case["primary_error_value"]),
            "loop_s": _number(case["loop_seconds"]),
            "receiver_errors": ";".join(f"{n}={v:.6g}" for n, v in receivers) if len(receivers) > 1 else ""}


def last_line(path, limit=240):
    try:
        with open(path, errors="replace") as f:
            lines = [line.strip() for line in f if line.strip()]
    except OSError:
        return ""
    return lines[-1][:limit] if lines else ""


def run_point(point, executables, scenes_dir, out_root, timeout, children):
    """Runs the point and returns its CSV row (a dict); `children` as for launch()."""
    run_dir = os.path.join(out_root, "runs", slug(point))
    os.makedirs(run_dir, exist_ok=True)
    for stale in ("summary.json", "convergence.csv", "cases.csv"):   # a half-finished earlier attempt
        if os.path.exists(os.path.join(run_dir, stale)):
            os.remove(os.path.join(run_dir, stale))
    scene = derived_scene(os.path.join(scenes_dir, point.scene), point.drop, os.path.join(out_root, "scenes"))
    argv = command_for(point, executables[point.driver], scene, run_dir)
    log = os.path.join(run_dir, "driver.log")
    row = {"config_id": point.config_id, "problem": point.problem, "method": point.method,
           "driver": point.driver, "resolution": point.resolution, "kernel": point.kernel,
           "support_ratio": point.support, "integrator": point.integrator, "dt_fraction": point.dt_fraction,
           "error_measure": ERROR_MEASURES[point.problem], "run_dir": os.path.relpath(run_dir, out_root)}
    report = launch(argv, log, timeout, children)
    code = report["exit_code"]
    row.update(exit_code=code, wall_s=report["wall_s"], peak_mib=report["peak_mib"])
    if report["killed"]:
        row.update(status="killed", note=report["killed"])
        return row
    if code != 0:
        # The drivers' exit codes: 2 bad input, 3 the run became unstable, 1 other errors.
        row.update(status={2: "bad_input", 3: "unstable"}.get(code, "failed"), note=last_line(log))
        return row
    try:
        results = read_results(point, run_dir)
    except (OSError, KeyError, IndexError, ValueError) as e:
        row.update(status="unreadable", note=f"could not read the driver's output: {e}")
        return row
    row.update(results)
    loop_s = results.get("loop_s", math.nan)
    row["particle_steps_per_s"] = results["particles"] * results["steps"] / loop_s if loop_s > 0 else math.nan
    err = results.get("error", math.nan)
    # A relative error of 1 is what the zero field scores: such a run exited normally but has no
    # accuracy (a scheme that does not converge, or a slow blow-up the driver's monitor did not
    # catch). It is kept, as "inaccurate", and left out of the Pareto front and the targets.
    if not (math.isfinite(err) and err < 1):
        row.update(status="inaccurate", note="relative error >= 1: no better than the zero field")
    else:
        row["status"] = "ok"
    return row
