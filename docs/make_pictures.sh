#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates the pictures in docs/images with the tool itself.
# usage: docs/make_pictures.sh BUILD/oiiotool-ext/texsyn [surfaces|fill|materials|patch]
# (with `surfaces`, only docs/surfaces.md's pictures; they need povray: apt-get install -y povray;
# with `fill`, `materials` or `patch`, only docs/fill.md's, docs/materials.md's, or
# docs/patch.md's and docs/which-method.md's)
set -euo pipefail
texsyn=$(realpath "$1")
cd "$(dirname "$0")"
samples=../data/samples
out=images
mkdir -p "$out"
unset OCIO
# One row: SAMPLE, then --patch, --neighborhood and --pyramid at 320x320 (seed 1), as OUT.
three_methods() { # SAMPLE OUT
  "$texsyn" --seed 1 "$1" --patch:size=320x320 -o "$out/pp_patch.png"
  "$texsyn" --seed 1 "$1" --neighborhood:size=320x320 -o "$out/pp_nb.png"
  "$texsyn" --seed 1 "$1" --pyramid:size=320x320 -o "$out/pp_pyr.png"
  oiiotool "$1" "$out/pp_patch.png" "$out/pp_nb.png" "$out/pp_pyr.png" --mosaic:pad=4 4x1 -o "$2"
}
# docs/patch.md: the three methods on the structured samples; docs/which-method.md: one
# sample and result per case.
patch_pictures() {
  for s in bricks tiles_green weave_green wood_grain flowers; do
    three_methods "$samples/$s.png" "$out/patch_$s.png"
  done
  # Small samples (128x128: a crop of the tiles, the marble as bundled): the defaults tune
  # themselves to them as to the large ones.
  for s in tiles_green marble_pink; do
    oiiotool "$samples/$s.png" --cut 128x128+0+0 -o "$out/pp_small.png"
    three_methods "$out/pp_small.png" "$out/patch_small_$s.png"
  done
  "$texsyn" --seed 1 "$samples/leaves_autumn.png" --patch:size=384x384 -o "$out/pp_f.png"
  oiiotool "$samples/leaves_autumn.png" "$out/pp_f.png" --mosaic:pad=4 2x1 -o "$out/which_small.png"
  "$texsyn" --seed 1 "$samples/bricks.png" --patch:size=320x320:repetition=0 -o "$out/pp_r0.png"
  "$texsyn" --seed 1 "$samples/bricks.png" --patch:size=320x320 -o "$out/pp_r05.png"
  "$texsyn" --seed 1 "$samples/bricks.png" --patch:size=320x320:repetition=2 -o "$out/pp_r2.png"
  oiiotool "$out/pp_r0.png" "$out/pp_r05.png" "$out/pp_r2.png" --mosaic:pad=4 3x1 \
      -o "$out/patch_repetition.png"
  "$texsyn" --seed 1 "$samples/rust.png" --pyramid:size=256x256 -o "$out/pp_a.png"
  "$texsyn" --seed 1 "$samples/grass.png" --neighborhood:size=256x256 -o "$out/pp_b.png"
  "$texsyn" --seed 1 "$samples/bricks.png" --patch:size=256x256 -o "$out/pp_c.png"
  "$texsyn" --seed 1 "$samples/leaves_autumn.png" --choosy:size=256x256 -o "$out/pp_d.png"
  "$texsyn" --seed 1 --cascade:preset=stone:size=256x256 -o "$out/pp_e.png"
  oiiotool "$samples/rust.png" "$out/pp_a.png" --mosaic:pad=4 2x1 -o "$out/which_stochastic.png"
  oiiotool "$samples/grass.png" "$out/pp_b.png" --mosaic:pad=4 2x1 -o "$out/which_foliage.png"
  oiiotool "$samples/bricks.png" "$out/pp_c.png" --mosaic:pad=4 2x1 -o "$out/which_structured.png"
  oiiotool "$samples/leaves_autumn.png" "$out/pp_d.png" --mosaic:pad=4 2x1 \
      -o "$out/which_histogram.png"
  oiiotool "$out/pp_e.png" -o "$out/which_no_sample.png"
  rm -f "$out"/pp_*
}
# docs/surfaces.md: --choosy-surface (seed 1) written as .ply and rendered with POV-Ray by
# render_surface.py at 480x360, each beside its sample (shown 2x, nearest, on the renders'
# grey) or beside the render it is compared with.
surface_pictures() {
  command -v povray >/dev/null || { echo "make_pictures.sh: needs povray (apt-get install -y povray)" >&2; exit 1; }
  local meshes=../data/meshes tmp
  tmp=$(mktemp -d)
  grow() { # SAMPLE MESH OPTIONS NAME [render_surface.py options...]
    local t0=$SECONDS
    "$texsyn" --seed 1 "$samples/$1.png" --choosy-surface:mesh="$meshes/$2.obj$3" -o "$tmp/$4.ply"
    echo "$4: texsyn $((SECONDS - t0)) s"
    python3 render_surface.py "$tmp/$4.ply" "$tmp/$4.png" --size 480x360 "${@:5}"
  }
  beside() { # SAMPLE RENDER OUT: the sample at 2x on a 480x360 grey cell, then the render
    oiiotool "$samples/$1.png" --resize:filter=box 256x256 \
        --pattern constant:color=0.93,0.93,0.93 480x360 3 --paste +112+52 "$tmp/$2.png" \
        --mosaic:pad=4 2x1 -d uint8 -o "$out/$3.png"
  }
  grow flowers sphere ":levels=4" sphere_flowers --view 1,0.6,1.6
  beside flowers sphere_flowers surface_sphere_flowers
  grow stucco_yellow cow ":levels=4:remesh=6000" cow_stucco --view 0.6,0.35,1
  beside stucco_yellow cow_stucco surface_cow_stucco
  grow pebbles cow ":levels=4:remesh=6000" cow_pebbles --view 0.6,0.35,1
  beside pebbles cow_pebbles surface_cow_pebbles
  grow pebbles cow ":levels=4:remesh=0" cow_pebbles_raw --view 0.6,0.35,1
  oiiotool "$tmp/cow_pebbles_raw.png" "$tmp/cow_pebbles.png" --mosaic:pad=4 2x1 -d uint8 \
      -o "$out/surface_cow_remesh.png"
  grow leaves_autumn mushroom ":levels=4" mushroom_leaves --view 1,0.7,0.5 --up 0,0,1
  beside leaves_autumn mushroom_leaves surface_mushroom_leaves
  grow marble_pink knot ":levels=4" knot_marble --view 0.3,0.4,1
  beside marble_pink knot_marble surface_knot_marble
  # The flat grid seen from above (--unlit: the face colours themselves; 256 pixels across
  # its 256x256 squares at levels=3), as it is and remeshed, beside --choosy at 256x256 with
  # isotropic=1 (the image counterpart of the six rotations); the middle 192x192 of each.
  grow pebbles plane_grid ":levels=3:remesh=0" plane_pebbles --size 272x272 --view 0,0,1 \
      --fov 8 --unlit
  grow pebbles plane_grid ":levels=3" plane_remesh --size 272x272 --view 0,0,1 --fov 8 --unlit
  "$texsyn" --seed 1 "$samples/pebbles.png" --choosy:size=256x256:levels=3:isotropic=1 \
      -o "$tmp/choosy.png"
  oiiotool "$tmp/plane_pebbles.png" --cut 192x192+40+40 "$tmp/plane_remesh.png" --cut 192x192+40+40 \
      "$tmp/choosy.png" --cut 192x192+32+32 --mosaic:pad=4 3x1 -d uint8 \
      -o "$out/surface_plane_choosy.png"
  rm -rf "$tmp"
}
# docs/fill.md: a hole cut into a bundled sample (black), filled by OIIO's push-pull (the
# baseline) and by --fill (seed 1), shown 2x; the masks are blobs made with oiiotool (boxes,
# blurred, thresholded). Then --tileable.
fill_pictures() {
  local tmp
  tmp=$(mktemp -d)
  blob() { # SIZE BOX1 BOX2 OUT
    oiiotool --create "$1" 1 --box:color=1:fill=1 "$2" --box:color=1:fill=1 "$3" --blur 25x25 \
        --subc 0.5 --mulc 1000 --clamp:min=0:max=1 -d uint8 -o "$4"
  }
  one() { # SAMPLE MASK NAME
    "$texsyn" --seed 1 "$samples/$1.png" --fill:mask="$2" -o "$tmp/filled.png"
    oiiotool "$2" --mulc -1 --addc 1 --ch 0,0,0 "$samples/$1.png" --mul -o "$tmp/holed.png"
    oiiotool "$samples/$1.png" --ch R,G,B,A=1 "$2" --mulc -1 --addc 1 --ch 0,0,0,0 --mul \
        --fillholes --ch R,G,B -o "$tmp/pushpull.png"
    oiiotool "$tmp/holed.png" "$tmp/pushpull.png" "$tmp/filled.png" --mosaic:pad=4 3x1 \
        --resize:filter=box 200% -d uint8 -o "$out/fill_$3.png"
  }
  one bricks ../data/masks/bricks_hole.png bricks
  blob 256x256 60,80,140,150 90,60,120,180 "$tmp/tiles_hole.png"
  one tiles_green "$tmp/tiles_hole.png" tiles
  blob 128x128 50,15,75,100 40,45,90,65 "$tmp/wood_hole.png"
  one wood_grain "$tmp/wood_hole.png" wood
  # A soft plate: a 64x64 crop of flowers enlarged 8 times, a 96x96 hole; the hole, the fill
  # with outline=copy (exact copies: the outline shows), with outline=match (the default).
  oiiotool "$samples/flowers.png" --cut 64x64+0+0 --resize 512x512 -o "$tmp/soft.png"
  oiiotool --create 512x512 1 --box:color=1:fill=1 208,208,303,303 -d uint8 -o "$tmp/soft_hole.png"
  "$texsyn" --seed 1 "$tmp/soft.png" --fill:mask="$tmp/soft_hole.png":outline=copy -o "$tmp/copy.png"
  "$texsyn" --seed 1 "$tmp/soft.png" --fill:mask="$tmp/soft_hole.png" -o "$tmp/match.png"
  oiiotool "$tmp/soft_hole.png" --mulc -1 --addc 1 --ch 0,0,0 "$tmp/soft.png" --mul -o "$tmp/holed.png"
  oiiotool "$tmp/holed.png" --cut 256x256+128+128 "$tmp/copy.png" --cut 256x256+128+128 \
      "$tmp/match.png" --cut 256x256+128+128 --mosaic:pad=4 3x1 -d uint8 -o "$out/fill_soft.png"
  # --tileable: the sample tiled 2x2 (its seams show), then the result tiled 2x2 (seed 1); the
  # lit ones with flatten=1, as texsyn advises for them.
  for s in rust tiles_green bricks leaves_autumn; do
    flat=""
    case "$s" in rust | tiles_green | bricks) flat=":flatten=1" ;; esac
    "$texsyn" --seed 1 "$samples/$s.png" --tileable$flat -o "$tmp/tile.png"
    oiiotool "$samples/$s.png" --dup --mosaic 2x1 --dup --mosaic 1x2 "$tmp/tile.png" --dup \
        --mosaic 2x1 --dup --mosaic 1x2 --mosaic:pad=8 2x1 -d uint8 -o "$out/tileable_$s.png"
  done
  rm -rf "$tmp"
}
# docs/materials.md: bricks with its height and normal maps (the sample's, at 256x256),
# then the set synthesized to 384x384 by --patch (seed 1), first as it is, then with
# isotropic=1 (the normal map turns with the copies); height and normal shown as stored.
material_pictures() {
  local tmp
  tmp=$(mktemp -d)
  "$texsyn" --seed 1 "$samples/bricks.png" \
      --material:height="$samples/bricks_height.png":normal="$samples/bricks_normal.png" \
      --patch:size=384x384 -o "$tmp/set_{map}.png"
  "$texsyn" --seed 1 "$samples/bricks.png" \
      --material:height="$samples/bricks_height.png":normal="$samples/bricks_normal.png" \
      --patch:size=384x384:isotropic=1 -o "$tmp/iso_{map}.png"
  oiiotool "$samples/bricks.png" "$samples/bricks_height.png" --ch 0,0,0 \
      "$samples/bricks_normal.png" --mosaic:pad=4 3x1 -d uint8 -o "$out/material_sample.png"
  for set in set iso; do
    oiiotool "$tmp/${set}_albedo.png" "$tmp/${set}_height.png" --ch 0,0,0 \
        "$tmp/${set}_normal.png" --mosaic:pad=4 3x1 -d uint8 -o "$out/material_$set.png"
  done
  rm -rf "$tmp"
}
if [ "${2:-}" = materials ]; then
  material_pictures
  ls -la "$out"/material_*
  exit 0
fi
if [ "${2:-}" = fill ]; then
  fill_pictures
  ls -la "$out"/fill_* "$out"/tileable_*
  exit 0
fi
if [ "${2:-}" = patch ]; then
  patch_pictures
  ls -la "$out"/patch_* "$out"/which_*
  exit 0
fi
if [ "${2:-}" = surfaces ]; then
  surface_pictures
  ls -la "$out"/surface_*
  exit 0
fi
oiiotool "$samples/rust.png" -o "$out/rust_sample.png"
"$texsyn" --seed 1 "$samples/rust.png" --pyramid:size=512x512 -o "$out/rust_512.png"
"$texsyn" --seed 1 "$samples/marble_pink.png" --pyramid:size=256x256 -o "$out/marble_steerable.png"
"$texsyn" --seed 1 "$samples/marble_pink.png" --pyramid:size=256x256:pyramid=laplacian -o "$out/marble_laplacian.png"
oiiotool "$samples/marble_pink.png" -o "$out/marble_sample.png"
"$texsyn" --seed 2 "$samples/stucco_yellow.png" --pyramid:size=192x192 -o "$out/stucco_tile.png"
oiiotool "$out/stucco_tile.png" "$out/stucco_tile.png" "$out/stucco_tile.png" "$out/stucco_tile.png" \
    --mosaic 2x2 -o "$out/stucco_tiled_2x2.png"
"$texsyn" --seed 1 "$samples/rust.png" --pyramid:size=512x512:iterations=0 -o "$out/rust_iter0.png"
"$texsyn" --seed 1 "$samples/rust.png" --pyramid:size=512x512:iterations=1 -o "$out/rust_iter1.png"
# docs/analysis-files.md: the statistics sliders, from one analysis.
"$texsyn" "$samples/rust.png" --analyze -o "$out/rust.tsa"
for look in "rust_sliders_default|" "rust_gain_coarse|:gain=1,1,2,1" "rust_gain_fine|:gain=2,0.5" \
    "rust_balance_vertical|:balance=0.8,0.8,0.8,0.8" \
    "rust_balance_horizontal|:balance=-0.8,-0.8,-0.8,-0.8"; do
    "$texsyn" --seed 1 "$out/rust.tsa" --pyramid:size=192x192${look#*|} -o "$out/${look%%|*}.png"
done
# homogeneity.md: stucco under the issue's 0.5 -> 1.5 ramp (applied in linear), and its
# synthesis without and with flatten=1.
tmp=$(mktemp -d)
oiiotool "$samples/stucco_yellow.png" --colorconvert sRGB linear \
    --pattern fill:left=0.5,0.5,0.5:right=1.5,1.5,1.5 128x128 3 --mul -d float -o "$tmp/lit.exr"
oiiotool "$tmp/lit.exr" --colorconvert linear sRGB -d uint8 -o "$out/stucco_lit.png"
"$texsyn" --seed 3 "$tmp/lit.exr" --pyramid:size=256x256 --tocolorspace sRGB -d uint8 \
    -o "$out/stucco_lit_plain.png"
"$texsyn" --seed 3 "$tmp/lit.exr" --pyramid:size=256x256:flatten=1 --tocolorspace sRGB -d uint8 \
    -o "$out/stucco_lit_flat.png"
rm -rf "$tmp"
# Solid textures: an xy, an xz and a yz slice side by side. The tool writes z slices only;
# python3-openimageio cuts the other two axes out of the stack of them.
solid_slices() { # EXR PNG
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys
import numpy as np
import OpenImageIO as oiio
inp = oiio.ImageInput.open(sys.argv[1])
slices = []
while inp.seek_subimage(len(slices), 0):
    slices.append(inp.read_image("float"))
vol = np.stack(slices)  # z, y, x, channel; sRGB-encoded values
n = vol.shape[0] // 2
row = np.concatenate([vol[n], vol[:, n, :, :], vol[:, :, n, :]], axis=1)
pixels = (np.clip(row, 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
out = oiio.ImageOutput.create(sys.argv[2])
out.open(sys.argv[2], oiio.ImageSpec(pixels.shape[1], pixels.shape[0], pixels.shape[2], "uint8"))
out.write_image(pixels)
out.close()
PY
}
for mode in combined laplacian; do
  "$texsyn" --seed 1 "$samples/marble_pink.png" --solid:size=128x128x128:pyramid=$mode \
      --tocolorspace "sRGB - Texture" -d float -o "$out/solid_$mode.exr"
  name=marble_solid_slices.png
  [ "$mode" = laplacian ] && name=marble_solid_laplacian_slices.png
  solid_slices "$out/solid_$mode.exr" "$out/$name"
  rm -f "$out/solid_$mode.exr"
done
# docs/mixtures.md: 128x128, so that the pictures stay small.
oiiotool "$samples/paper_crinkled.png" -o "$out/paper_sample.png"
oiiotool "$samples/stucco_yellow.png" -o "$out/stucco_sample.png"
"$texsyn" --seed 1 "$samples/rust.png" "$samples/paper_crinkled.png" --mix:palette=0:pattern=1:size=128x128 -o "$out/mix_rust_paper.png"
"$texsyn" --seed 1 "$samples/rust.png" "$samples/paper_crinkled.png" --mix:palette=1:pattern=0:size=128x128 -o "$out/mix_paper_rust.png"
"$texsyn" --seed 1 "$samples/paper_crinkled.png" --pyramid:size=128x128 -o "$out/paper_128.png"
"$texsyn" --seed 1 "$samples/stucco_yellow.png" --pyramid:size=128x128 -o "$out/stucco_128.png"
"$texsyn" --seed 1 "$samples/paper_crinkled.png" "$samples/stucco_yellow.png" --mix:split=2:size=128x128 -o "$out/split_paper_stucco.png"
"$texsyn" --seed 1 "$samples/stucco_yellow.png" "$samples/paper_crinkled.png" --mix:split=2:size=128x128 -o "$out/split_stucco_paper.png"
strip=()
for w in 1,0 0.75,0.25 0.5,0.5 0.25,0.75 0,1; do
    "$texsyn" --seed 1 "$samples/rust.png" "$samples/stucco_yellow.png" --mix:weights=$w:size=128x128 -o "$out/weights_$w.png"
    strip+=("$out/weights_$w.png")
done
oiiotool "${strip[@]}" --mosaic 5x1 -o "$out/weights_rust_stucco.png"
rm -f "${strip[@]}"
"$texsyn" --seed 1 "$samples/marble_pink.png" "$samples/stucco_yellow.png" --transfer -o "$out/transfer_marble_stucco.png"
"$texsyn" --seed 1 "$samples/paper_crinkled.png" "$samples/marble_pink.png" --transfer -o "$out/transfer_paper_marble.png"
# docs/neighborhood.md: each search back-end on grass and bricks (192x192 from the 256x256
# samples, seed 1; each row starts with the sample's top-left 192x192), two-by-two tilings
# with and without the seam pass, the report's Figure 3 (the causal L against the square
# with noise), and a source map re-applied to a height map.
for s in grass bricks; do
  oiiotool "$samples/$s.png" --cut 192x192+0+0 -o "$out/nb_sample.png" # shown at the same scale
  row=("$out/nb_sample.png")
  for search in exhaustive tsvq kdtree coherent; do
    "$texsyn" --seed 1 "$samples/$s.png" --neighborhood:size=192x192:search=$search -o "$out/nb_$search.png"
    row+=("$out/nb_$search.png")
  done
  oiiotool "${row[@]}" --mosaic:pad=4 5x1 -o "$out/neighborhood_${s}_searches.png"
  rm -f "$out"/nb_*.png
done
for tile in 0 1; do
  "$texsyn" --seed 2 "$samples/bricks.png" --neighborhood:size=128x128:tile=$tile -o "$out/nb_tile.png"
  oiiotool "$out/nb_tile.png" --dup --mosaic 2x1 --dup --mosaic 1x2 -o "$out/neighborhood_bricks_tile$tile.png"
done
oiiotool "$samples/stucco_yellow.png" --cut 64x64+0+0 -o "$out/nb_crop.png"
for shape in causal square; do
  "$texsyn" --seed 1 "$out/nb_crop.png" --neighborhood:size=128x128:levels=1:n=7:shape=$shape \
      -o "$out/nb_$shape.png"
done
oiiotool "$out/nb_crop.png" --resize 128x128 "$out/nb_causal.png" "$out/nb_square.png" \
    --mosaic:pad=4 3x1 -o "$out/neighborhood_figure3.png"
"$texsyn" --seed 1 "$samples/bricks.png" --neighborhood:size=256x256:map="$out/nb_map.exr" \
    -o "$out/nb_colour.png"
oiiotool "$samples/bricks.png" --chsum:weight=0.3,0.6,0.1 -o "$out/nb_height.png"
"$texsyn" --iscolorspace Raw --apply-map "$out/nb_map.exr" "$out/nb_height.png" -o "$out/nb_height_big.png"
oiiotool "$out/nb_colour.png" "$out/nb_height_big.png" --ch 0,0,0 --mosaic:pad=4 2x1 \
    -o "$out/neighborhood_apply_map.png"
rm -f "$out"/nb_*
# docs/choosy.md: choosy sampling against greedy selection on flowers, isotropic=0 and 1 on
# wood grain, and one pass per level against iterations=1,8 (seed 1; flowers with
# isotropic=1, the paper's setting).
"$texsyn" --seed 1 "$samples/flowers.png" --choosy:size=256x256:isotropic=1 -o "$out/ch_choosy.png"
"$texsyn" --seed 1 "$samples/flowers.png" --choosy:size=256x256:isotropic=1:penalty=0 -o "$out/ch_greedy.png"
"$texsyn" --seed 1 "$samples/flowers.png" --choosy:size=256x256:isotropic=1:iterations=1,8 -o "$out/ch_iter.png"
oiiotool "$samples/flowers.png" --resize 256x256 "$out/ch_choosy.png" "$out/ch_greedy.png" \
    --mosaic:pad=4 3x1 -o "$out/choosy_flowers_greedy.png"
oiiotool "$out/ch_choosy.png" "$out/ch_iter.png" --mosaic:pad=4 2x1 -o "$out/choosy_flowers_iterations.png"
for iso in 0 1; do
  "$texsyn" --seed 1 "$samples/wood_grain.png" --choosy:size=128x128:isotropic=$iso -o "$out/ch_iso$iso.png"
done
oiiotool "$samples/wood_grain.png" "$out/ch_iso0.png" "$out/ch_iso1.png" --mosaic:pad=4 3x1 \
    -o "$out/choosy_wood_isotropic.png"
rm -f "$out"/ch_*
# docs/cascade.md: the six presets, 256x256, seed 1, no input.
presets=()
for p in cells blotches fibres bands caustics stone; do
  "$texsyn" --seed 1 --cascade:preset=$p:size=256x256 -o "$out/cc_$p.png"
  presets+=("$out/cc_$p.png")
done
oiiotool "${presets[@]}" --mosaic:pad=4 3x2 -o "$out/cascade_presets.png"
rm -f "$out"/cc_*
rm -f "$out/stucco_tile.png" "$out/rust.tsa"
patch_pictures
surface_pictures
ls -la "$out"
