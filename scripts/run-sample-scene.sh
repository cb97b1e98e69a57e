#!/usr/bin/env bash
# Runs the sample 3-D scene (a Ricker point force in a fixed block) with VTK frames, PNG frames
# (under xvfb-run when there is no display) and probe CSVs, then plots the probes.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --target wavefield
out="${1:-out/block-ricker}"
run=(./build/release/drivers/wavefield --scene data/scenes/block-ricker.toml --out "$out")
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  xvfb-run -a -s "-screen 0 1280x1024x24" "${run[@]}"
else
  "${run[@]}"
fi
/usr/bin/python3 analysis/plot_probes.py "$out"
