#!/usr/bin/env bash
# The benchmark (an extra command, not part of the test command):
#   scripts/bench.sh [--with-cgal] [qmf_bench arguments...]
#
#  1. set-up (scripts/setup.sh, idempotent);
#  2. with --with-cgal: installs Debian's libcgal-dev (for the VSA comparison with CGAL) when missing;
#  3. configures build-bench/ (Release, -DQMF_BUILD_BENCH=ON -DQMF_BUILD_TESTS=OFF) and builds qmf_bench;
#  4. runs it (default: the pipeline on fandisk, rocker_arm_3356, rocker_arm_20k, bunny_3k, elephant,
#     casting from ../shared/meshes when that folder exists, else the meshes set-up extracted into
#     .deps/meshes; plus the ~1M-face cases: armadillo refined x4 and x16, fandisk x64, by midpoint
#     subdivision), writes out/bench/report.md and prints it (about 4 minutes on 2 cores).
# Arguments after the flags go to qmf_bench (e.g. `--big none`, `--meshes DIR`, mesh names;
# `build-bench/tests/bench/qmf_bench --help`). BUILD_DIR overrides build-bench/, JOBS the build jobs.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build-bench}"
JOBS="${JOBS:-$(nproc 2>/dev/null || echo 2)}"
OUT_DIR="$ROOT/out/bench"

WITH_CGAL=0
if [ "${1:-}" = "--with-cgal" ]; then WITH_CGAL=1; shift; fi

"$ROOT/scripts/setup.sh"

if [ "$WITH_CGAL" = 1 ] && ! dpkg-query -W -f='${Status}' libcgal-dev 2>/dev/null | grep -q "install ok installed"; then
  SUDO=""
  if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
  echo "bench: installing libcgal-dev (CGAL comparison)"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends libcgal-dev >/dev/null
fi

cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DQMF_BUILD_BENCH=ON -DQMF_BUILD_TESTS=OFF >/dev/null
cmake --build "$BUILD_DIR" --target qmf_bench -j "$JOBS"

mkdir -p "$OUT_DIR"
"$BUILD_DIR/tests/bench/qmf_bench" --out "$OUT_DIR/report.md" "$@" >/dev/null
echo
cat "$OUT_DIR/report.md"
echo
echo "bench: report written to $OUT_DIR/report.md"
