#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs the dependencies (Debian 12, apt-get) and builds texsyn in ./build (Release).
# Idempotent: a second run only rebuilds what changed. Extra arguments go to cmake;
# TEXSYN_BUILD_TARGETS (space-separated) builds only those targets (and what they need)
# instead of everything.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
# Ninja for a new build folder; an existing one keeps the generator it was made with.
generator=()
[ -f build/CMakeCache.txt ] || generator=(-G Ninja)
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@" > build.log 2>&1 \
  || { cat build.log; exit 1; }
targets=()
for t in ${TEXSYN_BUILD_TARGETS:-}; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}" >> build.log 2>&1 || { tail -50 build.log; exit 1; }
echo "texsyn: built in $(pwd)/build (log: build.log)"
