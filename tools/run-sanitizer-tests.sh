#!/usr/bin/env bash
# Builds aerial with AddressSanitizer + UndefinedBehaviorSanitizer (clang, ./build-sanitize) and
# runs, under them: every test that needs no GPU, a short list of GPU tests (lavapipe through the
# library and through the command), and each fuzz target over its seeds and regression inputs.
# Any sanitizer report fails the run. Leak reports from the Vulkan driver's own frames are
# suppressed (tools/sanitizers/lsan.supp, each entry justified); a leak in aerial's frames fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DAERIAL_SANITIZE=address,undefined -DAERIAL_FUZZ=ON "${launcher[@]}" >/dev/null
# Only what these tests run: not the offline tools (tools/bench).
cmake --build build-sanitize --parallel "$(nproc)" --target aerial aerial_tests \
  fuzz_atmosphere_toml fuzz_scene_toml fuzz_gltf fuzz_camera_path fuzz_table_cache

export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}
export ASAN_OPTIONS=detect_leaks=1:check_initialization_order=1:strict_init_order=1
export LSAN_OPTIONS=suppressions=$PWD/tools/sanitizers/lsan.supp:print_suppressions=0
# lavapipe stays loaded until exit, so that its leaks are named and suppressed (lsan.supp).
lavapipe=$(ls /usr/lib/*/libvulkan_lvp.so 2>/dev/null | head -1)
export LD_PRELOAD=${lavapipe}
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

# GPU test suites (fixtures on GpuTest, and the command-line tests that render or precompute).
# Everything else runs: the CPU-only tests, and the bad-input tests of the command (hostile files,
# full disks, resource limits), most of which end before the GPU is used.
gpu_suites="Render.*:VdbExport.*:VdbPaths.*:TableCacheIntegration.*:TableSanity.*:PhysicalSky.*"
gpu_suites+=":ViewerToneMap.*:TablesVsReference.*:GraphicsPipelineTest.*:SceneSurfaceRender.*"
gpu_suites+=":ViewerDebugViews.*:LeanFrame.*:Lut3d.*:MappingRoundTrip.*:GoldenImage.*"
gpu_suites+=":Cli.*:ViewCli.*:BenchQuick.*:ViewerSession.*:Exr.*:Png.*:ImageWriter.*"
gpu_suites+=":ShadowRender.*:FroxelShadows.*:Exposure_.*:SpectralTables.*:CpuGpuMappings.*:TableRead.*"
# Likewise the golden images: they are held to 1e-6 of the frames of the main suite's gcc build;
# clang's rounding moves the terrain's vertices, built on the CPU (noon 0.756% off, 2026-11-28).
golden_elsewhere="Render.MatchesGoldenImages"
# The short GPU list: small-table precompute and its cache round trip, one froxel frame, the VDB
# export, and the command end to end (including its errors).
gpu_short="TableSanity.*:TableCacheIntegration.*:Render.*:VdbExport.*:Cli.*"

cd build-sanitize
ctest --output-on-failure --timeout 1500 -R '^fuzz_regressions\.'
AERIAL_VALIDATION=1 AERIAL_CACHE_DIR=$PWD/test-cache ./aerial_tests --gtest_brief=1 \
  --gtest_filter="-$gpu_suites"
AERIAL_VALIDATION=1 AERIAL_CACHE_DIR=$PWD/test-cache ./aerial_tests --gtest_brief=1 \
  --gtest_filter="$gpu_short-$golden_elsewhere"
