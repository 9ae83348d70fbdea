#!/usr/bin/env bash
# Installs aerial from BUILD_DIR to a temporary prefix and compiles each installed header alone
# against it (tests/headers/CMakeLists.txt); also fails where an installed header declares
# something of aerial's implementation namespaces (a forward declaration would compile).
#   tests/headers/run.sh BUILD_DIR
source "$(dirname "$0")/../package/install.sh"
include="$work/prefix/include"
if grep -rnE 'namespace (aerial::)?(vk|bench|viewer|cli|terrain|reference)\b|\b(vk|reference)::' "$include/aerial"; then
  echo "an installed header names aerial's implementation (above)" >&2
  exit 1
fi
cmake -S "$here" -B "$work/build" -G Ninja -DAERIAL_INCLUDE_DIR="$include" >/dev/null
cmake --build "$work/build"
echo "compiled alone: $(cd "$include" && find aerial -name '*.h' | wc -l) installed headers"
