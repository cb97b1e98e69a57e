"""Speed-accuracy sweep over methods, resolutions, kernels and supports, integrators and step fractions.

    /usr/bin/python3 -m analysis.tradeoff --build build/release --out out/tradeoff [--full] [--jobs N]

(from the repository's top folder; the package is analysis/tradeoff/).

Each point is one driver process (wave1d, bar1d, plane2d, bar1d-sph, lamb2d, lamb3d, planewave) pinned
by --set to one configuration, on one core; the sweep runs --jobs of them at once. Writes into --out:
tradeoff.csv (a row per point, appended as it finishes), tradeoff.png (one panel per problem: error
against wall time with that problem's Pareto front), tradeoff-memory.png (error against peak memory
for the problems several methods solve), tradeoff.txt (per problem, the cheapest configuration for
10 %, 3 %, 1 % and 0.1 % error, at each receiver of the Lamb problems, also printed), runs/<point>/
(each driver's own output and log) and scenes/ (scene files with keys removed). Rerunning the command skips the points already in tradeoff.csv, so an interrupted sweep
resumes where it stopped. Page: docs/studies/tradeoff.md.
"""
import argparse
import os
import queue
import signal
import sys
import threading
import time

from .points import SWEEPS
from .plot import plot
from .report import report_text
from .run import run_point
from .table import Table

HERE = os.path.dirname(os.path.abspath(__file__))


def parse_args(argv):
    p = argparse.ArgumentParser(prog="python3 -m analysis.tradeoff", description=__doc__.split("\n\n")[0])
    p.add_argument("--build", required=True, help="CMake build folder holding drivers/ (e.g. build/release)")
    p.add_argument("--out", default="out/tradeoff", help="output folder (default: out/tradeoff)")
    size = p.add_mutually_exclusive_group()
    size.add_argument("--full", action="store_true", help="the longer sweep: finer resolutions, more kernels and fractions")
    size.add_argument("--smoke", action="store_true", help="four tiny points, for checking the tool itself")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 2,
                   help="driver processes at once (default: the number of cores)")
    p.add_argument("--timeout", type=float, default=1800, help="seconds before a point is killed (default 1800)")
    p.add_argument("--scenes", default=os.path.join(HERE, "..", "..", "data", "scenes"), help=argparse.SUPPRESS)
    args = p.parse_args(argv)
    if args.jobs < 1:
        p.error("--jobs must be at least 1")
    if not args.timeout > 0:
        p.error("--timeout must be positive")
    return args


def fail(message, code=2):
    """Bad input exits with 2, as the drivers do."""
    print(f"tradeoff: {message}", file=sys.stderr)
    sys.exit(code)


def find_executables(build, points):
    """{driver: path}; exits with a message naming what is missing."""
    if not os.path.isdir(build):
        fail(f"--build {build}: no such folder (configure and build first: "
                 f"cmake --preset release && cmake --build --preset release)")
    drivers = sorted({p.driver for p in points})
    paths = {d: os.path.join(build, "drivers", d) for d in drivers}
    missing = [d for d, path in paths.items() if not os.access(path, os.X_OK)]
    if missing:
        fail(f"missing driver executable(s) {', '.join(paths[d] for d in missing)}; "
                 f"build them: cmake --build {build} --target {' '.join(missing)}")
    return paths


def run_sweep(pending, executables, args):
    """Runs the points with --jobs worker threads; yields each finished row in the main thread."""
    todo, done = queue.Queue(), queue.Queue()
    for p in pending:
        todo.put(p)
    children, stop = set(), threading.Event()

    def worker():
        while not stop.is_set():
            try:
                point = todo.get_nowait()
            except queue.Empty:
                return
            try:
                done.put(("row", run_point(point, executables, args.scenes, args.out, args.timeout, children)))
            except Exception as e:  # noqa: BLE001 -- any failure must reach the main thread, or it waits forever
                done.put(("error", f"{point.config_id}: {type(e).__name__}: {e}"))

    threads = [threading.Thread(target=worker, daemon=True) for _ in range(min(args.jobs, len(pending)))]
    for t in threads:
        t.start()
    try:
        for _ in pending:
            while True:
                try:
                    yield done.get(timeout=0.5)   # a timeout, so that Ctrl-C reaches this thread
                    break
                except queue.Empty:
                    continue
    finally:
        stop.set()
        for child in list(children):
            child.terminate()   # the launcher kills its driver, then exits


def interrupted(_signum, _frame):
    raise KeyboardInterrupt   # a plain kill stops the running drivers too, as Ctrl-C does


def main(argv):
    args = parse_args(argv)
    signal.signal(signal.SIGTERM, interrupted)
    points = SWEEPS["full" if args.full else "smoke" if args.smoke else "default"]()
    executables = find_executables(args.build, points)
    os.makedirs(args.out, exist_ok=True)
    try:
        table = Table(os.path.join(args.out, "tradeoff.csv"))
    except ValueError as e:
        fail(str(e))
    finished = table.finished_ids()
    pending = [p for p in points if p.config_id not in finished]
    print(f"tradeoff: {len(points)} points, {len(points) - len(pending)} already in {table.path}, "
          f"{len(pending)} to run, {args.jobs} at a time", flush=True)
    start, errors = time.perf_counter(), []
    try:
        for k, (kind, item) in enumerate(run_sweep(pending, executables, args), 1):
            if kind == "error":
                errors.append(item)
                print(f"[{k}/{len(pending)}] not run: {item}", flush=True)
                continue
            table.append(item)
            err = item.get("error", float("nan"))
            print(f"[{k}/{len(pending)}] {item['status']:>9} {item['wall_s']:8.3f} s  error {err:9.3g}  "
                  f"{item['config_id']}", flush=True)
    except KeyboardInterrupt:
        fail(f"interrupted; finished points are in {table.path}: rerun the same command to resume", 130)
    print(f"tradeoff: ran {len(pending) - len(errors)} points in {time.perf_counter() - start:.1f} s", flush=True)

    text = report_text(table.rows)
    txt = os.path.join(args.out, "tradeoff.txt")
    with open(txt + ".tmp", "w") as f:
        f.write(text)
    os.replace(txt + ".tmp", txt)
    plot(table.rows, os.path.join(args.out, "tradeoff.png"))
    print(f"wrote {txt}\n\n{text}", end="")
    if errors:
        fail(f"{len(errors)} point(s) could not be run (not recorded; rerun to retry)", 1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
