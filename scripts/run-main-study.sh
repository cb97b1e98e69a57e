#!/usr/bin/env bash
# The README's main-study command: installs what is missing, builds the release preset, runs the
# main study end to end and plots it: lamb3d, the Ding-Long-Wu 3-D Lamb problem by very weak form
# SPH (docs/studies/lamb3d.md). About 95 s on 2 cores and 2.1 GiB of memory (the finest case
# has 185,193 particles). Writes CSV, PNG and VTK files and prints errors and cost.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --target lamb3d
out="${1:-out/lamb3d}"
./build/release/drivers/lamb3d --scene data/scenes/lamb3d.toml --out "$out"
/usr/bin/python3 analysis/plot_lamb3d.py "$out"
