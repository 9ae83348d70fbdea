#!/usr/bin/env bash
# Installs the Debian 12 packages aerial builds and runs with, skipping those already present.
# Run as root (or with sudo available). Safe to run again.
set -euo pipefail

packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config
  # Vulkan: loader, headers (vulkan.hpp), lavapipe, validation layers, GLSL -> SPIR-V
  libvulkan-dev mesa-vulkan-drivers vulkan-validationlayers glslang-tools spirv-tools
  # libraries
  libglm-dev libglfw3-dev libx11-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
  libopenvdb-dev libboost-iostreams-dev libtbb-dev libopenexr-dev libstb-dev
  libimgui-dev libtinygltf-dev libxxhash-dev libcairo2-dev fonts-dejavu-core
  liberfa-dev libhowardhinnant-date-dev tzdata
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth python3-openvdb python3-openimageio
  # sanitizer and fuzzing builds (tools/run-sanitizer-tests.sh, tools/fuzz.sh): clang, its
  # runtimes (ASan, UBSan, libFuzzer) and llvm-symbolizer for readable reports
  clang libclang-rt-dev llvm
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "setup: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
