#!/usr/bin/env bash
# Instructions executed by the pipeline, for A/B comparisons of speed work (an extra command, not
# part of the test command):
#   scripts/bench_instructions.sh [--meshes DIR] MESH [QMF_BENCH ...]
#
# Wall times on a shared 2-core machine move by 15-30% between identical runs, more than most
# single optimisations gain; the instructions counted by valgrind's callgrind (Debian's `valgrind`,
# installed when missing) move by well under 0.1%. Each qmf_bench binary given (default: the one
# scripts/bench.sh builds, build-bench/tests/bench/qmf_bench; copy a binary aside before rebuilding
# to compare two versions) runs the whole pipeline once on MESH in one process (all threads
# counted together), and a table gives millions of instructions: the whole run, and the stages
# (inclusive: a function and everything it calls). Counts are not times (cache misses are not
# counted), so a change that cuts instructions still needs a timing; one that does not is not
# worth one. About 50x slower than a plain run: a mesh of 20k faces takes ~5 minutes.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
MESH_DIR=""
if [ "${1:-}" = "--meshes" ]; then MESH_DIR="$2"; shift 2; fi
if [ $# -lt 1 ]; then
  echo "usage: $0 [--meshes DIR] MESH [QMF_BENCH ...]" >&2
  exit 2
fi
MESH="$1"
shift
BINARIES=("$@")
if [ ${#BINARIES[@]} -eq 0 ]; then BINARIES=("$ROOT/build-bench/tests/bench/qmf_bench"); fi
for b in "${BINARIES[@]}"; do
  if [ ! -x "$b" ]; then
    echo "bench_instructions: $b is not an executable (scripts/bench.sh builds build-bench/tests/bench/qmf_bench)" >&2
    exit 2
  fi
done
if ! command -v valgrind >/dev/null || ! command -v callgrind_annotate >/dev/null; then
  SUDO=""
  if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
  echo "bench_instructions: installing valgrind"
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends valgrind >/dev/null
fi
MESH_ARGS=()
if [ -n "$MESH_DIR" ]; then MESH_ARGS=(--meshes "$MESH_DIR"); fi

# stage name | a function whose inclusive count is the stage's (extended regular expression on
# callgrind_annotate's function names; patch work on pool threads is summed over the threads)
STAGES=(
  "VSA|VSASegmentation<[^>]*>::SegmentHere\("
  "boundary smoothing|RegionBoundarySmoothing<[^>]*>::SmoothHere\("
  "split along the front|PolylineEmbedding<[^>]*>::Embed\("
  "Q-Morph: re-meshing (calling thread)|qmorph::FeatureRemesh<[^>]*>::Do\("
  "Q-Morph: patches (all threads)|qmorph::PatchMesher::Run\("
  "  of which node moves rated|qmorph::PatchStage::WorstQualityIfMoved\("
  "closest-point searches (input surface)|(TriangleGrid<[^>]*>::Closest<|vcg::GridClosest<[^>]*>, vcg_ext::InputSurface)"
  "evaluation (benchmark only)|qmf_test::OneSidedDistance\("
)

WORK="$(mktemp -d)"
trap 'rm -rf "$WORK"' EXIT
i=0
for b in "${BINARIES[@]}"; do
  echo "bench_instructions: $b on $MESH ..." >&2
  valgrind --tool=callgrind --callgrind-out-file="$WORK/cg.$i" "$b" "${MESH_ARGS[@]}" --repeats 1 --no-cgal \
    --no-bitquad --big none --no-fork "$MESH" >"$WORK/log.$i" 2>&1 || {
    echo "bench_instructions: the run failed; its log:" >&2
    tail -n 20 "$WORK/log.$i" >&2
    exit 1
  }
  callgrind_annotate --inclusive=yes --threshold=100 "$WORK/cg.$i" >"$WORK/annotate.$i" 2>/dev/null
  i=$((i + 1))
done

millions() { awk -v n="$1" 'BEGIN { printf "%.0f", n / 1e6 }'; }
# the largest inclusive count of a function matching the pattern (a function listed once per
# thread it ran on is listed once, summed, by callgrind_annotate)
count_of() {
  grep -E "$2" "$1" | head -n 1 | awk '{ gsub(",", "", $1); print $1 }'
}

header="| stage (millions of instructions) |"
rule="|:--|"
for b in "${BINARIES[@]}"; do
  header="$header $(basename "$(dirname "$b")")/$(basename "$b") |"
  rule="$rule--:|"
done
echo
echo "instructions executed on $MESH (valgrind --tool=callgrind, one run each)"
echo
echo "$header"
echo "$rule"
row="| whole run |"
for ((k = 0; k < ${#BINARIES[@]}; ++k)); do
  total=$(count_of "$WORK/annotate.$k" "PROGRAM TOTALS")
  row="$row $(millions "${total:-0}") |"
done
echo "$row"
for stage in "${STAGES[@]}"; do
  name="${stage%%|*}"
  pattern="${stage#*|}"
  row="| $name |"
  for ((k = 0; k < ${#BINARIES[@]}; ++k)); do
    c=$(count_of "$WORK/annotate.$k" "$pattern")
    row="$row $(millions "${c:-0}") |"
  done
  echo "$row"
done
