#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Two texsyn builds on one workload, in alternating whole-process runs (the order flips
every pair, so the machine's drift hits both alike): prints each side's median wall time
and the median of the per-pair differences, the figure to quote for a change of a few
tens of milliseconds on a machine whose speed wanders by more.

usage: bench/paired.py THIS_TEXSYN OTHER_TEXSYN PAIRS NAME TEXSYN_ARGS...
(each run adds --threads 2 --seed 1 before the arguments and -o OUT.exr after them)"""
import os
import statistics
import subprocess
import sys
import tempfile
import time


def main():
    this, other, pairs, name, args = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4], sys.argv[5:]
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out.exr")

        def run(texsyn):
            t0 = time.perf_counter()
            subprocess.run([texsyn, "--threads", "2", "--seed", "1"] + args + ["-o", out],
                           check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            return time.perf_counter() - t0

        mine, theirs = [], []
        for i in range(pairs):
            if i % 2:
                theirs.append(run(other))
                mine.append(run(this))
            else:
                mine.append(run(this))
                theirs.append(run(other))
    differences = [a - b for a, b in zip(mine, theirs)]
    print("%-28s this %.3f s  other %.3f s  per-pair difference %+.3f s  (%d pairs)"
          % (name, statistics.median(mine), statistics.median(theirs),
             statistics.median(differences), pairs))


if __name__ == "__main__":
    main()
