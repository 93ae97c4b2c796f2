#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Issue #36's scaling table: whole `texsyn` processes (2 threads, seed 1, reading the sample
# and writing a half-float EXR) at growing output sizes, for each method at its defaults.
# For each run it prints the wall time, the peak resident memory, and the peak less what
# the process holds before any work (`texsyn --version`'s peak) per output pixel: the
# figure a TD multiplies by a farm job's pixels. After each method, the exponents of time
# and of peak memory against output pixels (least squares over the sizes, log-log).
# usage: bench/scaling.sh BUILD_DIR [SIZES (default "1024 2048 4096")] [METHODS (default
#        "pyramid patch neighborhood choosy fill cascade")]
set -euo pipefail
build=$(realpath "$1")
sizes="${2:-1024 2048 4096}"
methods="${3:-pyramid patch neighborhood choosy fill cascade}"
texsyn="$build/oiiotool-ext/texsyn"
# shellcheck source=bench/common.sh
source "$(dirname "$0")/common.sh"
bench_workdir

read -r _ base_mb <<< "$(measure "$texsyn" --version)"

# The arguments of one run of METHOD at SIZE (fill: a SIZE plate with a SIZE/4 square hole).
arguments() { # METHOD SIZE
  local s="$2"
  case "$1" in
    pyramid) echo "$samples/rust.png --pyramid:size=${s}x${s}" ;;
    patch) echo "$samples/bricks.png --patch:size=${s}x${s}" ;;
    neighborhood) echo "$samples/grass.png --neighborhood:size=${s}x${s}" ;;
    choosy) echo "$samples/tiles_green.png --choosy:size=${s}x${s}" ;;
    cascade) echo "--cascade:size=${s}x${s}" ;;
    fill)
      if [ ! -f "plate$s.png" ]; then
        oiiotool "$samples/rust.png" --resize "${s}x${s}" -o "plate$s.png"
        oiiotool --pattern constant:color=0 "${s}x${s}" 1 \
          --fill:color=1 "$((s / 4))x$((s / 4))+$((3 * s / 8))+$((3 * s / 8))" -d uint8 \
          -o "hole$s.png"
      fi
      echo "plate$s.png --fill:mask=hole$s.png" ;;
  esac
}

echo "start-up peak (texsyn --version): $base_mb MB"
fits=""
echo "| method | output | wall time | peak RSS | (peak - start-up) per output pixel |"
echo "| --- | --- | ---: | ---: | ---: |"
for m in $methods; do
  points=""
  for s in $sizes; do
    # shellcheck disable=SC2046 # the arguments are split on purpose
    read -r t mb <<< "$(measure "$texsyn" --threads 2 --seed 1 $(arguments "$m" "$s") -o out.exr)"
    pixels=$((s * s))
    awk -v m="$m" -v s="$s" -v t="$t" -v mb="$mb" -v b="$base_mb" -v n="$pixels" 'BEGIN {
      printf "| %s | %dx%d | %.2f s | %.0f MB | %.0f bytes |\n", m, s, s, t, mb, (mb - b) * 1048576 / n }'
    points="$points $pixels $t $mb"
  done
  # Least-squares slopes of log(time) and log(peak - start-up) against log(pixels).
  fits="$fits$(echo "$points" | awk -v m="$m" -v b="$base_mb" '{
    n = 0
    for (i = 1; i + 2 <= NF; i += 3) { x[n] = log($i); t[n] = log($(i + 1)); p[n] = log($(i + 2) - b); n++ }
    for (k = 0; k < n; k++) { sx += x[k]; st += t[k]; sp += p[k] }
    mx = sx / n; mt = st / n; mp = sp / n
    for (k = 0; k < n; k++) { sxx += (x[k] - mx) ^ 2; sxt += (x[k] - mx) * (t[k] - mt); sxp += (x[k] - mx) * (p[k] - mp) }
    if (n > 1) printf "%s: time ~ pixels^%.2f, memory above start-up ~ pixels^%.2f\n", m, sxt / sxx, sxp / sxx
  }')
"
done
echo
printf '%s' "$fits"
