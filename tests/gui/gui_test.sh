#!/usr/bin/env bash
# GUI smoke test: the real MeshLab GUI of the staged prefix starts on its own Xvfb with the
# freshly built plugin and a mesh, shows its window, stays alive, and quits cleanly on Ctrl+Q; the
# four filters are registered (meshlabserver -d dumps the filter list). Keeps a screenshot.
#   gui_test.sh --stage DIR --plugin FILE --mesh FILE --work DIR [--expect-filter NAME]... [--inject crash]
# --expect-filter adds a name to the four checked; --inject crash kills MeshLab with SIGSEGV once
# its window is up (both only to show that the test fails when it should).
# No time limits here: a hang (window never shown, no exit) is caught by the CTest TIMEOUT.
set -euo pipefail

STAGE="" PLUGIN="" MESH="" WORK="" INJECT=""
FILTERS=("Segment by Variational Shape Approximation" "Smooth Region Boundaries"
         "Split Triangles along Front" "Q-Morph Quad Conversion")
while [ "$#" -gt 0 ]; do
  case "$1" in
    --stage) STAGE="$2"; shift 2 ;;
    --plugin) PLUGIN="$2"; shift 2 ;;
    --mesh) MESH="$2"; shift 2 ;;
    --work) WORK="$2"; shift 2 ;;
    --expect-filter) FILTERS+=("$2"); shift 2 ;;
    --inject) INJECT="$2"; shift 2 ;;
    *) echo "gui_test.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
fail() { echo "GUI test FAILED: $*" >&2; exit 1; }
[ -n "$STAGE" ] && [ -n "$PLUGIN" ] && [ -n "$MESH" ] && [ -n "$WORK" ] || fail "--stage, --plugin, --mesh and --work are required"
STAGE="$(realpath -m "$STAGE")" PLUGIN="$(realpath -m "$PLUGIN")" MESH="$(realpath -m "$MESH")" WORK="$(realpath -m "$WORK")"

rm -rf "$WORK"
mkdir -p "$WORK/home"
chmod 700 "$WORK/home"   # also XDG_RUNTIME_DIR, which Qt wants private

# The staged plugin must be the build's (a stale or missing link would test something else).
[ -f "$PLUGIN" ] || fail "no such plugin: $PLUGIN"
staged="$STAGE/lib/x86_64-linux-gnu/meshlab/plugins/$(basename "$PLUGIN")"
[ -e "$staged" ] || fail "the plugin is not staged: $staged"
[ "$(realpath "$staged")" = "$(realpath "$PLUGIN")" ] || fail "$staged is not the build's plugin $PLUGIN"
[ -f "$MESH" ] || fail "no such mesh: $MESH"

ML_PID="" XVFB_PID="" ML_STATUS=""
cleanup() {
  if [ -n "$ML_PID" ] && kill -0 "$ML_PID" 2>/dev/null; then kill -9 "$ML_PID" 2>/dev/null || true; fi
  if [ -n "$XVFB_PID" ]; then kill "$XVFB_PID" 2>/dev/null || true; wait "$XVFB_PID" 2>/dev/null || true; fi
}
trap cleanup EXIT

# Its own X server: the screenshot shows only this MeshLab, and other tests' windows cannot be
# mistaken for it. Xvfb picks a free display (-displayfd).
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$WORK/xvfb.fd" >"$WORK/xvfb.log" 2>&1 </dev/null &
XVFB_PID=$!
while [ ! -s "$WORK/xvfb.fd" ]; do
  kill -0 "$XVFB_PID" 2>/dev/null || fail "Xvfb did not start: $(cat "$WORK/xvfb.log")"
  sleep 0.05
done
export DISPLAY=":$(tr -d '[:space:]' < "$WORK/xvfb.fd")"
export HOME="$WORK/home" XDG_RUNTIME_DIR="$WORK/home"   # private: MeshLab writes its settings there

# 1. Registration: the filter list of the staged meshlabserver names all four filters.
( cd "$WORK" && "$STAGE/bin/meshlabserver" -d filters.txt ) > "$WORK/meshlabserver.log" 2>&1 ||
  fail "meshlabserver -d failed: $(tail -n 5 "$WORK/meshlabserver.log")"
sed -n 's/^\\section f[0-9]* //p' "$WORK/filters.txt" | sed 's/ *$//' > "$WORK/filter_names.txt"
for name in "${FILTERS[@]}"; do
  grep -qxF -- "$name" "$WORK/filter_names.txt" || fail "filter '$name' is not registered (see $WORK/filters.txt)"
done
echo "registered: ${#FILTERS[@]} filters checked among $(wc -l < "$WORK/filter_names.txt")"

# 2. The GUI with a mesh: its main window ("MeshLab 2020.09 - [Project_1]") must appear.
( cd "$WORK" && exec "$STAGE/bin/meshlab" "$MESH" ) > "$WORK/meshlab.log" 2>&1 &
ML_PID=$!
# Waits for meshlab and sets ML_STATUS. Never inside $(...): a subshell cannot wait for its
# parent's child.
reap() { ML_STATUS=0; wait "$ML_PID" || ML_STATUS=$?; ML_PID=""; }
describe() { if [ "$1" -gt 128 ]; then echo "killed by signal $(( $1 - 128 )) ($(kill -l "$(( $1 - 128 ))"))"; else echo "status $1"; fi; }
win=""
while [ -z "$win" ]; do
  if ! kill -0 "$ML_PID" 2>/dev/null; then
    reap
    fail "meshlab exited before its window appeared ($(describe "$ML_STATUS")): $(tail -n 5 "$WORK/meshlab.log")"
  fi
  win="$(xdotool search --onlyvisible --name '^MeshLab ' 2>/dev/null | head -n1 || true)"
  [ -n "$win" ] || sleep 0.2
done
echo "window: $win '$(xdotool getwindowname "$win")'"

# 3. It stays alive a few seconds (rendering the mesh), and it opened the mesh.
sleep 3
if [ "$INJECT" = crash ]; then  # a loaded machine can take more than a moment to end it
  kill -SEGV "$ML_PID"
  for _ in $(seq 150); do kill -0 "$ML_PID" 2>/dev/null || break; sleep 0.2; done  # up to 30 s (a core dump)
fi
if ! kill -0 "$ML_PID" 2>/dev/null; then
  reap
  fail "meshlab crashed after its window appeared ($(describe "$ML_STATUS")): $(tail -n 5 "$WORK/meshlab.log")"
fi
# a loaded machine (ctest -j2 beside the pipelines) can take longer to load and draw: up to 30 s
for _ in $(seq 150); do grep -q "Opened mesh" "$WORK/meshlab.log" && break; sleep 0.2; done
grep -q "Opened mesh" "$WORK/meshlab.log" || fail "meshlab did not report opening $MESH: $(tail -n 5 "$WORK/meshlab.log")"

# 4. Screenshot, kept in the build tree; a blank screen has a handful of colours (taken again for
# up to 30 s while it is: the first frame may still be drawing).
for _ in $(seq 30); do
  xwd -root -silent | convert xwd:- "$WORK/meshlab_gui.png"
  colours="$(convert "$WORK/meshlab_gui.png" -format '%k' info:)"
  [ "$colours" -gt 100 ] && break
  sleep 1
done
[ "$colours" -gt 100 ] || fail "the screenshot looks blank ($colours colours): $WORK/meshlab_gui.png"
echo "screenshot: $WORK/meshlab_gui.png ($colours colours)"

# 5. Quit with Ctrl+Q (File > Exit) and wait for a clean exit.
xdotool windowfocus --sync "$win"
xdotool key --clearmodifiers ctrl+q
reap
[ "$ML_STATUS" = 0 ] || fail "meshlab did not exit cleanly after Ctrl+Q ($(describe "$ML_STATUS")): $(tail -n 5 "$WORK/meshlab.log")"
echo "GUI test passed: window shown, alive, mesh opened, exit status 0"
