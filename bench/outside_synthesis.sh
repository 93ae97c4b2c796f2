#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Issue #36's S6: what each method's 1024x1024 run spends outside its synthesis, beyond the
# process start-up that every program linking Debian's OIIO pays. For each method, RUNS
# whole `texsyn` processes (reading the 256x256 sample, the synthesis, writing a half-float
# EXR) and RUNS `texsyn --version` processes, alternating, and prints the medians of: the
# whole process, the synthesis as `-v` times it ("... in 1.23 s"), the start-up, and what
# is left (whole - synthesis - start-up: reading, colour conversion, writing).
# usage: bench/outside_synthesis.sh BUILD_DIR [RUNS (default 5)]
set -euo pipefail
build=$(realpath "$1")
runs="${2:-5}"
texsyn="$build/oiiotool-ext/texsyn"
# shellcheck source=bench/common.sh
source "$(dirname "$0")/common.sh"
bench_workdir
oiiotool --pattern constant:color=0 1024x1024 1 --fill:color=1 256x256+384+384 -d uint8 \
  -o hole.png
oiiotool "$samples/rust.png" --resize 1024x1024 -o plate.png

# Prints "whole synthesis" in seconds for one run of the given texsyn arguments.
run_once() {
  /usr/bin/python3 - "$texsyn" "$@" <<'EOF'
import re, subprocess, sys, time
t0 = time.perf_counter()
p = subprocess.run([sys.argv[1], "-v", "--threads", "2", "--seed", "1"] + sys.argv[2:],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
whole = time.perf_counter() - t0
found = re.findall(r" in ([0-9.]+) s$", p.stderr, re.M)
print("%.3f %s" % (whole, found[-1] if found else "nan"))
EOF
}
startup_once() {
  /usr/bin/python3 - "$texsyn" <<'EOF'
import subprocess, sys, time
t0 = time.perf_counter()
subprocess.run([sys.argv[1], "--version"], check=True, stdout=subprocess.DEVNULL)
print("%.3f" % (time.perf_counter() - t0))
EOF
}

workload() { # NAME ARGS...
  local name="$1"; shift
  local whole=() synth=() start=() left=()
  for _ in $(seq "$runs"); do
    read -r w s <<< "$(run_once "$@")"
    u=$(startup_once)
    whole+=("$w"); synth+=("$s"); start+=("$u")
    left+=("$(awk -v w="$w" -v s="$s" -v u="$u" 'BEGIN { printf "%.3f", w - s - u }')")
  done
  printf '| %s | %s | %s | %s | **%s** |\n' "$name" "$(median "${whole[@]}")" \
    "$(median "${synth[@]}")" "$(median "${start[@]}")" "$(median "${left[@]}")"
}

echo "| method (256² sample → 1024²) | whole process (s) | synthesis (s) | start-up (s) | outside both (s) |"
echo "| --- | ---: | ---: | ---: | ---: |"
workload pyramid "$samples/rust.png" --pyramid:size=1024x1024 -o out.exr
workload patch "$samples/bricks.png" --patch:size=1024x1024 -o out.exr
workload neighborhood "$samples/grass.png" --neighborhood:size=1024x1024 -o out.exr
workload choosy "$samples/tiles_green.png" --choosy:size=1024x1024 -o out.exr
workload cascade --cascade:size=1024x1024 -o out.exr
workload "fill (1024² plate, 256² hole)" plate.png --fill:mask=hole.png -o out.exr
workload "tileable (1024² image)" plate.png --tileable -o out.exr
