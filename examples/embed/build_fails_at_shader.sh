#!/usr/bin/env bash
# CTest: Example.EmbedBuildStopsAtAFailedShader. Installs aerial from BUILD_DIR to a temporary
# prefix and builds copies of examples/embed against it that cannot compile a shader, with CMake's
# default generator and with Ninja:
#  - a GLSL error in shaders/sky.frag: glslangValidator reports it with the file and line;
#  - a header that cannot be written (the build's shaders/ folder replaced by a file):
#    glslangValidator prints "Failed to open file" and exits 0, and the check after it
#    (cmake/CheckShaderOutput.cmake) must fail the command, naming the shader.
# Each build must fail at that shader, before any of the program's C++ is compiled (so the user
# sees the shader's error, not a C++ error about the missing header). Then, with Ninja, the folder
# is put back and the same build must complete.
#   examples/embed/build_fails_at_shader.sh BUILD_DIR
set -euo pipefail
build="$(cd "$1" && pwd)"
here="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Quiet unless it fails: then its output.
quiet() { "$@" >"$work/log" 2>&1 || { cat "$work/log" >&2; echo "failed: $*" >&2; exit 1; }; }
quiet cmake --install "$build" --prefix "$work/prefix"
cp -r "$here" "$work/good"
cp -r "$here" "$work/broken"
echo 'vec3 broken_on_purpose = undeclared_on_purpose;' >>"$work/broken/shaders/sky.frag"

generators=(default)
if command -v ninja >/dev/null; then generators+=(Ninja); fi

# expect_failure NAME LOG PATTERN: the build whose output is LOG failed (checked by the caller),
# its output matches PATTERN, and no object of the program (CMakeFiles/embed.dir) was compiled.
expect_failure() {
  if ! grep -Eq "$3" "$2"; then
    cat "$2" >&2
    echo "$1: the build's output does not match '$3'" >&2
    exit 1
  fi
  if grep -q 'CMakeFiles/embed\.dir/.*\.o' "$2"; then
    cat "$2" >&2
    echo "$1: the build went on to the program's C++ after a failed shader" >&2
    exit 1
  fi
  echo "$1: failed at the shader: $(grep -Em1 "$3" "$2")"
}

for generator in "${generators[@]}"; do
  g=()
  if [ "$generator" != default ]; then g=(-G "$generator"); fi

  b="$work/broken-$generator"
  quiet cmake -S "$work/broken" -B "$b" "${g[@]}" -DCMAKE_PREFIX_PATH="$work/prefix"
  if cmake --build "$b" --parallel 2 >"$b.log" 2>&1; then
    echo "$generator, GLSL error: the build succeeded" >&2
    exit 1
  fi
  expect_failure "$generator, GLSL error" "$b.log" 'ERROR: .*sky\.frag:[0-9]+:'

  b="$work/unwritable-$generator"
  quiet cmake -S "$work/good" -B "$b" "${g[@]}" -DCMAKE_PREFIX_PATH="$work/prefix"
  rm -rf "$b/shaders" && touch "$b/shaders"
  if cmake --build "$b" --parallel 2 >"$b.log" 2>&1; then
    echo "$generator, unwritable header: the build succeeded" >&2
    exit 1
  fi
  expect_failure "$generator, unwritable header" "$b.log" \
    '/shaders/[a-z]+\.(vert|frag): wrote no .*/shaders/[a-z_]+\.h'

  if [ "$generator" = Ninja ]; then
    rm "$b/shaders" && mkdir "$b/shaders"
    quiet cmake --build "$b" --parallel 2
    echo "$generator: the build completes once the folder is back"
  fi
done
