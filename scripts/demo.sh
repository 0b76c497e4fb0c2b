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
rm -rf "$OUT"
mkdir -p "$OUT/home"
# The shipped whole-pipeline script, with Q-Morph's export path pointing into the output folder.
sed "s|name=\"ExportPath\" value=\"\"|name=\"ExportPath\" value=\"$OUT/quads.obj\"|" \
    "$ROOT/filter_qmorph_front/scripts/closed_mesh_to_quads.mlx" > "$OUT/pipeline.mlx"
start=$(date +%s%N)
# Private HOME: meshlabserver writes its config there, not into the user's.
( cd "$OUT" && HOME="$OUT/home" xvfb-run -a "$BUILD_DIR/mlstage/bin/meshlabserver" -i "$MESH" -s "$OUT/pipeline.mlx" \
    -o "$OUT/quads_polygonal.ply" -m ff fq fc -o "$OUT/front.obj" -l 1 > "$OUT/meshlabserver.log" 2>&1 ) || {
  echo "demo: meshlabserver failed, see $OUT/meshlabserver.log" >&2; tail -n 20 "$OUT/meshlabserver.log" >&2; exit 1; }
end=$(date +%s%N)
for f in quads.obj quads_polygonal.ply front.obj; do
  [ -s "$OUT/$f" ] || { echo "demo: $f was not written, see $OUT/meshlabserver.log" >&2; exit 1; }
done
if command -v f3d >/dev/null 2>&1; then  # a picture when Debian's f3d is installed (optional)
  xvfb-run -a -s "-screen 0 1280x1024x24" f3d "$OUT/quads.obj" --output="$OUT/quads.png" --resolution=1000,800 -e \
    --camera-azimuth-angle=40 --camera-elevation-angle=30 >/dev/null 2>&1 || true
fi

{
  echo "mesh:    $MESH"
  echo "script:  filter_qmorph_front/scripts/closed_mesh_to_quads.mlx (default parameters)"
  # the filters' log lines ("LOG: <level> <text>")
  sed -n 's/^LOG: [0-9] /log:     /p' "$OUT/meshlabserver.log" || true
  echo "wall:    $(( (end - start) / 1000000 )) ms (meshlabserver start-up included)"
  echo "outputs: $OUT/quads.obj (real quads)"
  echo "         $OUT/quads_polygonal.ply (MeshLab's polygonal form: faux diagonals and selected front in the face flags, region id in the face quality)"
  echo "         $OUT/front.obj (the smoothed region boundaries, layer 1)"
  [ -s "$OUT/quads.png" ] && echo "         $OUT/quads.png"
} | tee "$OUT/report.txt"
