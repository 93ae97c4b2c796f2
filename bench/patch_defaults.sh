#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Issue #33's timing: `texsyn … --patch` with its defaults as a whole process (reading the
# sample, synthesis, writing a half-float EXR), this build against another texsyn (the
# previous defaults), in alternating runs so that the machine's drift hits both alike. For
# each workload it prints the median wall time and peak resident memory of each side over
# PAIRS pairs, and the median of the per-pair ratios.
# usage: bench/patch_defaults.sh BUILD_DIR OTHER_TEXSYN [PAIRS (default 5)]
set -euo pipefail
build=$(realpath "$1")
other=$(realpath "$2")
pairs="${3:-5}"
# shellcheck source=bench/common.sh
source "$(dirname "$0")/common.sh"
bench_workdir
oiiotool "$samples/bricks.png" --cut 128x128+0+0 -o bricks128.png
cp "$samples/bricks.png" "$samples/grass.png" "$samples/tiles_green.png" \
   "$samples/paper_crinkled.png" "$samples/rust.png" .

workload() { # NAME SAMPLE SIZE
  local new_t=() new_m=() old_t=() old_m=() ratio=()
  for _ in $(seq "$pairs"); do
    read -r tn mn <<< "$(measure "$build/oiiotool-ext/texsyn" --threads 2 --seed 1 "$2" \
                          --patch:size="$3" -o new.exr)"
    read -r to mo <<< "$(measure "$other" --threads 2 --seed 1 "$2" --patch:size="$3" -o old.exr)"
    new_t+=("$tn") new_m+=("$mn") old_t+=("$to") old_m+=("$mo")
    ratio+=("$(awk -v a="$tn" -v b="$to" 'BEGIN { printf "%.3f", a / b }')")
  done
  printf '%-24s this %6.2f s %5.0f MB   other %6.2f s %5.0f MB   this/other %.2f\n' "$1" \
    "$(median "${new_t[@]}")" "$(median "${new_m[@]}")" "$(median "${old_t[@]}")" \
    "$(median "${old_m[@]}")" "$(median "${ratio[@]}")"
}
workload "bricks 256 -> 1024" bricks.png 1024x1024
workload "bricks 128 -> 512" bricks128.png 512x512
workload "grass 256 -> 1024" grass.png 1024x1024
workload "tiles 256 -> 1024" tiles_green.png 1024x1024
workload "bricks 256 -> 2048" bricks.png 2048x2048
# Samples that try one level fewer: on the output itself (twice the sample) and on a trial.
workload "paper 128 -> 512" paper_crinkled.png 512x512
workload "rust 256 -> 512" rust.png 512x512
workload "rust 256 -> 1024" rust.png 1024x1024
