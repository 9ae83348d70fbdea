#!/usr/bin/env bash
# Renders every built-in preset into docs/gallery/PRESET.png (480x270) and rewrites the gallery
# table at the top of README.md (between the "gallery:begin" and "gallery:end" markers) to show
# them, so the README's gallery is what the current build draws.
#
#   bash tools/make-gallery.sh              # every preset below, with ./build/aerial
#   AERIAL=/path/to/aerial bash tools/make-gallery.sh
#   bash tools/make-gallery.sh noon sunset  # re-render only these
#
# The README's table shows every preset of the list below that has an image in docs/gallery/.
# A preset the binary does not know fails the script (aerial's own error message, exit status 1):
# the gallery is either every preset or an error, never a silent gap.
set -euo pipefail
cd "$(dirname "$0")/.."

# The built-in presets, in the order the gallery shows them (src/aerial/scene/presets.cpp).
all_presets=(noon afternoon sunset sunrise evening twilight high-altitude)

aerial=${AERIAL:-./build/aerial}
width=${GALLERY_WIDTH:-480}
height=${GALLERY_HEIGHT:-270}
columns=4
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-/tmp}

if [[ ! -x "$aerial" ]]; then
  echo "make-gallery: $aerial is not an executable; build it first (bash tools/build.sh) or set AERIAL" >&2
  exit 1
fi

presets=("$@")
if [[ ${#presets[@]} -eq 0 ]]; then presets=("${all_presets[@]}"); fi

mkdir -p docs/gallery
for preset in "${presets[@]}"; do
  echo "make-gallery: $preset"
  "$aerial" render --quiet --preset "$preset" --width "$width" --height "$height" \
    --out "docs/gallery/$preset.png"
done

# The README's table: the presets of all_presets that have an image, $columns to a row, each
# image under its name.
shown=()
for p in "${all_presets[@]}"; do
  if [[ -f "docs/gallery/$p.png" ]]; then shown+=("$p"); fi
done
table=$(mktemp)
trap 'rm -f "$table"' EXIT
{
  echo "<!-- gallery:begin (made by tools/make-gallery.sh; do not edit by hand) -->"
  for ((row = 0; row < ${#shown[@]}; row += columns)); do
    header="|" rule="|" images="|"
    for ((i = row; i < row + columns && i < ${#shown[@]}; ++i)); do
      p=${shown[i]}
      header+=" \`$p\` |"
      rule+="---|"
      images+=" ![$p](docs/gallery/$p.png) |"
    done
    if ((row > 0)); then echo; fi
    echo "$header"
    echo "$rule"
    echo "$images"
  done
  echo "<!-- gallery:end -->"
} >"$table"

if ! grep -q '^<!-- gallery:begin' README.md || ! grep -q '^<!-- gallery:end -->' README.md; then
  echo "make-gallery: README.md has no gallery markers; the table was not written" >&2
  exit 1
fi
awk -v table="$table" '
  /^<!-- gallery:begin/ { while ((getline line < table) > 0) print line; skip = 1; next }
  /^<!-- gallery:end -->/ { skip = 0; next }
  !skip { print }
' README.md >README.md.tmp
mv README.md.tmp README.md
echo "make-gallery: wrote docs/gallery/*.png and the README's gallery table"
