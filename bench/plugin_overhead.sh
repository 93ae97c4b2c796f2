#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Issue #3's workload: the cost of opening a recipe through the OIIO plugin against the
# same synthesis by the texsyn tool, on workload P2 (rust.png 256x256 -> 1024x1024, steerable,
# 5 iterations, 2 threads), both writing a float EXR. Prints the median of 5 runs each.
# usage: bench/plugin_overhead.sh BUILD_DIR
set -euo pipefail
build=$(realpath "$1")
repo="$(cd "$(dirname "$0")/.." && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$repo/data/samples/rust.png" "$work/"
cd "$work"
export OCIO= OIIO_LIBRARY_PATH="$build/plugins"
median() { sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
time_runs() {
  for _ in 1 2 3 4 5; do
    local t0 t1
    t0=$(date +%s.%N)
    "$@" > /dev/null
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f\n", b - a }'
  done | median
}
cli=$(time_runs "$build/oiiotool-ext/texsyn" --threads 2 --seed 1 rust.png \
      --pyramid:size=1024x1024 -d float -o cli.exr)
plugin=$(time_runs oiiotool --threads 2 "rust.png.texsyn?size=1024x1024&seed=1" -d float -o plugin.exr)
idiff -fail 0 cli.exr plugin.exr > /dev/null || { echo "outputs differ"; exit 1; }
echo "texsyn CLI  median ${cli} s"
echo "oiiotool    median ${plugin} s"
awk -v c="$cli" -v p="$plugin" 'BEGIN { printf "overhead    %.1f %%\n", 100 * (p - c) / c }'
