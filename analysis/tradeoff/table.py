"""tradeoff.csv: one row per finished point, appended as each point finishes, read back to resume.

Each row is written as one complete line with a single write and then flushed and synced, so an
interrupted sweep leaves whole rows only (a torn last line, from a machine crash, is dropped on
reading and its point rerun).
"""
import csv
import io
import math
import os

COLUMNS = ["config_id", "status", "exit_code", "problem", "method", "resolution", "particles", "kernel",
           "support_ratio", "integrator", "dt_fraction", "error", "error_measure", "wall_s", "loop_s", "peak_mib",
           "steps", "particle_steps_per_s", "dt", "dt_stable", "driver", "run_dir", "receiver_errors", "note"]

NUMERIC = ["exit_code", "particles", "dt_fraction", "error", "wall_s", "loop_s", "peak_mib", "steps",
           "particle_steps_per_s", "dt", "dt_stable"]


def _format(value):
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.9g}"
    return "" if value is None else str(value)


def format_row(row):
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerow([_format(row.get(c)) for c in COLUMNS])
    return buffer.getvalue()


class Table:
    def __init__(self, path):
        self.path = path
        self.rows = read_rows(path) if os.path.exists(path) else []

    def finished_ids(self):
        return {r["config_id"] for r in self.rows}

    def append(self, row):
        line = format_row(row)
        new = not os.path.exists(self.path) or os.path.getsize(self.path) == 0
        with open(self.path, "a") as f:
            if new:
                f.write(",".join(COLUMNS) + "\n")
            f.write(line)
            f.flush()
            os.fsync(f.fileno())
        self.rows.append(parse_row(next(csv.DictReader(io.StringIO(",".join(COLUMNS) + "\n" + line)))))


def parse_row(raw):
    row = dict(raw)
    for c in NUMERIC:
        try:
            row[c] = float(row[c]) if row.get(c) not in (None, "") else math.nan
        except ValueError:
            row[c] = math.nan
    return row


def read_rows(path):
    """The complete rows of an existing tradeoff.csv; raises ValueError if its columns are not ours."""
    with open(path, newline="") as f:
        text = f.read()
    if not text.strip():
        return []
    if not text.endswith("\n"):
        # A torn last line: cut it off, so the next append starts on a line of its own.
        text = text[: text.rfind("\n") + 1]
        with open(path + ".tmp", "w") as f:
            f.write(text)
        os.replace(path + ".tmp", path)
    reader = csv.DictReader(io.StringIO(text))
    if reader.fieldnames != COLUMNS:
        raise ValueError(f"{path} has other columns than this version of the tool writes; "
                         f"use another --out folder or remove the file")
    return [parse_row(r) for r in reader if r.get(COLUMNS[-1]) is not None]
