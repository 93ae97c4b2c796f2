#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs every workload of a benchmark program in its own process (so peak_MB is that
# workload's) and prints median wall time and peak memory (a workload of one repetition:
# its time).
# usage: bench/run.sh BUILD_DIR [filter-regex] [program: pyramid_bench (default), solid_bench,
#        neighborhood_bench, choosy_bench, cascade_bench, patch_bench, surface_bench,
#        fill_bench, material_bench, python_overhead_bench (compare with python_overhead.sh)]
set -euo pipefail
bench="$1/bench/${3:-pyramid_bench}"
filter="${2:-.}"
for name in $("$bench" --benchmark_list_tests | grep -E "$filter"); do
  "$bench" --benchmark_filter="^${name}\$" --benchmark_format=csv 2>/dev/null \
    | awk -F, -v n="$name" '$1 ~ /_median"?$/ || $1 ~ /repeats:1\/real_time"?$/ { for (i = 1; i <= NF; i++) if (h[i] == "\"peak_MB\"" || h[i] == "peak_MB") p = $i; printf "%-36s median %8.0f ms  peak %6.0f MB\n", n, $3, p }
                            NR == 1 { for (i = 1; i <= NF; i++) h[i] = $i }'
done
