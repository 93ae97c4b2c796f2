# SPDX-License-Identifier: Apache-2.0
"""Issue #19's Python workload: the call bench/python_overhead_bench.cpp makes in C++, made
through the texsyn module. PY1: rust.png (256x256 RGB, its stored values as float32) ->
1024x1024 pyramid synthesis with the defaults, seed 1, 2 threads, I/O excluded.

usage: PYTHONPATH=BUILD/python /usr/bin/python3 bench/python_overhead.py SAMPLE [REPETITIONS]
Prints the median wall time, the process's peak memory and the result's pixel sum (which
must equal the C++ run's)."""
import resource
import statistics
import sys
import time

import numpy as np
import OpenImageIO as oiio
import texsyn


def main():
    path = sys.argv[1]
    repetitions = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    sample = oiio.ImageBuf(path).get_pixels(oiio.FLOAT)[:256, :256, :3]
    sample = np.ascontiguousarray(sample)
    times = []
    for _ in range(repetitions):
        start = time.perf_counter()
        out = texsyn.pyramid(sample, size=(1024, 1024), seed=1, threads=2)
        times.append(time.perf_counter() - start)
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print(f"PY1_python_256_to_1024  median {1000 * statistics.median(times):8.0f} ms  "
          f"peak {peak_mb:6.0f} MB  sum {out.astype(np.float64).sum():.0f}")


if __name__ == "__main__":
    main()
