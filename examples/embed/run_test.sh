#!/usr/bin/env bash
# The example's test (CTest: Example.EmbedDrawsItsOwnMeshesLikeAerialRender): installs aerial from
# BUILD_DIR to a temporary prefix, builds examples/embed against the installed package with CMake's
# default generator, renders scene.toml with it (validation layers on: any message fails) and with
# `aerial render` from BUILD_DIR, and compares the two frames pixel by pixel.
#   examples/embed/run_test.sh BUILD_DIR
# The tables are cached in $AERIAL_CACHE_DIR (CTest: BUILD_DIR/test-cache), or a temporary one.
set -euo pipefail
build="$(cd "$1" && pwd)"
here="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cache="${AERIAL_CACHE_DIR:-$work/cache}"

# Quiet unless it fails: then its output, which names what failed.
quiet() { "$@" >"$work/log" 2>&1 || { cat "$work/log" >&2; echo "failed: $*" >&2; exit 1; }; }
quiet cmake --install "$build" --prefix "$work/prefix"
# CMake's default generator (no -G), as the README builds it: Unix Makefiles unless CMAKE_GENERATOR
# says otherwise. build_fails_at_shader.sh builds the example with Ninja too.
quiet cmake -S "$here" -B "$work/embed" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix"
quiet cmake --build "$work/embed" --parallel "$(nproc)"

AERIAL_VALIDATION=1 "$work/embed/embed" "$here/scene.toml" "$work/embed.exr" "$cache" 320 180
# The same frame as aerial draws it: the default 4D tables (aerial::PrecomputeOptions::Default()),
# froxel mode on aerial::Froxels' default grid (32x32x32, quadratic to 128 km), no shadow map and
# one sample per pixel, like the example. Only the sky is drawn another way: in froxel mode aerial's sky pass reads a
# per-frame sky-view table (192x108, shaders/include/sky_view.glsl), where the example evaluates
# GetSkyRadianceAlongRay on the tables per pixel. --colour rgb: the example takes the library's
# default tables, whatever the commands' default.
"$build/aerial" render --scene "$here/scene.toml" --width 320 --height 180 --aerial froxel --froxel-reads per-pixel --froxels 32x32x32 \
  --colour rgb --froxel-far-m 128000 --shadows off --supersample 1 --cache-dir "$cache" --quiet --out "$work/aerial.exr"

# Bounds on the largest per-pixel relative error, max_c |a_c - b_c| / max_c b_c:
#  - mesh pixels, 1e-5: both sides run the same code on the same data. The froxel volume is one
#    compute shader on one FrameBlock (MakeFrameUniforms of the same camera); the vertices, the
#    matrix and so the rasterized coverage are the same; the lighting (GetLambertianRadiance per
#    vertex, ShadeLambertian) and the aerial perspective (the froxel read, the phase functions)
#    are the same GLSL functions. Only the compilation of two different shader modules may round
#    differently (e.g. nu from normalize() or from a division, FMA contraction): float rounding,
#    ~1e-7 per operation over a few dozen operations. A real difference (a froxel slice off, a
#    wrong phase or a missed light term) is 1e-3 or more. Measured: 0 (bit-identical).
#  - sky pixels, 1e-2: the sky-view table resamples the same lookups, and aerial holds it within
#    1% of the per-pixel sky (Render.SkyViewTableMatchesPerPixelSky bounds whole frames at 1%
#    relative RMSE, measured 0.05-0.23%). Per pixel it is furthest off on the horizon's row,
#    where the radiance changes fastest with the view's elevation (above, the sky brightens toward
#    the horizon; below, the ground a ray meets recedes to the horizon's distance), faster than
#    the table's rows follow even though they crowd there. That row is 0.26% off here (the sun 60
#    degrees up); a low sun takes it further (0.90% at 10 degrees, 1.5% at 15 degrees ahead of
#    the camera, 4.7% at 2 degrees), which is why the scene keeps the sun high. Measured: relative
#    RMSE 3.9e-4, max 2.6e-3 (on the horizon's row).
"$work/embed/embed_compare" "$work/embed.exr" "$work/aerial.exr" 1e-5 1e-2
