#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Regenerates every golden reference with the given texsyn binary. Commit the result on its
# own, saying why the pixels changed.  usage: regenerate.sh BUILD/oiiotool-ext/texsyn
set -euo pipefail
texsyn=$(realpath "$1")
here="$(cd "$(dirname "$0")" && pwd)"
DATA="$(cd "$here/../../data/samples" && pwd)"
export DATA
for case_dir in "$here"/*/; do
  [ -f "$case_dir/cmd" ] || continue
  rm -rf "$case_dir/ref" && mkdir -p "$case_dir/ref"
  (cd "$case_dir/ref" && eval "\"$texsyn\" $(cat "$case_dir/cmd")")
  echo "regenerated $(basename "$case_dir"): $(ls "$case_dir/ref")"
done
