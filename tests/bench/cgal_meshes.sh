#!/usr/bin/env bash
# Closed meshes from Debian's libcgal-demo data (downloaded, never installed) that no test or shared
# benchmark uses: a set kept aside for judging the defaults on inputs they were not tuned on.
#   tests/bench/cgal_meshes.sh OUT_DIR
# then, e.g.:
#   ../shared/tools/quadcheck/acceptance.sh build/mlstage/bin/meshlabserver \
#       filter_qmorph_front/scripts/closed_mesh_to_quads.mlx /tmp/kept OUT_DIR/*.off
set -euo pipefail
OUT=${1:?out dir}
# every closed 2-manifold of the package's data/meshes that is not in ../shared/meshes (checked
# with evalquad: closed_manifold true)
NAMES="bear bones bull cactus camel cheese couplingdown cow cross dino diplodocus dragknob elk femur hand
handle helmet homer knot1 man oblong part pinion refined_elephant retinal rotor spool triceratops turbine
beam tripod"
mkdir -p "$OUT"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && { apt-get download -qq libcgal-demo >/dev/null 2>&1 || apt-get download libcgal-demo; })
dpkg-deb -x "$tmp"/libcgal-demo_*.deb "$tmp/x"
for n in $NAMES; do
  tar -xzf "$tmp/x/usr/share/doc/libcgal-dev/data.tar.gz" -O "data/meshes/$n.off" > "$OUT/$n.off"
done
echo "cgal_meshes: $(echo $NAMES | wc -w) meshes in $OUT"
