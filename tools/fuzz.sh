#!/usr/bin/env bash
# Fuzzes aerial's input readers with libFuzzer (tests/fuzz), under AddressSanitizer and
# UndefinedBehaviorSanitizer, in ./build-sanitize (clang).
#
#   tools/fuzz.sh [--seconds N] [TARGET...]   fuzz each target N seconds (default 600), in turn;
#                                             all targets when none is named
#   tools/fuzz.sh --replay TARGET BINARY      run BINARY once over TARGET's seeds and regression
#                                             inputs (what CTest does in the sanitizer build)
#
# Targets: atmosphere_toml scene_toml gltf camera_path table_cache. Seeds come from examples/ and
# tests/data/; the corpus grows in build-sanitize/corpus/TARGET. An input that crashes, leaks, hangs
# (10 s) or exhausts memory (2 GiB) is written to tests/fuzz/regressions/TARGET/: fix the bug,
# then commit the input so the replay keeps it fixed. Fuzzing goes on after a finding (fork mode),
# and the last line per target gives runs, runs per second, coverage and findings.
set -euo pipefail
if [[ ${1:-} == --replay ]]; then replay_binary=$(realpath "$3"); fi
cd "$(dirname "$0")/.."
root=$PWD

seed_files() {
  case "$1" in
    atmosphere_toml) ls examples/atmospheres/*.toml tests/data/bad_mie_g.toml tests/data/unknown_key.toml \
         tests/data/huge_rayleigh.toml tests/data/huge_solar_irradiance.toml tests/fuzz/seeds/toml/* ;;
    scene_toml) ls examples/scenes/*.toml tests/data/bad_scene.toml tests/data/huge_*.toml tests/data/hostile/scene_*.toml tests/fuzz/seeds/toml/* ;;
    gltf) ls examples/scenes/*.gltf tests/data/hostile/*.gltf tests/data/hostile/*.glb ;;
    camera_path) ls examples/paths/*.toml tests/data/bad_camera_path.toml tests/data/hostile/camera_path_*.toml tests/fuzz/seeds/toml/* ;;
    table_cache) ls tests/fuzz/seeds/table_cache/* ;;
    *) echo "fuzz.sh: unknown target $1" >&2; exit 2 ;;
  esac
}

# Seeds and regression inputs, gathered in one directory per target.
seed_dir() {
  local dir=$1/seeds/$2
  rm -rf "$dir" && mkdir -p "$dir" "tests/fuzz/regressions/$2"
  for f in $(seed_files "$2"); do cp "$f" "$dir/"; done
  echo "$dir"
}

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

if [[ ${1:-} == --replay ]]; then
  target=$2
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  seeds=$(seed_dir "$work" "$target")
  exec "$replay_binary" -runs=0 -rss_limit_mb=2048 -timeout=10 "$seeds" "tests/fuzz/regressions/$target"
fi

seconds=600
if [[ ${1:-} == --seconds ]]; then seconds=$2; shift 2; fi
targets=("$@")
((${#targets[@]})) || targets=(atmosphere_toml scene_toml gltf camera_path table_cache)

cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DAERIAL_SANITIZE=address,undefined -DAERIAL_FUZZ=ON >/dev/null
cmake --build build-sanitize --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"

for target in "${targets[@]}"; do
  seeds=$(seed_dir build-sanitize "$target")
  mkdir -p "build-sanitize/corpus/$target"
  log=build-sanitize/fuzz-$target.log
  echo "fuzz.sh: $target for $seconds s (log: $log)"
  (cd build-sanitize && tests/fuzz/fuzz_"$target" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
      -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=16384 -print_final_stats=1 \
      -artifact_prefix="$root/tests/fuzz/regressions/$target/" \
      "corpus/$target" "$root/$seeds" "$root/tests/fuzz/regressions/$target") >"$log" 2>&1 || true
  grep -E "^#[0-9]+: cov:|stat::|DONE" "$log" | tail -3
  echo "fuzz.sh: $target findings: $(ls "tests/fuzz/regressions/$target" | wc -l) in tests/fuzz/regressions/$target"
done
