#!/usr/bin/env bash
# The test command: set-up (idempotent), build, and the whole suite through CTest; then the unit
# and plugin tests (the bounded fuzz run among them) again under AddressSanitizer and
# UndefinedBehaviorSanitizer (CTest names Sanitizer.*, label "sanitizer").
#   scripts/test.sh [extra ctest arguments]
# Builds in build/ and build-sanitize/ (override with BUILD_DIR=... and SANITIZE_BUILD_DIR=...;
# QMF_SKIP_SANITIZE=1 skips the sanitizer run). .ci/run calls exactly this.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$ROOT/build}"
SANITIZE_BUILD_DIR="${SANITIZE_BUILD_DIR:-$ROOT/build-sanitize}"
JOBS="$(nproc 2>/dev/null || echo 2)"

"$ROOT/scripts/setup.sh"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DQMF_BUILD_TESTS=ON >/dev/null
cmake --build "$BUILD_DIR" -j "$JOBS"
(cd "$BUILD_DIR" && ctest --output-on-failure -j "$JOBS" "$@")

if [ "${QMF_SKIP_SANITIZE:-0}" != 1 ]; then
  echo "== unit and plugin tests under AddressSanitizer + UndefinedBehaviorSanitizer ($SANITIZE_BUILD_DIR)"
  cmake -S "$ROOT" -B "$SANITIZE_BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DQMF_BUILD_TESTS=ON -DQMF_SANITIZE=ON >/dev/null
  cmake --build "$SANITIZE_BUILD_DIR" -j "$JOBS" --target unit_tests plugin_tests
  (cd "$SANITIZE_BUILD_DIR" && ctest --output-on-failure -j "$JOBS" -L sanitizer)
fi
