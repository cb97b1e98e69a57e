#!/usr/bin/env bash
# Fuzzes the scene reader, the time-function tables and the checkpoint reader with libFuzzer
# (clang, address and undefined-behaviour sanitizers: the fuzz preset) for SECONDS per target
# (default 60), from the seed corpus (data/scenes, tests/fuzz/seeds), and prints the executions
# each target reached.
# A crash stops with a non-zero exit and the input libFuzzer wrote (build/fuzz/artifacts/): copy it
# into tests/fuzz/regressions/<target>/ so that test_fuzz_replay replays it in every build.
#   bash scripts/run-fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
bash scripts/install-deps.sh
cmake --preset fuzz > /dev/null
cmake --build --preset fuzz
build=build/fuzz
status=0
for target in scene time_function checkpoint; do
  corpus="$build/corpus/$target"
  artifacts="$build/artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  if [ "$target" = scene ]; then cp data/scenes/*.toml "$corpus/"; fi
  cp tests/fuzz/seeds/"$target"/* "$corpus/" 2>/dev/null || true
  cp tests/fuzz/regressions/"$target"/* "$corpus/" 2>/dev/null || true
  log="$build/fuzz_$target.log"
  echo "== fuzz_$target for $seconds s (log: $log)"
  # One worker; rss limit well under the machine's memory; the corpus grows across runs.
  if "$build/tests/fuzz/fuzz_$target" "$corpus" -max_total_time="$seconds" -rss_limit_mb=4096 -timeout=20 \
      -artifact_prefix="$artifacts/" -print_final_stats=1 > "$log" 2>&1; then
    echo "fuzz_$target: $(grep -o 'number_of_executed_units: [0-9]*' "$log" | grep -o '[0-9]*$') executions," \
         "no crash; corpus $(ls "$corpus" | wc -l) inputs"
  else
    status=1
    echo "fuzz_$target: FAILED; the report:"
    grep -E "ERROR|SUMMARY|Test unit written|uncaught|terminate" "$log" | head -20
    echo "(copy the input above into tests/fuzz/regressions/$target/ and fix the reader)"
  fi
done
exit $status
