#!/usr/bin/env bash
# The main job on the built-in defaults: install, build, precompute the "earth" tables (cached),
# render the default scene to out/aerial-noon.png and .exr, and print a probe of the noon sky
# from the same (spectral) tables.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
bash tools/build.sh
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
mkdir -p out
./build/aerial precompute
./build/aerial render --timings --out out/aerial-noon.png
./build/aerial render --out out/aerial-noon.exr
echo "wrote out/aerial-noon.png and out/aerial-noon.exr"
echo "noon sky, looking 45 degrees up, across the sun's direction:"
./build/aerial probe --altitude-m 0 --view-zenith-deg 45 --sun-zenith-deg 20 --azimuth-deg 90 --distance-m 10000
