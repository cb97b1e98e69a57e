"""Helpers shared by the plot scripts (run with Debian's /usr/bin/python3)."""
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
