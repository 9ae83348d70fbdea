#!/usr/bin/env bash
# Installs, builds and runs the whole test suite (validation layers on in every GPU test).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
bash tools/build.sh
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
cd build
# As many tests at once as there are cores (the slow end-to-end bench starts first: its COST).
ctest --output-on-failure --timeout 1500 -j"$(nproc)"
