#!/usr/bin/env bash
# The main job: set-up (idempotent), build the plugin and qmf_report, run the four filters through
# the real meshlabserver, one call per step (the shipped scripts cut into steps, default
# parameters), and write the results, a report and pictures into out/<mesh>/.
#   scripts/demo.sh [mesh.off|mesh.ply|mesh.obj|mesh.stl]     (default: fandisk from .deps/meshes)
# Environment: BUILD_DIR (default build/), OUT_ROOT (default out/), QMF_VIEW="azimuth,elevation" (the
# overall pictures' view in degrees, +Y up; default: the view that shows most of the regions).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
OUT_ROOT="${OUT_ROOT:-$ROOT/out}"
JOBS="$(nproc 2>/dev/null || echo 2)"
SCRIPTS="$ROOT/filter_qmorph_front/scripts"

[ "$#" -le 1 ] || { echo "usage: scripts/demo.sh [mesh.off|.ply|.obj|.stl]" >&2; exit 2; }
fail() { echo "demo: $*" >&2; exit 1; }

setup_log="$(mktemp)"
"$ROOT/scripts/setup.sh" > "$setup_log" 2>&1 || { cat "$setup_log" >&2; rm -f "$setup_log"; fail "set-up failed"; }
rm -f "$setup_log"

MESH="${1:-$ROOT/.deps/meshes/fandisk.off}"
[ -f "$MESH" ] || fail "no such mesh: $MESH"
MESH="$(realpath -s "$MESH")"   # -s: keep the path the user knows (no symlinks resolved)
case "$(echo "${MESH##*.}" | tr '[:upper:]' '[:lower:]')" in
  off|ply|obj|stl) ;;
  *) fail "not an OFF, PLY, OBJ or STL file: $MESH" ;;
esac
NAME="$(basename "$MESH")"; NAME="${NAME%.*}"
case "$NAME" in ""|.|..) NAME=mesh ;; esac
OUT="$OUT_ROOT/$NAME"
SHOWN="${MESH#"$ROOT"/}"   # the input as the report names it: relative to the repository when inside
RUN="$OUT/run"   # per-step scripts, meshlabserver logs, private HOME, picture scenes

echo "demo: building the plugin and qmf_report in $BUILD_DIR"
build_log="$BUILD_DIR/demo-build.log"
mkdir -p "$BUILD_DIR"
{ cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo &&
  cmake --build "$BUILD_DIR" -j "$JOBS" --target filter_qmorph_front qmf_report; } > "$build_log" 2>&1 ||
  { tail -n 30 "$build_log" >&2; fail "build failed, see $build_log"; }
ML="$BUILD_DIR/mlstage/bin/meshlabserver"
REPORT_TOOL="$BUILD_DIR/tools/qmf_report/qmf_report"

rm -rf "$OUT"
mkdir -p "$RUN/home" "$RUN/render"

# One X server for every meshlabserver and f3d call of the run (xvfb-run per call costs more);
# Xvfb picks a free display itself (-displayfd); -noreset, or a call made while the server resets
# after the previous one left fails to connect.
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$RUN/xvfb.fd" >"$RUN/xvfb.log" 2>&1 </dev/null &
XVFB_PID=$!
trap 'kill "$XVFB_PID" 2>/dev/null || true' EXIT
for _ in $(seq 1 100); do [ -s "$RUN/xvfb.fd" ] && break; sleep 0.05; done
[ -s "$RUN/xvfb.fd" ] || fail "Xvfb did not start: $(cat "$RUN/xvfb.log")"
export DISPLAY=":$(tr -d '[:space:]' < "$RUN/xvfb.fd")"

# Per-step scripts: each shipped script runs the pipeline from the start, so take one filter block
# out of it (its default parameters unchanged).
filter_block() {
  local block; block="$(sed -n "/<filter name=\"$1\">/,/<\/filter>/p" "$2")"
  [ -n "$block" ] || fail "no filter '$1' in $2"
  printf '%s\n' "$block"
}
step_script() {  # step_script OUT.mlx BLOCK...
  local out="$1"; shift
  { echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'; printf '%s\n' "$@"; echo '</FilterScript>'; } > "$out"
}
# (assignments: a missing block stops the demo under set -e, an argument would not)
VSA_BLOCK="$(filter_block "Segment by Variational Shape Approximation" "$SCRIPTS/vsa_segment.mlx")"
SMOOTH_BLOCK="$(filter_block "Smooth Region Boundaries" "$SCRIPTS/smooth_boundaries.mlx")"
SPLIT_BLOCK="$(filter_block "Split Triangles along Front" "$SCRIPTS/split_along_front.mlx")"
# relative export path: meshlabserver runs in $OUT, so no path needs escaping for XML or sed
QMORPH_BLOCK="$(filter_block "Q-Morph Quad Conversion" "$SCRIPTS/qmorph.mlx" |
  sed 's|name="ExportPath" value=""|name="ExportPath" value="quads.obj"|')"
step_script "$RUN/step1.mlx" "$VSA_BLOCK"
step_script "$RUN/step2.mlx" "$SMOOTH_BLOCK"
# Step 3 re-runs step 2 in memory (milliseconds) instead of reading front.obj back: MeshLab's OBJ
# writer keeps 6 decimals, and the split along rounded curves can end in slightly different quads
# than the whole-pipeline script gives. The step's figures are the Split filter's own.
step_script "$RUN/step3.mlx" "$SMOOTH_BLOCK" "$SPLIT_BLOCK"
step_script "$RUN/step4.mlx" "$QMORPH_BLOCK"
grep -q 'value="quads.obj"' "$RUN/step4.mlx" || fail "no ExportPath parameter in $SCRIPTS/qmorph.mlx"

STEP_NAMES=("" "Segment by Variational Shape Approximation" "Smooth Region Boundaries"
            "Split Triangles along Front" "Q-Morph Quad Conversion")
now_ms() { echo $(( $(date +%s%N) / 1000000 )); }
progress() { printf '[%3d%%] step %d/4 %s: %s\n' "$(( ($1 - 1) * 25 + $2 ))" "$1" "${STEP_NAMES[$1]}" "$3"; }
LOG_PREFIX=("" "VSA:" "Smooth Region Boundaries:" "Split Triangles along Front:" "Q-Morph")
# the step's own filter log lines (meshlabserver prints them as "LOG: <level> <text>")
log_lines() { sed -n 's/^LOG: [0-9]* //p' "$RUN/step$1.log" | grep -F -- "${LOG_PREFIX[$1]}" || true; }
# the filter's own time: the first "<seconds> s" ending a clause of its log
filter_seconds() { log_lines "$1" | grep -oE '[0-9]+\.[0-9]+ s(;|$)' | head -n1 | grep -oE '[0-9]+\.[0-9]+' || echo "?"; }
summary() {
  local s
  case "$1" in
    1) s="$(log_lines 1 | sed -n 's/^VSA: \([0-9]* regions on [0-9]* faces\).*/\1/p')" ;;
    2) s="$(log_lines 2 | sed -n 's/^Smooth Region Boundaries: \([0-9]* curves ([0-9]* closed loops), [0-9]* corners\).*/\1/p')" ;;
    3) s="$(log_lines 3 | sed -n 's/^Split Triangles along Front: .*; \([0-9]* vertices and [0-9]* faces added\); \([0-9]* front edges selected; [0-9]* patches\).*/\2, \1/p')" ;;
    4) s="$(log_lines 4 | sed -n 's/^Q-Morph: [0-9]* patches.*; \([0-9]* quads, [0-9]* triangles left ([^)]*)\).*/\1/p')" ;;
  esac
  echo "${s:-see run/step$1.log}"
}
declare -a WALL_MS
run_step() {  # run_step N OUTPUT_FILE... -- MESHLABSERVER_ARGS...
  local n="$1"; shift
  local outputs=()
  while [ "$1" != "--" ]; do outputs+=("$1"); shift; done
  shift
  progress "$n" 0 "running"
  local t0; t0="$(now_ms)"
  # private HOME: meshlabserver writes its settings there, not into the user's; the C locale:
  # Qt takes the user's, and a comma-decimal one would change the log figures read below
  if ! ( cd "$OUT" && HOME="$RUN/home" XDG_RUNTIME_DIR="$RUN/home" LC_ALL=C "$ML" "$@" ) > "$RUN/step$n.log" 2>&1; then
    progress "$n" 0 "FAILED, see $RUN/step$n.log"
    log_lines "$n" >&2
    tail -n 5 "$RUN/step$n.log" >&2
    exit 1
  fi
  WALL_MS[$n]=$(( $(now_ms) - t0 ))
  for f in "${outputs[@]}"; do
    [ -s "$OUT/$f" ] || { progress "$n" 0 "FAILED: $f was not written, see $RUN/step$n.log"; exit 1; }
  done
  progress "$n" 25 "$(summary "$n") (filter $(filter_seconds "$n") s, meshlabserver call $(( WALL_MS[$n] )) ms)"
}

# Debian's meshlabserver 2020.09 aborts on any OBJ with faces (an assertion in its OBJ importer,
# Debian bug #1054006): an OBJ input goes in as a PLY written by qmf_report.
ML_INPUT="$MESH"
if [ "$(echo "${MESH##*.}" | tr '[:upper:]' '[:lower:]')" = obj ]; then
  ML_INPUT="$RUN/input.ply"
  "$REPORT_TOOL" --convert "$MESH" "$ML_INPUT" || fail "cannot convert $MESH to PLY"
  echo "demo: OBJ input converted to $ML_INPUT for meshlabserver"
fi

run_step 1 regions.ply -- -i "$ML_INPUT" -s "$RUN/step1.mlx" -o regions.ply -m fq fc
run_step 2 front.obj -- -i regions.ply -s "$RUN/step2.mlx" -o front.obj -l 1
run_step 3 split.ply -- -i regions.ply -s "$RUN/step3.mlx" -o split.ply -m ff fq fc
run_step 4 quads_polygonal.ply quads.obj -- -i split.ply -s "$RUN/step4.mlx" -o quads_polygonal.ply -m ff fq fc

# Quality tables, per-quad scaled Jacobians and the picture scenes, from the product's own code.
PICTURE_SIZE=1200x900
( cd "$OUT" && "$REPORT_TOOL" --input "$MESH" --split split.ply --quads quads_polygonal.ply --quads-obj quads.obj \
    --regions regions.ply --front front.obj --jacobians scaled_jacobian.dat --render-dir run/render --resolution "$PICTURE_SIZE" --supersample 2 \
    ${QMF_VIEW:+--view "$QMF_VIEW"} ) \
  > "$RUN/quality.md" 2> "$RUN/qmf_report.log" || { cat "$RUN/qmf_report.log" >&2; fail "qmf_report failed"; }

# Pictures: f3d renders each scene (two at a time; the overall quads one at twice the size, scaled
# down here: its edges are often thinner than a pixel), then the picture is brightened (f3d 1.3's
# lights leave a white surface facing the camera at about 55% grey; no option changes that); 256
# colours keep the files small, -strip drops the timestamps (the same picture, the same file).
render() {
  local view="$1" args
  mapfile -t args < "$RUN/render/$view.args"
  f3d "$RUN/render/$view.ply" "${args[@]}" --output="$OUT/$view.png" > "$RUN/render/$view.log" 2>&1 &&
    convert "$OUT/$view.png" -resize "$PICTURE_SIZE>" -level 0%,62% -modulate 100,125 +dither -colors 256 -strip "$OUT/$view.png"
}
PICTURES=(regions front quads closeup)
pids=()
for view in "${PICTURES[@]}"; do
  render "$view" & pids+=($!)
  if [ "${#pids[@]}" -ge 2 ]; then wait "${pids[0]}" || fail "rendering failed, see $RUN/render/"; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p" || fail "rendering failed, see $RUN/render/"; done

# Histogram of the scaled Jacobian (log scale: most quads are near 1, the tail is what matters).
TITLE="$(printf '%s' "$NAME" | tr -c 'A-Za-z0-9 _.+-' '_')"
QUADS="$(grep -c '^[-0-9]' "$OUT/scaled_jacobian.dat" || true)"
HISTOGRAM=""
[ "$QUADS" -gt 0 ] && HISTOGRAM=scaled_jacobian.png   # no quads, no histogram
[ -z "$HISTOGRAM" ] || ( cd "$OUT" && gnuplot ) > "$RUN/gnuplot.log" 2>&1 <<EOF || fail "gnuplot failed, see $RUN/gnuplot.log"
set terminal pngcairo size 1000,560 font "DejaVu Sans,12"
set output 'scaled_jacobian.png'
stats 'scaled_jacobian.dat' using 1 nooutput
w = 0.02
bin(x) = w * floor(x / w) + w / 2
set title "$TITLE: scaled Jacobian of the $QUADS quads"
set xlabel "scaled Jacobian (1 = square corners)"
set ylabel "quads (log scale)"
set logscale y
set yrange [0.8:*]
set xrange [(STATS_min < 0 ? STATS_min : 0):1.02]
set boxwidth w * 0.9
set style fill solid 0.85 noborder
set grid ytics
set arrow from 0.3, graph 0 to 0.3, graph 1 nohead dashtype 2 linecolor rgb "#c0392b" linewidth 2
set label "0.3" at 0.31, graph 0.92 textcolor rgb "#c0392b"
plot 'scaled_jacobian.dat' using (bin(\$1)):(1.0) smooth frequency with boxes linecolor rgb "#3b6ea8" notitle
EOF

# report.md
total_filter="$(for n in 1 2 3 4; do filter_seconds "$n"; done | awk '{ if ($1 != "?") s += $1 } END { printf "%.3f", s }')"
total_wall=$(( WALL_MS[1] + WALL_MS[2] + WALL_MS[3] + WALL_MS[4] ))
{
  echo "# $NAME: closed triangle mesh to quads"
  echo
  echo "Input \`$SHOWN\`; the four filters of \`filter_qmorph_front\` with default parameters, one"
  echo "meshlabserver call per step (\`run/step<n>.mlx\`, cut from the shipped scripts). Written by"
  echo "\`scripts/demo.sh\` on $(date -u '+%Y-%m-%d %H:%M UTC') with MeshLab $(dpkg-query -W -f='${Version}' meshlab 2>/dev/null || echo '?')."
  echo
  echo "## Steps"
  echo
  echo "| step | filter | filter time | meshlabserver call | result |"
  echo "|:--|:--|--:|--:|:--|"
  for n in 1 2 3 4; do
    echo "| $n/4 | ${STEP_NAMES[$n]} | $(filter_seconds "$n") s | ${WALL_MS[$n]} ms | $(summary "$n") |"
  done
  echo "| | **total** | **$total_filter s** | **$total_wall ms** | |"
  echo
  echo "Filter time: the filter's own figure from its log; a meshlabserver call includes start-up, loading and saving."
  echo "The filters' log lines (\`LOG:\` lines of meshlabserver):"
  echo
  for n in 1 2 3 4; do
    echo "$n. ${STEP_NAMES[$n]}"
    log_lines "$n" | sed 's/^/   - /'
  done
  echo
  cat "$RUN/quality.md"
  echo
  echo "## Pictures"
  echo
  echo "Regions of step 1 (one colour per region, adjacent regions differ; dark lines where the region changes):"
  echo
  echo "![regions](regions.png)"
  echo
  echo "Front of step 2: the smoothed curves (red) over the regions, with the jagged region boundaries they replace (blue):"
  echo
  echo "![front curves](front.png)"
  echo
  echo "Quad mesh of step 4: quad edges dark, the initial front red, quads below 0.3 scaled Jacobian yellow, triangles orange:"
  echo
  echo "![quads](quads.png)"
  echo
  echo "Close-up where the front meets the rows of quads:"
  echo
  echo "![close-up](closeup.png)"
  echo
  if [ -n "$HISTOGRAM" ]; then echo "![scaled Jacobian histogram](scaled_jacobian.png)"; else echo "No quads, so no scaled-Jacobian histogram."; fi
  echo
  echo "## Files"
  echo
  echo "| file | what |"
  echo "|:--|:--|"
  echo "| \`quads.obj\` | the quad mesh with real 4-vertex faces (Q-Morph's *Export quads to*) |"
  echo "| \`quads_polygonal.ply\` | MeshLab's polygonal form (\`-m ff fq fc\`): quads as triangle pairs with a faux diagonal, the front as selected face-edges (face flags), region id in the face quality |"
  echo "| \`regions.ply\` | step 1: region id in the face quality, a colour per region |"
  echo "| \`front.obj\` | step 2: the smoothed region boundaries (polylines, OBJ \`l\` lines) |"
  echo "| \`split.ply\` | step 3: the mesh split along the front, front edges selected (face flags), region ids |"
  echo "| \`scaled_jacobian.dat\` | scaled Jacobian per quad, in the face order of \`quads.obj\` |"
  echo "| \`run/\` | per-step scripts and meshlabserver logs, picture scenes (PLY + f3d options) |"
} > "$OUT/report.md"

echo "demo: $OUT/report.md (pipeline: filters $total_filter s, meshlabserver calls $total_wall ms)"
echo "demo: pictures $(for v in "${PICTURES[@]}"; do printf '%s.png ' "$v"; done)$HISTOGRAM"
