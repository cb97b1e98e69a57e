#!/usr/bin/env bash
# The README's main-study command: installs what is missing, builds the release preset, runs the
# main study end to end (CSV, PNG) and prints its errors and cost.
# Until the Lamb study lands, the main study is wave1d (docs/studies/wave1d.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --target wave1d
out="${1:-out/wave1d}"
./build/release/drivers/wave1d --scene data/scenes/wave1d.toml --out "$out"
/usr/bin/python3 analysis/plot_wave1d.py "$out"
