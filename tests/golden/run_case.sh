#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs one golden case and compares every reference with idiff (all subimages).
# usage: run_case.sh TEXSYN CASE_DIR WORK_DIR
# A case directory holds `cmd` (texsyn's arguments; $DATA is data/samples), `tolerance`
# ("FAIL FAILPERCENT": idiff -fail / -failpercent, with the reason in a comment line) and
# ref/ (the expected files, made by regenerate.sh only).
set -euo pipefail
texsyn=$1 case_dir=$2 work=$3
DATA="$(cd "$case_dir/../../../data/samples" && pwd)"
export DATA
rm -rf "$work" && mkdir -p "$work" && cd "$work"
eval "\"$texsyn\" $(cat "$case_dir/cmd")"
read -r fail failpercent < <(grep -v '^#' "$case_dir/tolerance")
status=0
for ref in "$case_dir"/ref/*; do
  out="$work/$(basename "$ref")"
  echo "idiff -a -fail $fail -failpercent $failpercent $ref $out"
  idiff -a -fail "$fail" -failpercent "$failpercent" "$ref" "$out" || status=1
done
exit $status
