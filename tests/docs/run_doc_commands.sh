#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs every texsyn / oiiotool / iinfo / exrinfo / maketx command line shown in ```sh blocks
# of a Markdown file, in order, in a scratch directory with the sample files the docs name
# and texsyn's OIIO plugin on OIIO_LIBRARY_PATH.
# usage: run_doc_commands.sh TEXSYN_EXE PLUGIN_DIR REPO_DIR DOC.md WORK_DIR
set -euo pipefail
texsyn=$1 plugins=$2 repo=$3 doc=$4 work=$5
export OIIO_LIBRARY_PATH="$plugins"
rm -rf "$work" && mkdir -p "$work/bin"
ln -s "$texsyn" "$work/bin/texsyn"
export PATH="$work/bin:$PATH"
unset OCIO TEXSYN_CACHE TEXSYN_CACHE_VERBOSE  # docs/cache.md sets them where it shows them
cd "$work"
cp "$repo/data/samples/rust.png" rust.png
cp "$repo/data/samples/marble_pink.png" marble.png
cp "$repo/data/samples/paper_crinkled.png" paper.png
cp "$repo/data/samples/stucco_yellow.png" stucco.png
cp "$repo/data/samples/grass.png" grass.png
cp "$repo/data/samples/bricks.png" bricks.png
cp "$repo/data/masks/bricks_hole.png" bricks_hole.png
cp "$repo/data/samples/bricks_height.png" "$repo/data/samples/bricks_normal.png" .
cp "$repo/data/samples/flowers.png" flowers.png
cp "$repo/data/samples/wood_grain.png" wood_grain.png
cp "$repo/data/samples/tiles_green.png" tiles.png
cp "$repo/data/samples/weave_green.png" weave.png
cp "$repo/ocio-configs/config.ocio" studio.ocio
cp "$repo/data/meshes/cow.obj" "$repo/data/meshes/torus_uv.obj" "$repo/data/meshes/sphere.obj" .
oiiotool "$repo/data/samples/stucco_yellow.png" -d uint16 -o scan.tif
cp "$repo/data/samples/leaves_autumn.png" leaves.png
cp wood_grain.png wood.png && cp wood_grain.png trim.png
# A plate with its height map, a material set and masks of its size (the bricks' hole), and a
# soft plate: a 64x64 crop of the flowers enlarged 4 times.
oiiotool bricks.png -d half -o plate.exr && oiiotool bricks_height.png -d half -o plate_height.exr
cp bricks.png albedo.png && cp bricks_normal.png normal.png && cp bricks_height.png rough.png
for m in logo logo_mask hole; do cp bricks_hole.png "$m.png"; done
oiiotool flowers.png --cut 64x64+0+0 --resize 256x256 -d half -o soft_plate.exr
mkdir -p build && ln -s "$plugins" build/plugins  # the README's build-tree plugin path

# Extract the commands: inside ```sh fences, lines starting with a tool name, joined with
# their backslash continuations.
awk '
  /^```sh/ { inblock = 1; next }
  /^```/   { inblock = 0; next }
  inblock {
    line = $0
    if (cont != "") { cmd = cmd " " line } else if (line ~ /^([A-Z_]+=[^ ]+ )*(texsyn|oiiotool|iinfo|exrinfo|maketx) /) { cmd = line } else { next }
    if (line ~ /\\$/) { sub(/\\$/, "", cmd); cont = 1; next }
    cont = ""; sub(/[ \t]+#.*$/, "", cmd); print cmd; cmd = ""
  }' "$doc" > commands.txt

count=0
while IFS= read -r cmd; do
  echo "+ $cmd"
  bash -c "$cmd" > /dev/null
  count=$((count + 1))
done < commands.txt
echo "$count commands from $(basename "$doc") ran"
# A page with sh blocks must yield commands (else the extraction broke); pages without any
# (the generated option tables) pass with none.
if grep -q '^```sh' "$doc"; then [ "$count" -gt 0 ]; fi
