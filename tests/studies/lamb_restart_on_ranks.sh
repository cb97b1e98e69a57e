#!/bin/bash
# Checkpoints per rank with one manifest (issue 22): a run on N ranks with --checkpoint-every, then
# a restart on N ranks from a copy of its folder that lost its newest checkpoints, must end with the
# uninterrupted run's probe series and energy tables byte for byte, having gone on from the middle
# of a case. The copy keeps, for the first time loop, rank 0's older checkpoint only and the other
# ranks' newest two (a run killed while they were a checkpoint ahead): the ranks must agree on the
# older one. Every later loop keeps its older checkpoint only on every rank. Cases that run on rank 0
# alone checkpoint in rank 0's folder alone (with EXPECT=alone every case must; the other ranks
# then write no checkpoint at all).
# A restart on N + 1 ranks and a serial restart are refused with exit 2, naming both rank counts.
# Usage: [EXPECT=alone] lamb_restart_on_ranks.sh <driver> <mpiexec> <ranks> <work folder> [--set ...]
set -euo pipefail
. "$(dirname "$0")/compare_tables.sh"
driver=$1 mpiexec=$2 ranks=$3 work=$4
shift 4
rm -rf "$work"
mkdir -p "$work"
export OMP_NUM_THREADS=1 CI=true OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
on_ranks() {
  local n=$1
  shift
  # Ranks that disagree on a checkpoint wait on one another for ever: fail instead (a run takes seconds).
  timeout -k 10 180 "$mpiexec" -np "$n" --oversubscribe "$driver" --quiet "$@"
}
fail=0

# The uninterrupted run, checkpointed every 10 steps.
on_ranks "$ranks" --out "$work/whole" --checkpoint-every 10 "$@" > "$work/whole.log" 2>&1
manifest="$work/whole/checkpoint-manifest.txt"
grep -q "^ranks $ranks\$" "$manifest" || { echo "FAIL: $manifest does not name $ranks ranks"; cat "$manifest"; exit 1; }
while read -r key file; do  # every file the manifest names is there
  [ "$key" != file ] || [ -f "$work/whole/$file" ] || { echo "FAIL: $manifest names $file, which is missing"; exit 1; }
done < "$manifest"
# Rank 0 steps every loop; the others those on the ranks (a case on rank 0 alone leaves them none).
ls "$work/whole/rank-0-of-$ranks"/checkpoint-0000-*.mfwc > /dev/null || { echo "FAIL: rank 0 wrote no checkpoint of loop 0"; exit 1; }
# With EXPECT=alone every case runs on rank 0 alone: the other ranks must write nothing.
for ((r = 1; r < ranks; r++)); do
  count=$(find "$work/whole/rank-$r-of-$ranks" -name "checkpoint-*.mfwc" | wc -l)
  if [ "${EXPECT:-}" = alone ]; then
    [ "$count" = 0 ] || { echo "FAIL: rank $r wrote $count checkpoints of cases that ran on rank 0 alone"; exit 1; }
  else
    [ "$count" -gt 0 ] || { echo "FAIL: rank $r wrote no checkpoint"; exit 1; }
  fi
done

# An "interrupted" copy of run $1 in $2: the scene and the checkpoints, minus the newest of each
# loop as said above, no outputs; then the restart on the same rank count from it, which must end
# with the uninterrupted run's tables and have gone on from step $3 of the first case.
cut_and_restart() {
  local from=$1 cut=$2 expect=$3 removed=0
  mkdir -p "$cut"
  cp "$from/scene.resolved.toml" "$from/checkpoint-manifest.txt" "$cut/"
  cp -r "$from"/rank-*-of-"$ranks" "$cut/"
  for folder in "$cut"/rank-*-of-"$ranks"; do
    rank=$(basename "$folder" | cut -d- -f2)
    for loop in $(ls "$folder" | sed -n 's/^checkpoint-\([0-9]\{4\}\)-.*/\1/p' | sort -u); do
      [ "$loop" = 0000 ] && [ "$rank" != 0 ] && continue
      files=$(ls "$folder"/checkpoint-"$loop"-*.mfwc | sort)
      [ "$(echo "$files" | wc -l)" -ge 2 ] || continue
      rm "$(echo "$files" | tail -1)"
      removed=$((removed + 1))
    done
  done
  [ "$removed" -ge 1 ] || { echo "FAIL: no checkpoint to remove in $cut"; fail=1; }

  on_ranks "$ranks" --restart "$cut" > "$cut.log" 2>&1 ||
    { echo "FAIL: the restart on $ranks ranks from $cut exited $?"; cat "$cut.log"; exit 1; }

  compare_tables "$work/whole" "$cut" "the run restarted in $cut" || fail=1

  # The restart really went on from inside the first case, and says so.
  /usr/bin/python3 - "$cut/summary.json" "$expect" <<'PY' || fail=1
import json, os, sys
summary = json.load(open(sys.argv[1]))
expect = int(sys.argv[2])
first = summary["cases"][0]
resumed, steps = first.get("resumed_from_step", -1), first.get("steps", 0)
notes = " ".join(summary.get("notes", []))
ok = resumed == expect and 0 < resumed < steps
if not ok:
    print(f"FAIL: the first case resumed from step {resumed}, not {expect} strictly inside its {steps} steps")
for case in summary["cases"][1:]:  # every later case had its newest checkpoint removed on every rank
    if case.get("resumed_from_step") != expect:
        print(f"FAIL: case {case['case']} resumed from step {case.get('resumed_from_step')}, not {expect}"); ok = False
if os.environ.get("EXPECT") == "alone" and "ran on rank 0 alone" not in notes:
    print("FAIL: no case ran on rank 0 alone:", notes[:400]); ok = False
if "ran on rank 0 alone" in notes and "on rank 0 (" not in notes:
    print("FAIL: no loop that ran on rank 0 alone resumed from rank 0's checkpoint:", notes[:400]); ok = False
if "time loop 0 resumed from step" not in notes:
    print("FAIL: the summary does not say where the loops resumed:", notes[:300]); ok = False
print(f"{sys.argv[1]}: the first case resumed from step {resumed} of {steps}")
sys.exit(0 if ok else 1)
PY
  echo "$cut: removed $removed checkpoints"
}

# From the run checkpointed every 10 steps: the first case goes on from step 40. From one
# checkpointed every 25 (the same outputs), from step 25: more of the case is stepped again.
cut_and_restart "$work/whole" "$work/cut" 40
on_ranks "$ranks" --out "$work/every25" --checkpoint-every 25 "$@" > "$work/every25.log" 2>&1
cut_and_restart "$work/every25" "$work/cut25" 25

# Another rank count, and a serial run, are refused (exit 2) naming both counts.
status=0
on_ranks $((ranks + 1)) --restart "$work/whole" --out "$work/more" > "$work/more.log" 2>&1 || status=$?
if [ "$status" != 2 ] || ! grep -q "written by $ranks MPI ranks; this run has $((ranks + 1)) MPI ranks" "$work/more.log"; then
  echo "FAIL: a restart on $((ranks + 1)) ranks exited $status (expected 2 naming $ranks and $((ranks + 1)) ranks):"
  head -5 "$work/more.log"
  fail=1
fi
status=0
"$driver" --quiet --restart "$work/whole" --out "$work/serial" > "$work/serial.log" 2>&1 || status=$?
if [ "$status" != 2 ] || ! grep -q "a run on $ranks MPI ranks; this run is serial" "$work/serial.log"; then
  echo "FAIL: a serial restart exited $status (expected 2 naming $ranks ranks and serial):"
  head -5 "$work/serial.log"
  fail=1
fi
exit $fail
