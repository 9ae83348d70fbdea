#!/usr/bin/env bash
# Builds aerial with AddressSanitizer + UndefinedBehaviorSanitizer (clang, ./build-sanitize) and
# runs, under them, the tests chosen by their CTest labels (cmake/TestLabels.cmake): every test
# that needs no GPU (`cpu`), the GPU tests labelled `sanitizer`, and each fuzz target over its seeds and
# regression inputs. Any sanitizer report fails the run. Leak reports from the Vulkan driver's own
# frames are suppressed (tools/sanitizers/lsan.supp, each entry justified); a leak in aerial's
# frames fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DAERIAL_SANITIZE=address,undefined -DAERIAL_FUZZ=ON "${launcher[@]}" \
  -DAERIAL_WARNINGS_AS_ERRORS="${AERIAL_WARNINGS_AS_ERRORS:-OFF}" >/dev/null
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

cd build-sanitize
ctest --output-on-failure --timeout 1500 -R '^fuzz_regressions\.'
ctest --output-on-failure --timeout 1500 -j"$(nproc)" -L '^cpu$'
# Of the GPU tests, those labelled `sanitizer` (cmake/TestLabels.cmake): the ones that fit CI's time
# on two cores under the sanitizers (all of them take about 3,000 s of a core in the Release build,
# several times that here). The high-sun variants' frames and the bench's frames run the frame's
# code as Render's tests do and would add about 440 s of a core here: they are left out.
ctest --output-on-failure --timeout 1500 -j"$(nproc)" -L '^sanitizer$' -LE '^slow$'
