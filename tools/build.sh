#!/usr/bin/env bash
# Configures and builds aerial (Release) into ./build. ccache is used when it is installed.
set -euo pipefail
cd "$(dirname "$0")/.."
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# AERIAL_WARNINGS_AS_ERRORS=ON in the environment (CI sets it) makes every warning an error.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
  -DAERIAL_WARNINGS_AS_ERRORS="${AERIAL_WARNINGS_AS_ERRORS:-OFF}" >/dev/null
cmake --build build --parallel "$(nproc)"
