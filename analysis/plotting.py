"""Helpers shared by the plot scripts (run with Debian's /usr/bin/python3)."""
import csv
import os

import matplotlib

matplotlib.use("Agg")


def save_atomically(fig, png, dpi=110):
    """Write the figure under a temporary name and rename it, so a PNG is never half written."""
    tmp = png + ".tmp.png"
    fig.savefig(tmp, dpi=dpi)
    os.replace(tmp, png)
    print(f"wrote {png}")


def finish_axes(axes):
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)


def read_table(path):
    """A CSV file with a header as a list of {column: text} rows; lines starting with # are comments."""
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def read_columns(path):
    """A numeric CSV file with a header as {column: [values]}, or None when the file is missing."""
    if not os.path.exists(path):
        return None
    with open(path) as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = [[float(x) for x in row] for row in reader]
    return {name: [row[k] for row in rows] for k, name in enumerate(header)}
