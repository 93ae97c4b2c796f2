#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The README's second command: installs, builds, and runs the whole test suite with ctest,
# then the AddressSanitizer + UndefinedBehaviorSanitizer subset (scripts/sanitize.sh
# address-ci) and a short run of every fuzz target (tests/fuzz/run; TEXSYN_FUZZ_SECONDS
# per target, default 10).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
(cd build && ctest --output-on-failure -j2 --timeout 600)
bash scripts/sanitize.sh address-ci
bash tests/fuzz/run "${TEXSYN_FUZZ_SECONDS:-10}"
