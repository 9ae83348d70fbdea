#!/usr/bin/env bash
# Installs aerial from BUILD_DIR to a temporary prefix, builds tests/package against the installed
# package (find_package(aerial)) and runs it, and compiles the client's own shaders against the
# installed GLSL (share/aerial/glsl): the package test of CTest (Package.*).
#   tests/package/run.sh BUILD_DIR
set -euo pipefail
build=$1
here="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
cmake -S "$here" -B "$work/client" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/client" >/dev/null
for shader in client_surface.frag client_particle.vert; do
  glslangValidator --quiet --target-env vulkan1.2 -I"$work/prefix/share/aerial/glsl" \
    -o "$work/$shader.spv" "$here/$shader"
  echo "client shader compiled against the installed GLSL: $shader"
done
"$work/client/package_client" "$here/../../examples/atmospheres/earth.toml" "$work/cache"
