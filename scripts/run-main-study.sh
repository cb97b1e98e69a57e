#!/usr/bin/env bash
# The README's main-study command: installs what is missing, builds the release preset, runs the
# main study end to end and plots it: lamb3d, the Ding-Long-Wu 3-D Lamb problem by very weak form
# SPH (docs/studies/lamb3d.md). About 95 s on 2 cores and 2.1 GiB of memory (the finest case
# has 185,193 particles). Prints the plan (mfwave plan), then runs the scene (mfwave run): writes CSV,
# PNG and VTK files and prints errors and cost.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release --target lamb3d mfwave
out="${1:-out/lamb3d}"
# What the scene will cost and how accurate it is, predicted before any stepping (docs/mfwave.md),
# then the run through the one program, which hands the scene to its study (lamb3d).
./build/release/drivers/mfwave plan data/scenes/lamb3d.toml
./build/release/drivers/mfwave run data/scenes/lamb3d.toml --out "$out"
/usr/bin/python3 analysis/plot_lamb3d.py "$out"
