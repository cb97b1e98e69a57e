# Sourced by the Lamb-on-ranks test scripts.
# compare_tables REFERENCE OTHER WHAT: every probe series and energy table of the REFERENCE run's
# folder must be the same file byte for byte in OTHER (WHAT names that run in the messages). Prints a
# FAIL line per difference; returns 1 on any, or when fewer than two tables were compared.
compare_tables() {
  local reference=$1 other=$2 what=$3 compared=0 status=0 file name
  for file in "$reference"/*-probes.csv "$reference"/*-energy.csv; do
    [ -e "$file" ] || continue
    name=$(basename "$file")
    compared=$((compared + 1))
    if ! cmp -s "$file" "$other/$name"; then
      echo "FAIL: $name of $what differs from the reference run's"
      status=1
    fi
  done
  if [ "$compared" -lt 2 ]; then
    echo "FAIL: only $compared probe or energy tables to compare"
    status=1
  fi
  echo "compared $compared tables of $what"
  return $status
}
