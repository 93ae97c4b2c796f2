#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Issue #19's comparison: workload PY1 (rust.png 256x256 float -> 1024x1024 pyramid, seed 1,
# 2 threads, I/O excluded) called from C++ (bench/python_overhead_bench.cpp) and from Python
# (bench/python_overhead.py), in alternating processes so that the machine's drift hits both
# alike. Each process reports its median of 5; the script prints the median over PAIRS
# pairs of each side, their ratio, both peaks, and fails if the two results' sums differ.
# usage: bench/python_overhead.sh BUILD_DIR [PAIRS (default 5)]
set -euo pipefail
build=$(realpath "$1")
pairs="${2:-5}"
repo="$(cd "$(dirname "$0")/.." && pwd)"
sample="$repo/data/samples/rust.png"
cpp_times=() py_times=()
for _ in $(seq "$pairs"); do
  cpp=$("$build/bench/python_overhead_bench" --benchmark_format=csv \
          2> /dev/null | awk -F, '$1 ~ /_median"?$/ { print $3, $(NF - 1), $NF }')
  py=$(PYTHONPATH="$build/python" /usr/bin/python3 "$repo/bench/python_overhead.py" "$sample" 5 \
         | awk '{ print $3, $6, $9 }')
  read -r cpp_ms cpp_mb cpp_sum <<< "$cpp"
  read -r py_ms py_mb py_sum <<< "$py"
  [ "$(printf '%.0f' "$cpp_sum")" = "$(printf '%.0f' "$py_sum")" ] \
    || { echo "results differ: C++ sum $cpp_sum, Python sum $py_sum"; exit 1; }
  echo "pair: C++ ${cpp_ms} ms (${cpp_mb} MB)  Python ${py_ms} ms (${py_mb} MB)"
  cpp_times+=("$cpp_ms") py_times+=("$py_ms")
done
median() { printf '%s\n' "$@" | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
c=$(median "${cpp_times[@]}") p=$(median "${py_times[@]}")
awk -v c="$c" -v p="$p" 'BEGIN { printf "median C++ %.0f ms, Python %.0f ms, Python/C++ %.3f\n", c, p, p / c }'
