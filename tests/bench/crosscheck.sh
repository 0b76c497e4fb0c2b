#!/usr/bin/env bash
# Benchmark-side cross-check (not in the test command): the shipped whole-pipeline script through the
# staged meshlabserver on each mesh, the filter's own logged figures (flipped faces, folded quads,
# quads, triangles) next to an independent judge's (evalquad from ../shared/tools/quadcheck).
#   tests/bench/crosscheck.sh OUT_DIR [--remesh PERCENT] MESH.ply ...
# --remesh P sets TargetEdgeLength to P % of each mesh's bounding-box diagonal (0: off, the default).
# Needs scripts/test.sh to have built the staged prefix (build/mlstage) and evalquad built
# (../shared/tools/quadcheck/build.sh, default /tmp/quadcheck-build; QUADCHECK_BUILD overrides).
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
MLS="${MLS:-$ROOT/build/mlstage/bin/meshlabserver}"
EVAL="${QUADCHECK_BUILD:-/tmp/quadcheck-build}/evalquad"
OUT="${1:?out dir}"; shift
PERCENT=0
if [ "${1:-}" = "--remesh" ]; then PERCENT="$2"; shift 2; fi
mkdir -p "$OUT"
printf '%-16s %8s %7s %6s | %-22s | %-34s | %s\n' mesh quads tris wall "filter: flipped folded" "evalquad: flipped folded hd% chi" "elements/expected"
for m in "$@"; do
  name="$(basename "${m%.*}")"
  "$EVAL" "$m" "$m" --samples 1000 > "$OUT/$name.ref.json" 2>/dev/null
  read -r diag area chi_in < <(python3 -c "import json;d=json.load(open('$OUT/$name.ref.json'));print(d['ref_bbox_diag'],d['area'],d['euler_characteristic'])")
  L=$(python3 -c "print($diag*$PERCENT/100)")
  sed "s/name=\"TargetEdgeLength\" value=\"[^\"]*\"/name=\"TargetEdgeLength\" value=\"$L\"/" \
    "$ROOT/filter_qmorph_front/scripts/closed_mesh_to_quads.mlx" > "$OUT/$name.mlx"
  start=$(date +%s.%N)
  xvfb-run -a "$MLS" -i "$m" -o "$OUT/$name.ply" -m ff fq -s "$OUT/$name.mlx" > "$OUT/$name.log" 2>&1
  wall=$(python3 -c "print('%.1f' % ($(date +%s.%N) - $start))")
  "$EVAL" "$m" "$OUT/$name.ply" > "$OUT/$name.json" 2>/dev/null || echo '{}' > "$OUT/$name.json"
  logged=$(grep -o 'flipped faces: [0-9]*, folded quads: [0-9]*' "$OUT/$name.log" | tail -1 | sed 's/[a-z:,]//g')
  python3 - "$OUT/$name.json" "$name" "$wall" "$logged" "$area" "$L" "$chi_in" <<'PY'
import json, sys
e = json.load(open(sys.argv[1])); name, wall, logged, area, L, chi = sys.argv[2:8]
L = float(L); expected = float(area) / (L * L) if L > 0 else 0
elements = e.get('quads', 0) + e.get('tris', 0) / 2
ratio = '%.2f' % (elements / expected) if expected else '-'
print('%-16s %8s %7s %6s | %-22s | %-34s | %s' % (name, e.get('quads'), e.get('tris'), wall + 's', logged.strip(),
      '%s %s %.3f %s%s' % (e.get('inverted_faces'), e.get('folded_quads'), 100 * e.get('hd_sym_max', 9),
      e.get('euler_characteristic'), '' if str(e.get('euler_characteristic')) == chi and e.get('closed_manifold') else ' (TOPOLOGY)'), ratio))
PY
done
