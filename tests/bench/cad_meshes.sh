#!/usr/bin/env bash
# Closed CAD tessellations from Debian packages (downloaded, never installed) that no test or shared
# benchmark uses: a second set kept aside, of machined parts, a thin-walled part and coarse STL
# exports, for judging the defaults on CAD input they were not tuned on.
#   tests/bench/cad_meshes.sh OUT_DIR
# then, e.g.:
#   ../shared/tools/quadcheck/acceptance.sh build/mlstage/bin/meshlabserver \
#       filter_qmorph_front/scripts/closed_mesh_to_quads.mlx /tmp/cad OUT_DIR/*.off
set -euo pipefail
OUT=${1:?out dir}
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# package: path in it of each STL that is a closed 2-manifold once its corners are merged (checked
# with evalquad: closed_manifold true); the others of these packages have holes or non-manifold edges
FILES="occt-misc:usr/share/opencascade/data/stl/TR12J_OCC.stl
occt-misc:usr/share/opencascade/data/stl/sh1.stl
occt-misc:usr/share/opencascade/data/stl/sh2.stl
occt-misc:usr/share/opencascade/data/stl/shape.stl
netgen-doc:usr/share/doc/netgen/examples/hinge.stl
netgen-doc:usr/share/doc/netgen/examples/part1.stl
gmsh-doc:usr/share/doc/gmsh-doc/doc/gmsh/tutorial/t13_data.stl.gz
gmsh-doc:usr/share/doc/gmsh-doc/doc/gmsh/demos/simple_geo/sphere-surf.stl.gz"
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for pkg in occt-misc netgen-doc gmsh-doc; do
  (cd "$tmp" && { apt-get download -qq "$pkg" >/dev/null 2>&1 || apt-get download "$pkg"; })
  dpkg-deb -x "$tmp/${pkg}"_*.deb "$tmp/x"
done
n=0
while IFS=: read -r pkg path; do
  name=$(basename "${path%.gz}" .stl)
  src="$tmp/x/$path"
  if [[ $path == *.gz ]]; then gzip -dc "$src" > "$tmp/$name.stl"; src="$tmp/$name.stl"; fi
  python3 "$HERE/stl_to_off.py" "$src" "$OUT/$name.off"
  n=$((n + 1))
done <<< "$FILES"
echo "cad_meshes: $n meshes in $OUT"
