#!/usr/bin/env bash
# Installs aerial from BUILD_DIR to a temporary prefix, builds tests/package against the installed
# package (find_package(aerial)) and runs it, and compiles the client's own shaders against the
# installed GLSL (share/aerial/glsl): the package test of CTest (Package.*).
#   tests/package/run.sh BUILD_DIR
source "$(dirname "$0")/install.sh"
# Only the public API is installed: no header of aerial's implementation (src/).
for internal in vk precompute render froxel; do
  if [ -e "$work/prefix/include/aerial/$internal" ] || [ -e "$work/prefix/include/$internal" ]; then
    echo "an implementation directory was installed: $internal" >&2
    exit 1
  fi
done
echo "public headers installed: $(cd "$work/prefix/include" && find aerial -name '*.h' | sort | tr '\n' ' ')"
# A Debug client of a Release aerial: the public headers use Vulkan's C API only, so build types
# (NDEBUG) need not match.
cmake -S "$here" -B "$work/client" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/client" >/dev/null
# The installed GLSL lives in the client's shaders: each macro it defines starts with AERIAL_.
foreign_macros=$(grep -rhE '^[[:space:]]*#[[:space:]]*define[[:space:]]' "$work/prefix/share/aerial/glsl" |
  sed -E 's/^[[:space:]]*#[[:space:]]*define[[:space:]]+([A-Za-z0-9_]+).*/\1/' | grep -v '^AERIAL_' || true)
if [ -n "$foreign_macros" ]; then
  echo "the installed GLSL defines macros without the AERIAL_ prefix: $foreign_macros" >&2
  exit 1
fi
for shader in client_surface.frag client_particle.vert client_own_names.frag; do
  glslangValidator --quiet --target-env vulkan1.2 -I"$work/prefix/share/aerial/glsl" \
    -o "$work/$shader.spv" "$here/$shader"
  echo "client shader compiled against the installed GLSL: $shader"
done
"$work/client/package_client" "$here/../../examples/atmospheres/earth.toml" "$work/cache"
