#!/usr/bin/env bash
# Checks mfwave as an installed package (docs/install.md), from a build folder that is already
# built (CI: build/release after scripts/run-tests.sh):
#   1. `cmake --install` into a fresh prefix gives the programs, the libraries, the headers under
#      include/mfwave, the CMake package and share/mfwave (scenes, reference tables, plot scripts);
#   2. examples/consumer configures against that prefix alone (find_package(mfwave 0.2)), builds,
#      runs, and prints the probe value the in-tree build of the same source prints;
#   3. CPack makes the Debian package; unpacked into a clean root (dpkg -x), its lamb3d runs the main
#      study at one spacing with no --scene (its shipped scene) and writes a summary.json that names
#      the version and the git revision.
# Usage: bash scripts/check-install.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$(pwd)
build=$(realpath "${1:-build/release}")
work=$(mktemp -d /tmp/mfwave-check-install.XXXXXX)
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
unset MFWAVE_DATA_DIR  # the programs must find their data by themselves

fail() { echo "check-install: FAILED: $*" >&2; exit 1; }
step() { echo "check-install: $(date -u +%T) $*"; }
[ -f "$build/CMakeCache.txt" ] || fail "$build is not a configured build folder (run scripts/run-tests.sh first)"
[ -x "$build/drivers/lamb3d" ] || fail "$build/drivers/lamb3d is not built (run scripts/run-tests.sh first)"

step "1. cmake --install $build --prefix $work/prefix"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
prefix=$work/prefix
for f in bin/lamb3d bin/wavefield bin/stability include/mfwave/io/run/RunSummary.hpp \
         include/mfwave/methods/very_weak_sph/VeryWeakSph.hpp include/mfwave/core/Types.hpp \
         lib/cmake/mfwave/mfwaveConfig.cmake lib/cmake/mfwave/mfwaveConfigVersion.cmake \
         lib/cmake/mfwave/mfwaveTargets.cmake lib/cmake/mfwave/FindSuiteSparse.cmake \
         share/mfwave/data/scenes/lamb3d.toml share/mfwave/data/reference/luo2011-table1-rkcm-critical-dt.csv \
         share/mfwave/analysis/plot_lamb3d.py share/mfwave/analysis/tradeoff/__main__.py; do
  [ -e "$prefix/$f" ] || fail "the install has no $f"
done
libraries=$(find "$prefix/lib" -name 'libmfwave_*.a' | wc -l)
[ "$libraries" -ge 20 ] || fail "expected one static library per lib/ folder, found $libraries"
[ -z "$(find "$prefix/include" -type l)" ] || fail "the installed headers include symbolic links (build-tree links)"
if grep -rqF -e "$source_dir" -e "$build" "$prefix/lib/cmake/mfwave"; then
  fail "the installed CMake package names the source or build folder: $(grep -rlF -e "$source_dir" -e "$build" "$prefix/lib/cmake/mfwave")"
fi
echo "  $(find "$prefix/bin" -type f | wc -l) programs, $libraries libraries, $(find "$prefix/include" -name '*.hpp' | wc -l) headers, $(find "$prefix/share/mfwave" -type f | wc -l) shared files"

step "2. examples/consumer against the installed package"
generator=()
command -v ninja > /dev/null && generator=(-G Ninja)
cmake -S examples/consumer -B "$work/consumer" "${generator[@]}" -DCMAKE_PREFIX_PATH="$prefix" \
  > "$work/consumer-configure.log" 2>&1 || { cat "$work/consumer-configure.log"; fail "configuring examples/consumer"; }
cmake --build "$work/consumer" > "$work/consumer-build.log" 2>&1 || { cat "$work/consumer-build.log"; fail "building examples/consumer"; }
installed=$(timeout 120 "$work/consumer/consumer") || fail "the consumer exited with $?"
echo "$installed" | sed 's/^/  /'
value=$(echo "$installed" | sed -n 's/^probe top_centre v_z = //p')
[ -n "$value" ] || fail "the consumer printed no probe value"
# The same source built in-tree (tests/examples) is the reference: the installed headers and
# libraries must give the same number.
if [ -x "$build/tests/examples/example_consumer" ]; then
  reference=$(timeout 120 "$build/tests/examples/example_consumer" | sed -n 's/^probe top_centre v_z = //p')
  /usr/bin/python3 -c "import sys; a, b = float(sys.argv[1]), float(sys.argv[2]); sys.exit(abs(a - b) > 1e-9 * abs(b))" \
    "$value" "$reference" || fail "the installed consumer prints $value, the in-tree build $reference"
  echo "  matches the in-tree build ($reference)"
else
  # Without the tests built: the figure the in-tree test holds it to (tests/examples/CMakeLists.txt).
  /usr/bin/python3 -c "import sys; sys.exit(abs(float(sys.argv[1]) - 2.61246e-02) > 1e-5 * 2.61246e-02)" "$value" \
    || fail "the installed consumer prints $value, not 2.61246e-02 (tests/examples/CMakeLists.txt)"
  echo "  matches the measured figure 2.61246e-02 (no in-tree build of the example in $build/tests/examples)"
fi

step "3. cpack -G DEB, unpacked with dpkg -x into a clean root"
(cd "$build" && cpack -G DEB -B "$work/package" > "$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; fail "cpack -G DEB"; }
deb=$(find "$work/package" -maxdepth 1 -name 'mfwave_*.deb' | head -1)
[ -n "$deb" ] || fail "cpack made no mfwave_*.deb in $work/package"
echo "  $(basename "$deb"), $(du -h "$deb" | cut -f1)"
depends=$(dpkg-deb -f "$deb" Depends)
[ -n "$depends" ] || fail "the package lists no dependencies"
echo "  Depends: $depends"
dpkg -x "$deb" "$work/root"
lamb3d=$work/root/usr/bin/lamb3d
[ -x "$lamb3d" ] || fail "the package has no usr/bin/lamb3d"
"$lamb3d" --version | sed 's/^/  /'
mkdir -p "$work/run" && cd "$work/run"  # away from the source tree: the scene must come from the package
start=$(date +%s)
timeout 600 "$lamb3d" --set 'study.spacings=[0.5]' --out "$work/run/lamb3d" > "$work/lamb3d.log" 2>&1 \
  || { cat "$work/lamb3d.log"; fail "lamb3d from the package exited with $?"; }
grep -q "shipped scene $work/root/usr/share/mfwave/data/scenes/lamb3d.toml" "$work/lamb3d.log" \
  || { cat "$work/lamb3d.log"; fail "lamb3d did not run the package's shipped scene"; }
grep -q "plot: /usr/bin/python3 $work/root/usr/share/mfwave/analysis/plot_lamb3d.py" "$work/lamb3d.log" \
  || { cat "$work/lamb3d.log"; fail "lamb3d did not name the package's plot script"; }
grep -E '^galerkin_0.5 |centre_relative_l2|plot:' "$work/lamb3d.log" | sed 's/^/  /'
/usr/bin/python3 - "$work/run/lamb3d/summary.json" <<'PY' || fail "summary.json of the packaged lamb3d"
import json, sys
s = json.load(open(sys.argv[1]))
if not s.get("mfwave_version") or not s.get("git_revision"):
    raise SystemExit("summary.json names no mfwave_version or git_revision")
if not s.get("cases"):
    raise SystemExit("summary.json has no cases")
print("  summary.json: mfwave", s["mfwave_version"], "git", s["git_revision"], "cases", [c["case"] for c in s["cases"]])
PY
echo "  lamb3d from the package: $(( $(date +%s) - start )) s"
step "all install checks passed"
