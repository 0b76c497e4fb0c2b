#!/usr/bin/env bash
# The main job: set-up (idempotent), build the plugin, run the whole pipeline through the real
# meshlabserver on a mesh (default: fandisk, extracted from Debian's libcgal-demo at set-up) and
# write the results and a short report into out/<mesh>/.
#   scripts/demo.sh [mesh.off|mesh.ply|mesh.obj|mesh.stl]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
JOBS="$(nproc 2>/dev/null || echo 2)"

"$ROOT/scripts/setup.sh" >/dev/null
MESH="$(realpath "${1:-$ROOT/.deps/meshes/fandisk.off}")"
[ -f "$MESH" ] || { echo "demo: no such mesh: $MESH" >&2; exit 1; }
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS" --target filter_qmorph_front >/dev/null

NAME="$(basename "${MESH%.*}")"
OUT="$ROOT/out/$NAME"
mkdir -p "$OUT/home"
SCRIPT="$ROOT/filter_qmorph_front/scripts/vsa_segment.mlx"
start=$(date +%s%N)
# Private HOME: meshlabserver writes its config there, not into the user's.
( cd "$OUT" && HOME="$OUT/home" xvfb-run -a "$BUILD_DIR/mlstage/bin/meshlabserver" \
    -i "$MESH" -o "$OUT/regions.ply" -m fq fc -s "$SCRIPT" > "$OUT/meshlabserver.log" 2>&1 ) || {
  echo "demo: meshlabserver failed, see $OUT/meshlabserver.log" >&2; tail -n 20 "$OUT/meshlabserver.log" >&2; exit 1; }
end=$(date +%s%N)
[ -s "$OUT/regions.ply" ] || { echo "demo: no output written, see $OUT/meshlabserver.log" >&2; exit 1; }

{
  echo "mesh:    $MESH"
  echo "script:  $SCRIPT"
  # the filters' log lines ("LOG: <level> <text>")
  sed -n 's/^LOG: [0-9] /log:     /p' "$OUT/meshlabserver.log" || true
  echo "wall:    $(( (end - start) / 1000000 )) ms (meshlabserver start-up included)"
  echo "output:  $OUT/regions.ply (face quality = region id, face colour = region)"
} | tee "$OUT/report.txt"
