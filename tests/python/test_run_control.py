# SPDX-License-Identifier: Apache-2.0
"""Long runs from Python (docs/python.md, "Long runs"): seed= and threads= as the tool
takes them, the same array at any threads=, progress callbacks, an exception or Ctrl-C
stopping a run, and other Python threads running meanwhile (the GIL is released)."""
import os
import re
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np
import pytest

import texsyn

# Runs long enough to interrupt (several seconds), each signalled once its progress passes
# a fraction: choosy reports every few rows; a 2048² pyramid steps once per iteration and
# colour component (each step a second or more of band transforms, which it stops
# between bands); a 2048² patch synthesis at 0.6 is in its finest level, whose searches
# and votes take seconds and stop between rows.
LONG_RUNS = {
    "choosy": ("texsyn.choosy(sample, size=(1024, 1024), levels=3, progress=progress, "
               "threads=2)", 0.0),
    "pyramid": ("texsyn.pyramid(sample, size=(2048, 2048), progress=progress, threads=2)",
                0.1),
    "patch": ("texsyn.patch(sample, size=(2048, 2048), progress=progress, threads=2)", 0.6),
}


def test_seed_and_threads_take_what_the_tool_takes(cli):
    # The tool's ranges, from its own messages.
    for option, value in (("--seed", "-1"), ("--threads", "-1")):
        r = cli.run(option, value, "--cascade:size=8x8", "-o", "out.exr")
        assert r.returncode == 1
        lo, hi = re.search(r"out of range (\d+)\.\.(\d+)", r.stderr).groups()
        keyword = option[2:]
        for good in (int(lo), int(hi)):
            texsyn.cascade(size=(8, 8), **{keyword: good})
        for bad in (int(lo) - 1, int(hi) + 1, 1.0, "1", True, None):
            with pytest.raises(ValueError, match=f"^{keyword}=.* : expected an integer in "
                                                 f"{lo}..{hi}$"):
                texsyn.cascade(size=(8, 8), **{keyword: bad})
    texsyn.cascade(size=(8, 8), seed=np.int64(3), threads=np.uint8(1))  # integers of numpy


def test_max_memory_is_the_runs_own_budget(stucco):
    # Work beyond the budget is refused before it starts; within it, it runs; sizes as
    # --max-memory takes them, or bytes.
    with pytest.raises(Exception, match="this run's budget is 64.0 MB"):
        texsyn.pyramid(stucco, size=(4096, 4096), max_memory="64M")
    out = texsyn.pyramid(stucco, size=(32, 32), iterations=1, max_memory=64 << 20)
    assert out.shape == (32, 32, 3)
    for bad in ("lots", "0", 0, -1, 1.5):
        with pytest.raises(ValueError, match=r"^max_memory="):
            texsyn.pyramid(stucco, size=(32, 32), max_memory=bad)


def test_recipe_run_checks_threads(samples):
    recipe = texsyn.Recipe.load(f"{samples['stucco.png']}.texsyn?size=16x16&iterations=1")
    for bad in (-1, 1025, 2.0):
        with pytest.raises(ValueError, match="threads="):
            recipe.run(threads=bad)
    assert np.array_equal(recipe.run(threads=1), recipe.run(threads=2))


@pytest.mark.parametrize("method, args, options", [
    ("pyramid", ("stucco",), dict(size=(64, 64), iterations=2)),
    ("solid", ("stucco",), dict(size=(16, 16, 16), iterations=1)),
    ("mix", ("pair",), dict(palette=0, pattern=1, size=(32, 32), iterations=1)),
    ("neighborhood", ("stucco",), dict(size=(32, 32), levels=2, search="kdtree")),
    ("choosy", ("stucco",), dict(size=(32, 32), levels=2)),
    ("patch", ("bricks",), dict(size=(64, 64))),
    ("fill", ("bricks",), dict(mask="mask", patch=(7, 5))),
    ("cascade", (), dict(size=(64, 64), preset="stone")),
])
def test_the_same_seed_gives_the_same_array_at_any_thread_count(stucco, bricks, method, args,
                                                                options):
    mask = np.zeros(bricks.shape[:2], np.float32)
    mask[40:60, 30:50] = 1
    values = {"stucco": stucco, "bricks": bricks, "pair": [stucco, bricks[:64, :64].copy()],
              "mask": mask}
    args = [values[a] for a in args]
    options = {k: values.get(v, v) if isinstance(v, str) else v for k, v in options.items()}
    run = getattr(texsyn, method)

    def image(**more):
        out = run(*args, **options, **more)
        return out[0] if isinstance(out, tuple) else out
    one = image(seed=11, threads=1)
    assert np.array_equal(image(seed=11, threads=2), one)
    assert np.array_equal(image(seed=11), one)  # threads=0: every core
    assert not np.array_equal(image(seed=12, threads=2), one)


def test_progress_is_monotonic_from_the_calling_thread(stucco):
    for call in (lambda p: texsyn.pyramid(stucco, size=(32, 32), iterations=3, progress=p),
                 lambda p: texsyn.patch(stucco, size=(48, 48), progress=p),
                 lambda p: texsyn.cascade(size=(32, 32), progress=p, threads=2),
                 lambda p: texsyn.choosy(stucco, size=(192, 192), levels=3, progress=p)):
        fractions, threads = [], set()

        def progress(fraction):
            fractions.append(fraction)
            threads.add(threading.get_ident())
        started = time.monotonic()
        call(progress)
        elapsed = time.monotonic() - started
        assert len(fractions) >= 2 and fractions[0] < 1
        assert all(0 <= f <= 1 for f in fractions)
        assert fractions == sorted(fractions)
        assert fractions[-1] == 1.0
        assert threads == {threading.get_ident()}
        # At most every 50 ms, and at the end (choosy has hundreds of steps).
        assert len(fractions) <= elapsed / 0.05 + 2, (len(fractions), elapsed)


def test_recipe_run_reports_progress(samples):
    recipe = texsyn.Recipe.load(f"{samples['stucco.png']}.texsyn?size=32x32&iterations=2")
    fractions = []
    recipe.run(progress=fractions.append)
    assert fractions and fractions == sorted(fractions) and fractions[-1] == 1.0


class Stop(Exception):
    pass


def test_an_exception_in_the_callback_stops_the_run_and_propagates(stucco):
    for call in (lambda p: texsyn.pyramid(stucco, size=(32, 32), iterations=5, progress=p),
                 lambda p: texsyn.choosy(stucco, size=(64, 64), levels=2, progress=p),
                 lambda p: texsyn.Recipe.from_json(
                     '{"texsyn_recipe": 1, "method": "cascade", "size": [32, 32]}').run(
                         progress=p)):
        calls = []

        def progress(fraction):
            calls.append(fraction)
            raise Stop(fraction)
        with pytest.raises(Stop) as stopped:
            call(progress)
        assert calls == [stopped.value.args[0]]  # no call after the raise
        assert stopped.value.args[0] < 1  # stopped before the end
    # Nothing of the stopped runs is left over: the next run is whole.
    assert texsyn.pyramid(stucco, size=(32, 32), iterations=1).shape == (32, 32, 3)


@pytest.mark.parametrize("method", sorted(LONG_RUNS))
def test_ctrl_c_stops_a_run_within_about_a_second(tmp_path, samples, method):
    """A child Python process in a long synthesis gets SIGINT: it ends in KeyboardInterrupt
    soon after, before writing its result."""
    long_run, fraction = LONG_RUNS[method]
    script = tmp_path / "long_run.py"
    script.write_text(textwrap.dedent(f"""\
        import signal
        import sys
        import numpy as np
        import OpenImageIO as oiio
        import texsyn
        # Python leaves SIGINT ignored if it started so (a background job): take it.
        signal.signal(signal.SIGINT, signal.default_int_handler)
        sample = oiio.ImageBuf({str(samples["stucco.png"])!r}).get_pixels(oiio.FLOAT)
        started = []
        def progress(fraction):
            if not started and fraction >= {fraction}:
                started.append(fraction)
                print("running", flush=True)
        result = {long_run}
        np.save(sys.argv[1], result[0])
        """))
    out = tmp_path / "result.npy"
    child = subprocess.Popen([sys.executable, str(script), str(out)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    try:
        assert child.stdout.readline() == "running\n", child.stderr.read()
        time.sleep(0.2)  # into the step after the one reported
        sent = time.monotonic()
        child.send_signal(signal.SIGINT)
        child.wait(timeout=30)
        stopped_after = time.monotonic() - sent
    finally:
        child.kill()
        child.wait()
    stderr = child.stderr.read()
    assert stderr.rstrip().endswith("KeyboardInterrupt"), stderr
    assert child.returncode != 0
    # About a second, with room for a busy machine (and the child's own exit).
    assert stopped_after < 1.5, stopped_after
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["long_run.py"]


@pytest.mark.parametrize("method", ["patch", "fill"])
def test_the_interpreter_exits_cleanly_while_a_daemon_thread_is_in_a_run(tmp_path, method):
    """Python exiting while a daemon thread is inside texsyn used to end in `terminate
    called without an active exception` (or a segfault): the run is stopped at exit and the
    process ends normally, soon."""
    call = {
        "patch": "texsyn.patch(image, size=(2048, 2048), threads=2, progress=progress)",
        "fill": "texsyn.fill(image, mask=mask, threads=2, progress=progress)",
    }[method]
    script = tmp_path / "exit_during_run.py"
    script.write_text(textwrap.dedent(f"""\
        import threading
        import numpy as np
        import texsyn
        rng = np.random.default_rng(1)
        image = rng.random((512, 512, 3), dtype=np.float32)
        mask = np.zeros((512, 512), np.float32)
        mask[96:416, 96:416] = 1
        started = threading.Event()
        def progress(fraction):
            started.set()
        threading.Thread(target=lambda: {call}, daemon=True).start()
        started.wait(60)
        print("exiting", flush=True)
        """))
    begun = time.monotonic()
    child = subprocess.run([sys.executable, str(script)], capture_output=True, text=True,
                           env=os.environ.copy(), timeout=120)
    assert child.returncode == 0, child.stderr
    assert child.stdout == "exiting\n"
    assert "terminate" not in child.stderr and child.stderr == "", child.stderr
    assert time.monotonic() - begun < 30


def test_other_python_threads_run_during_a_synthesis(stucco):
    counter = [0]
    done = threading.Event()

    def count():
        while not done.is_set():
            counter[0] += 1
    def run():
        started = time.monotonic()
        texsyn.choosy(stucco, size=(192, 192), levels=3, threads=1)
        return time.monotonic() - started
    alone = run()
    worker = threading.Thread(target=count)
    worker.start()
    try:
        time.sleep(0.05)
        before = counter[0]
        beside = run()
        during = counter[0] - before
    finally:
        done.set()
        worker.join()
    assert beside > 0.1  # long enough to tell
    # Holding the GIL for the whole call would leave the counter almost still; a released
    # GIL lets it count at its own pace (millions a second; 1000 is a safe floor).
    assert during > 1000, (during, beside)
    # And the busy thread hardly slows the run: the run takes the GIL back (for Ctrl-C)
    # only every 50 ms, not at each of its hundreds of steps, each a wait of up to the
    # interpreter's 5 ms switch interval (that made it 20 times slower). Three times, for
    # a shared machine.
    assert beside < 3 * alone + 0.3, (beside, alone)
