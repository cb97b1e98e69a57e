#!/bin/bash
# A signal that reaches one rank of a run under mpirun stops every rank after the same step
# (issue 22; TimeLoop::agreeAcrossRanks): the run exits 143 within seconds instead of hanging in a
# halo exchange, rank 0 writes complete tables and summary.json says it was interrupted, no
# temporary file is left, and the wall-clock checkpoints (agreed the same way) let a restart on the
# same rank count finish with the probes and energies of an uninterrupted serial run, byte for byte.
# Usage: wavefield_signal_on_ranks.sh <driver> <mpiexec> <work folder>
set -uo pipefail
driver=$1 mpiexec=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
export OMP_NUM_THREADS=1 CI=true OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
scene=(--set output.png=false --set output.vtk=false --set integrator.end_time=100)
fail=0

"$driver" --quiet --out "$work/serial" "${scene[@]}" > "$work/serial.log" 2>&1 || { echo "FAIL: the serial run"; exit 1; }

timeout 120 "$mpiexec" -np 2 --oversubscribe "$driver" --quiet --out "$work/ranks" --checkpoint-every 0.5s "${scene[@]}" \
  > "$work/ranks.log" 2>&1 &
launcher=$!
# Once the ranks step (a wall-clock checkpoint's manifest is there), SIGTERM to one rank alone.
for _ in $(seq 1 300); do
  [ -e "$work/ranks/checkpoint-manifest.txt" ] && break
  sleep 0.1
done
sleep 0.5
ranks=$(pgrep -P "$(pgrep -f "^$mpiexec -np 2 --oversubscribe $driver --quiet --out $work/ranks" | head -1)")
target=$(echo $ranks | awk '{print $NF}')
if [ -z "$target" ]; then echo "FAIL: no rank process to signal"; exit 1; fi
kill -TERM "$target"
wait "$launcher"
code=$?
if [ "$code" -ne 143 ]; then echo "FAIL: the interrupted run exited $code, not 143 (124: it hung)"; fail=1; fi
if ls "$work/ranks" | grep -q '\.tmp'; then echo "FAIL: temporary files left: $(ls "$work/ranks" | grep '\.tmp')"; fail=1; fi
grep -q '"interrupted": "SIGTERM"' "$work/ranks/summary.json" || { echo "FAIL: summary.json does not say SIGTERM"; fail=1; }
partial=$(($(wc -l < "$work/ranks/probes.csv") - 1))
whole=$(($(wc -l < "$work/serial/probes.csv") - 1))
if ! [ "$partial" -gt 0 ] || ! [ "$partial" -lt "$whole" ]; then
  echo "FAIL: the interrupted run has $partial probe rows (the whole run $whole)"; fail=1
fi
# Its rows are the serial run's first rows.
if ! cmp -s <(head -n "$((partial + 1))" "$work/serial/probes.csv") <(head -n "$((partial + 1))" "$work/ranks/probes.csv"); then
  echo "FAIL: the interrupted run's probe rows differ from the serial run's"; fail=1
fi

timeout 120 "$mpiexec" -np 2 --oversubscribe "$driver" --quiet --restart "$work/ranks" > "$work/restart.log" 2>&1 \
  || { echo "FAIL: the restart on 2 ranks"; cat "$work/restart.log"; fail=1; }
for table in probes.csv energy.csv; do
  cmp -s "$work/serial/$table" "$work/ranks/$table" || { echo "FAIL: $table after the restart differs from the serial run's"; fail=1; }
done
echo "interrupted after $partial of $whole probe rows; exit $code"
exit $fail
