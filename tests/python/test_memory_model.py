# SPDX-License-Identifier: Apache-2.0
"""The memory model (issue #36, S7): the estimate a method refuses work by, and a farm job
is sized from, against the peak resident memory of a whole `texsyn` process doing that
work less what the process holds before any work (`texsyn --version`'s peak). Within 25%
at a small and a larger size, for the methods whose estimates are calibrated against
measured peaks (bench/README.md, "Scaling with output size"): pyramid, choosy and fill.
The estimate is read from the refusal under a budget too small for it."""
import os
import re
import subprocess

import pytest

import texsyn
from conftest import DATA, TOOL

SAMPLES = DATA / "samples"
UNITS = {"B": 1.0, "KB": 1024.0, "MB": 1024.0**2, "GB": 1024.0**3}


def estimate(run):
    """The largest estimate `run(max_memory=budget)` refuses by: each refusal's estimate
    plus 1 MB is the next budget, up to the synthesis's own (not an analysis's)."""
    budget, found = 1024, 0.0
    for _ in range(4):
        with pytest.raises(ValueError) as refusal:
            run(max_memory=budget)
        message = str(refusal.value)
        m = re.search(r"would need about ([0-9.]+) ([KMG]?B) of memory", message)
        assert m, message
        found = max(found, float(m.group(1)) * UNITS[m.group(2)])
        if "analysis" not in message:
            return found
        budget = int(found) + (1 << 20)
    raise AssertionError("no estimate of the synthesis itself")


# Reports the peak resident memory of the command it runs. A separate small process: Linux
# counts what a child held before exec (a copy of its parent) in its peak, and the test's
# own process holds more than a small run of the tool.
_PEAK = """
import os, subprocess, sys
p = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
_, status, usage = os.wait4(p.pid, 0)
err = p.stderr.read().decode()
if os.waitstatus_to_exitcode(status) != 0:
    sys.exit(err)
print(usage.ru_maxrss * 1024)
"""


def peak_bytes(*args):
    """The peak resident memory of one `texsyn` process with these arguments."""
    env = dict(os.environ)
    env.pop("OIIO_LIBRARY_PATH", None)  # no plugins loaded beyond OIIO's own
    done = subprocess.run(["/usr/bin/python3", "-c", _PEAK, TOOL, *args], env=env,
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return float(done.stdout)


def plate_and_hole(tmp_path, side):
    """A `side`² plate (rust enlarged) and a mask with a square hole of a quarter of it."""
    plate, hole = tmp_path / f"plate{side}.png", tmp_path / f"hole{side}.png"
    q = side // 4
    subprocess.run(["oiiotool", str(SAMPLES / "rust.png"), "--resize", f"{side}x{side}",
                    "-o", str(plate)], check=True)
    subprocess.run(["oiiotool", "--pattern", "constant:color=0", f"{side}x{side}", "1",
                    "--fill:color=1", f"{q}x{q}+{3 * side // 8}+{3 * side // 8}",
                    "-d", "uint8", "-o", str(hole)], check=True)
    return str(plate), str(hole)


CASES = {
    # method: (sizes, the estimate at a size, the tool's arguments at a size)
    "pyramid": ((512, 1024),
                lambda s, _: estimate(lambda **k: texsyn.pyramid(
                    str(SAMPLES / "rust.png"), size=(s, s), **k)),
                lambda s, _: [str(SAMPLES / "rust.png"), f"--pyramid:size={s}x{s}"]),
    "choosy": ((768, 960),
               lambda s, _: estimate(lambda **k: texsyn.choosy(
                   str(SAMPLES / "tiles_green.png"), size=(s, s), **k)),
               lambda s, _: [str(SAMPLES / "tiles_green.png"), f"--choosy:size={s}x{s}"]),
    "fill": ((768, 1024),
             lambda s, files: estimate(lambda **k: texsyn.fill(files[0], mask=files[1], **k)),
             lambda s, files: [files[0], f"--fill:mask={files[1]}"]),
}


@pytest.mark.parametrize("method", sorted(CASES))
def test_the_estimate_predicts_the_measured_peak(method, tmp_path):
    sizes, estimate_at, arguments_at = CASES[method]
    start = peak_bytes("--version")
    for side in sizes:
        files = plate_and_hole(tmp_path, side) if method == "fill" else None
        predicted = estimate_at(side, files)
        measured = peak_bytes("--threads", "2", "--seed", "1", *arguments_at(side, files),
                              "-o", str(tmp_path / "out.exr")) - start
        assert 0.75 * measured <= predicted <= 1.25 * measured, (
            f"{method} at {side}x{side}: estimated {predicted / 2**20:.0f} MB, "
            f"measured {measured / 2**20:.0f} MB above the start-up's {start / 2**20:.0f} MB")
