# Sourced by the package tests: installs aerial from the build directory $1 to $work/prefix, in a
# temporary directory $work that is removed on exit; $here is the sourcing script's directory.
set -euo pipefail
build=$1
here="$(cd "$(dirname "${BASH_SOURCE[1]}")" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
