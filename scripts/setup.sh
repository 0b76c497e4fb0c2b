#!/usr/bin/env bash
# Set-up for a fresh Debian bookworm machine (idempotent; run as root or with sudo available).
#  1. installs the Debian packages the build, the tests (GUI test too) and the demo need;
#  2. enables source packages by deriving deb-src entries from apt's own entries;
#  3. fetches MeshLab's source package, pinned to the installed binary, into .deps/meshlab-src
#     (git-ignored: only its src/common headers and vcglib are used, nothing is committed);
#  4. extracts test meshes from Debian's libcgal-demo (downloaded, not installed) into .deps/meshes.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
DEPS="$ROOT/.deps"
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive

# MeshLab itself and what the plugin builds against (Qt, OpenGL/GLEW, Eigen for vcglib), the build
# tools, GoogleTest, Xvfb for meshlabserver (xauth for xvfb-run), dpkg-dev and xz-utils for
# `apt-get source`, ca-certificates for apt's https sources.
PACKAGES=(meshlab qtbase5-dev libqt5opengl5-dev libglew-dev libeigen3-dev cmake make g++
          libgtest-dev xvfb xauth dpkg-dev xz-utils ca-certificates
          # demo pictures (f3d renders, imagemagick scales them down, gnuplot draws the histogram)
          f3d imagemagick gnuplot-nox
          # GUI test: find and close the MeshLab window (xdotool), screenshot (xwd; convert to PNG)
          xdotool x11-apps)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

apt_updated=0
apt_update() { if [ "$apt_updated" = 0 ]; then $SUDO apt-get update -qq; apt_updated=1; fi; }

if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  apt_update
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# deb-src entries derived from the existing ones: no host name is written here.
if ! grep -rqs '^Types:.*deb-src\|^deb-src ' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  echo "setup: enabling source packages"
  if [ -f /etc/apt/sources.list.d/debian.sources ]; then
    sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources \
      | $SUDO tee /etc/apt/sources.list.d/debian-src.sources >/dev/null
  fi
  if [ -f /etc/apt/sources.list ] && grep -q '^deb ' /etc/apt/sources.list; then
    sed -n 's/^deb /deb-src /p' /etc/apt/sources.list | $SUDO tee /etc/apt/sources.list.d/debian-src.list >/dev/null
  fi
  apt_updated=0
fi

ML_VERSION="$(dpkg-query -W -f='${Version}' meshlab)"
ML_SRC="$DEPS/meshlab-src"
if [ ! -f "$ML_SRC/.version" ] || [ "$(cat "$ML_SRC/.version")" != "$ML_VERSION" ]; then
  echo "setup: fetching the meshlab $ML_VERSION source package"
  apt_update
  rm -rf "$DEPS/meshlab-dl" "$ML_SRC"
  mkdir -p "$DEPS/meshlab-dl"
  (cd "$DEPS/meshlab-dl" && apt-get source -qq "meshlab=$ML_VERSION" >/dev/null 2>&1 \
     || apt-get source "meshlab=$ML_VERSION")
  tree="$(find "$DEPS/meshlab-dl" -mindepth 1 -maxdepth 1 -type d -name 'meshlab-*' | head -n1)"
  [ -d "$tree/vcglib" ] && [ -d "$tree/src/common" ] || { echo "setup: unexpected source tree $tree" >&2; exit 1; }
  # keep only what the build uses: src/common headers (+ src for <common/...>) and vcglib
  mkdir -p "$ML_SRC/src"
  mv "$tree/src/common" "$ML_SRC/src/common"
  mv "$tree/vcglib" "$ML_SRC/vcglib"
  rm -rf "$DEPS/meshlab-dl"
  echo "$ML_VERSION" > "$ML_SRC/.version"
fi

# Real test meshes from Debian's libcgal-demo data (downloaded, never installed).
MESHES="$DEPS/meshes"
if [ ! -f "$MESHES/.done" ] || [ ! -f "$MESHES/man.off" ]; then
  echo "setup: extracting test meshes from libcgal-demo"
  apt_update
  rm -rf "$DEPS/cgal-dl"; mkdir -p "$DEPS/cgal-dl" "$MESHES"
  (cd "$DEPS/cgal-dl" && apt-get download -qq libcgal-demo >/dev/null 2>&1 || apt-get download libcgal-demo)
  dpkg-deb -x "$DEPS"/cgal-dl/libcgal-demo_*.deb "$DEPS/cgal-dl/x"
  tar -xzf "$DEPS/cgal-dl/x/usr/share/doc/libcgal-dev/data.tar.gz" -C "$DEPS/cgal-dl" \
      data/meshes/fandisk.off data/meshes/elephant.off data/meshes/joint.off data/meshes/anchor.off \
      data/meshes/armadillo.off data/meshes/diplodocus.off data/meshes/femur.off data/meshes/man.off
  mv "$DEPS"/cgal-dl/data/meshes/*.off "$MESHES/"
  rm -rf "$DEPS/cgal-dl"
  touch "$MESHES/.done"
fi
echo "setup: ok (meshlab $ML_VERSION, sources in $ML_SRC, meshes in $MESHES)"
