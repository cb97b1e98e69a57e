"""Starts one driver of the tradeoff sweep and reports its wall time and its own peak memory.

    /usr/bin/python3 -I -S analysis/tradeoff/launch.py LOG TIMEOUT EXECUTABLE [ARGS...]

Prints one JSON line: exit_code (negative: the signal that ended it), wall_s, peak_mib, killed
(why it was stopped, or null). The driver's stdout and stderr go to LOG.

Why a separate, small process: Linux carries a process's peak-RSS mark across execve, so the
ru_maxrss that os.wait4 returns for a driver forked from the sweep itself (tens of MiB once
matplotlib is loaded) would be at least the sweep's size. This interpreter, started with -I -S and
only built-in modules imported before the fork, holds about 5 MiB when it forks: less than any
driver's own footprint, so the figure is the driver's.
"""
import os
import signal
import sys
import time


def main():
    log, timeout, argv = sys.argv[1], float(sys.argv[2]), sys.argv[3:]
    fd = os.open(log, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    start = time.perf_counter()
    pid = os.fork()
    if pid == 0:
        try:
            os.dup2(fd, 1)
            os.dup2(fd, 2)
            os.execv(argv[0], argv)
        finally:
            os._exit(127)
    os.close(fd)

    state = {"exited": False, "killed": None}

    def stop(signum, _frame):
        # The child is killed only while it has not exited; after waitid below it is a zombie
        # until reaped, so its pid cannot have been reused when this runs.
        if not state["exited"]:
            state["killed"] = f"timeout after {timeout:g} s" if signum == signal.SIGALRM else "sweep interrupted"
            os.kill(pid, signal.SIGKILL)

    for s in (signal.SIGALRM, signal.SIGTERM, signal.SIGINT):
        signal.signal(s, stop)
    signal.setitimer(signal.ITIMER_REAL, timeout)
    os.waitid(os.P_PID, pid, os.WEXITED | os.WNOWAIT)
    wall = time.perf_counter() - start
    state["exited"] = True
    signal.setitimer(signal.ITIMER_REAL, 0)
    _, status, usage = os.wait4(pid, 0)

    import json  # only now: imports before the fork would raise the floor of the driver's ru_maxrss
    try:
        print(json.dumps({"exit_code": os.waitstatus_to_exitcode(status), "wall_s": wall,
                          "peak_mib": usage.ru_maxrss / 1024.0, "killed": state["killed"]}), flush=True)  # KiB
    except BrokenPipeError:
        # The sweep has gone (interrupted): nobody to report to. Point stdout at /dev/null so that
        # the interpreter's final flush does not complain.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())


if __name__ == "__main__":
    main()
