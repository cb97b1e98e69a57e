#!/bin/bash
# The finite-difference wavefield under mpirun gives the serial run's numbers (issue 22): the same
# scene alone and on N ranks; probes.csv and energy.csv must be the same files byte for byte,
# summary.json the same figures (energy, stable steps, operator size), the run must say it stepped
# on the ranks, and its frames must be one .pvtp per frame over N pieces. The serial run must have
# moved (a probe above 1e-3), so two runs that did nothing cannot pass.
# Usage: wavefield_on_ranks.sh <driver> <mpiexec> <ranks> <work folder> [--set ...]
set -euo pipefail
driver=$1 mpiexec=$2 ranks=$3 work=$4
shift 4
rm -rf "$work"
mkdir -p "$work"
export OMP_NUM_THREADS=1 CI=true
"$driver" --quiet --out "$work/serial" --set output.png=false "$@" > "$work/serial.log"
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  "$mpiexec" -np "$ranks" --oversubscribe "$driver" --quiet --out "$work/ranks" --set output.png=false "$@" \
  > "$work/ranks.log"

fail=0
for table in probes.csv energy.csv; do
  if ! cmp -s "$work/serial/$table" "$work/ranks/$table"; then
    echo "FAIL: $table on $ranks ranks differs from the serial run's"
    fail=1
  fi
done
/usr/bin/python3 - "$work" "$ranks" <<'PY' || fail=1
import csv, glob, json, sys
work, ranks = sys.argv[1], int(sys.argv[2])
serial = json.load(open(f"{work}/serial/summary.json"))
ranked = json.load(open(f"{work}/ranks/summary.json"))
ok = True
def figures(s):  # the speeds differ by nature
    return {k: v for k, v in s["figures"].items() if "per_second" not in k}
fa, fb = figures(serial), figures(ranked)
if not fa or fa != fb:
    print("FAIL: the figures differ:", {k: (fa.get(k), fb.get(k)) for k in set(fa) | set(fb) if fa.get(k) != fb.get(k)}); ok = False
if serial["steps"] != ranked["steps"]:
    print("FAIL: steps", serial["steps"], ranked["steps"]); ok = False
if f"stepped on {ranks} ranks" not in " ".join(ranked.get("notes", [])):
    print("FAIL: the run does not say it stepped on the ranks"); ok = False
rows = list(csv.reader(open(f"{work}/serial/probes.csv")))[1:]
peak = max(abs(float(x)) for row in rows for x in row[1:])
if not peak > 1e-3:
    print("FAIL: the serial probes stayed at", peak); ok = False
masters = glob.glob(f"{work}/ranks/*.pvtp")
if not masters:
    print("FAIL: no .pvtp frames"); ok = False
elif open(masters[0]).read().count("<Piece ") != ranks:
    print(f"FAIL: {masters[0]} does not list {ranks} pieces"); ok = False
print(f"compared {len(fa)} figures, {len(rows)} probe rows (peak {peak:.3g}); {len(masters)} .pvtp frames")
sys.exit(0 if ok else 1)
PY
# Bad input on every rank: exit 2, the message once (rank 0's; the others wait, then are aborted);
# not quiet, so the shipped scene's line must appear once too (the launcher's first process only).
set +e
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
  "$mpiexec" -np "$ranks" --oversubscribe "$driver" --out "$work/bad" --set integrator.cfl=-1 "$@" \
  > "$work/bad.log" 2>&1
code=$?
set -e
said=$(grep -c "error: .*integrator.cfl" "$work/bad.log" || true)
if [ "$code" -ne 2 ] || [ "$said" -ne 1 ]; then
  echo "FAIL: bad input on $ranks ranks exited $code and said so $said times (want 2 and once)"; cat "$work/bad.log"; fail=1
fi
shipped=$(grep -c "no --scene given" "$work/bad.log" || true)
if [ "$shipped" -ne 1 ]; then
  echo "FAIL: the shipped scene's line appears $shipped times on $ranks ranks (want once)"; cat "$work/bad.log"; fail=1
fi
exit $fail
