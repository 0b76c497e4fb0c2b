#!/usr/bin/env bash
# Regenerates the README's demo pictures in docs/: scripts/demo.sh on a CAD part (fandisk) and a
# scan (armadillo, seen from the front: QMF_VIEW), then copies their pictures and reports.
#   scripts/docs_pictures.sh
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT_ROOT="${OUT_ROOT:-$ROOT/out}"
export OUT_ROOT

"$ROOT/scripts/demo.sh" "$ROOT/.deps/meshes/fandisk.off"
QMF_VIEW=180,20 "$ROOT/scripts/demo.sh" "$ROOT/.deps/meshes/armadillo.off"

for mesh in fandisk armadillo; do
  for picture in regions front quads closeup scaled_jacobian; do
    cp "$OUT_ROOT/$mesh/$picture.png" "$ROOT/docs/demo_${mesh}_$picture.png"
  done
done
echo "docs_pictures: docs/demo_{fandisk,armadillo}_{regions,front,quads,closeup,scaled_jacobian}.png"
