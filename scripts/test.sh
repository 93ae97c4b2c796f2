#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The README's second command: installs, builds, and runs the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
cd build
ctest --output-on-failure -j2 --timeout 600
