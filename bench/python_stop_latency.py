# SPDX-License-Identifier: Apache-2.0
"""Issue #19's Ctrl-C figures: how long a texsyn call takes to raise KeyboardInterrupt
after SIGINT, per method, at large sizes. Each run is signalled (by a timer thread, with
os.kill) DELAY seconds after it started; the time from the signal to the exception is
printed, and the worst per method. 2 threads, the default options, seed 1.

usage: PYTHONPATH=BUILD/python /usr/bin/python3 bench/python_stop_latency.py \\
           [METHOD[:SIZE]=DELAY,DELAY,...] ...
(default: every workload below with its delays). A run that ends before its signal says so.
"""
import os
import pathlib
import signal
import sys
import threading
import time

import numpy as np
import OpenImageIO as oiio

import texsyn

SAMPLE = pathlib.Path(__file__).resolve().parent.parent / "data" / "samples" / "bricks.png"

# method:size -> delays (s): spread over the run, the last ones in its finest level.
WORKLOADS = {
    "pyramid:4096": [2, 9, 20],
    "patch:4096": [5, 18, 28],
    "neighborhood:4096": [1, 3, 6],
    "choosy:4096": [1, 10, 40],
    "solid:256": [1, 6, 20],
    "fill:2048": [3, 15, 40],
    "tileable:4096": [1.5, 10, 30],
}


def call(method, size):
    """The call for a workload: a synthesis of size² (size³ for solid) from bricks.png, or
    a fill of the middle quarter / tileable of a size² plate (bricks.png tiled)."""
    sample = oiio.ImageBuf(str(SAMPLE)).get_pixels(oiio.FLOAT)
    if method in ("fill", "tileable"):
        reps = size // sample.shape[0] + 1
        plate = np.tile(sample, (reps, reps, 1))[:size, :size].copy()
        if method == "tileable":
            return lambda: texsyn.tileable(plate, threads=2)
        mask = np.zeros((size, size), np.float32)
        mask[size // 4:3 * size // 4, size // 4:3 * size // 4] = 1
        return lambda: texsyn.fill(plate, mask=mask, threads=2)
    shape = (size,) * (3 if method == "solid" else 2)
    run = getattr(texsyn, method)
    return lambda: run(sample, size=shape, seed=1, threads=2)


def stop_latency(run, delay):
    """Seconds from SIGINT (sent `delay` s into run()) to KeyboardInterrupt; None if the run
    ended first."""
    sent = []

    def interrupt():
        sent.append(time.monotonic())
        os.kill(os.getpid(), signal.SIGINT)
    timer = threading.Timer(delay, interrupt)
    timer.start()
    try:
        run()
    except KeyboardInterrupt:
        return time.monotonic() - sent[0]
    timer.cancel()
    return None


def main(args):
    signal.signal(signal.SIGINT, signal.default_int_handler)
    workloads = dict(WORKLOADS)
    if args:
        workloads = {}
        for a in args:
            name, _, delays = a.partition("=")
            workloads[name] = [float(d) for d in delays.split(",")]
    for name, delays in workloads.items():
        method, _, size = name.partition(":")
        run = call(method, int(size or 1024))
        worst = 0.0
        for delay in delays:
            latency = stop_latency(run, delay)
            if latency is None:
                print(f"{name}: ended before the signal at {delay:g} s", flush=True)
                continue
            worst = max(worst, latency)
            print(f"{name}: signal at {delay:g} s, stopped {latency:.2f} s later", flush=True)
        print(f"{name}: worst {worst:.2f} s", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
