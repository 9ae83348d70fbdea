#!/usr/bin/env bash
# The main job on the built-in defaults: install, build, precompute the "earth" tables (cached)
# and print a probe of the noon sky.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
bash tools/build.sh
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
./build/aerial precompute
echo "noon sky, looking 45 degrees up toward the sun's side:"
./build/aerial probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 20 --azimuth-deg 90 --distance-m 10000
