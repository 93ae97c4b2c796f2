#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""numbers.py: the measurements docs/*.md quote, regenerated from the tests and benchmarks.

A page marks each number it quotes as <!--n:KEY-->VALUE<!--/n-->. The tests print
"[doc] KEY VALUE" lines (tests/unit/test_metrics.h: doc_number); the benchmarks print
their medians through bench/run.sh. This script runs them and rewrites every marked value.

  /usr/bin/python3 docs/numbers.py BUILD          # the tests' numbers (about a minute)
  /usr/bin/python3 docs/numbers.py BUILD --bench  # and the benchmarks' (several minutes)
  /usr/bin/python3 docs/numbers.py BUILD --bench=bench.W_  # and only these benchmarks' keys
  /usr/bin/python3 docs/numbers.py BUILD --eval DIR...  # and ../shared/eval/compare.py's
                                                  # results.json in each DIR (means)
  /usr/bin/python3 docs/numbers.py --check        # every marked key has a source (a test)
"""
import glob
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SPAN = re.compile(r"<!--n:([A-Za-z0-9_.\-]+)-->(.*?)<!--/n-->")

# Key prefix -> (test binary under BUILD/tests, gtest filter) that prints it.
TESTS = {
    "fill.bricks.": ("fill_test", "Fill.BricksHoleLooksLikeItsSurroundings"),
    "fill.outline.": ("fill_test", "Fill.TheOutlineDoesNotShowOnSoftOrSharpPlates"),
    "fill.lattice.": ("fill_test", "Fill.LargeAndFeatheredHolesHoldNoLattice"),
    "tileable.small.": ("fill_test", "Tileable.SmallSamplesGetABandLikeTheirMiddle"),
    "tileable.": ("fill_test", "Tileable.SamplesTileAndKeepTheirMiddle"),
    "choosy.": ("choosy_test", "ChoosyQuality.MatchesFirstOrderStatisticsFarBetterThanGreedy"),
    "structure.": ("structure_test", "Structure.*"),
    "surface.band.": ("surface_boundary_test", "SurfaceBoundary.*Band*"),
    "stop.": ("methods_test", "Methods.StopLatencyIsAboutASecondForEveryRow"),
}
# Key prefix -> (benchmark program, bench/run.sh filter): "bench.<workload>.median" (s) and
# "bench.<workload>.peak" (MB), <workload> the short name before the first "_" or the whole.
BENCH = {
    "bench.C": ("choosy_bench", "C[1-4]"),
    "bench.T": ("patch_bench", "."),
    "bench.O_": ("patch_bench", "."),
    "bench.S_": ("patch_bench", "."),
    "bench.M1": ("material_bench", "M1"),
    "bench.W_": ("surface_bench", "W_"),
}


# "eval.<run>.<metric>": the mean of compare.py's metric over every row of run <run> in the
# results.json files given with --eval, and "eval.<run>.<sample>.<metric>" over one sample's
# rows; digits per metric.
EVAL_DIGITS = {"acf_dist": 4, "band_stats": 4, "repeat": 4, "seam": 3, "hist_w1": 4, "seconds": 2}


def run_eval(dirs):
    import json
    rows = []
    for d in dirs:
        with open(os.path.join(d, "results.json")) as f:
            rows += json.load(f)
    values = {}
    for run in {r["run"] for r in rows}:
        ok = [r for r in rows if r["run"] == run and r.get("ok") and "acf_dist" in r]
        for metric, digits in EVAL_DIGITS.items():
            if ok:
                mean = sum(r[metric] for r in ok) / len(ok)
                values[f"eval.{run}.{metric}"] = f"{mean:.{digits}f}"
        per = {}
        for r in ok:
            per.setdefault(r["sample"], []).append(r)
        for sample, v in per.items():  # "eval.<run>.<sample>.<metric>": its mean over the seeds
            for metric, digits in EVAL_DIGITS.items():
                values[f"eval.{run}.{sample}.{metric}"] = f"{sum(x[metric] for x in v) / len(v):.{digits}f}"
        if per:
            values[f"eval.{run}.worst_acf"] = "%.4f" % max(sum(x["acf_dist"] for x in v) / len(v) for v in per.values())
            values[f"eval.{run}.worst_repeat"] = "%.4f" % max(max(x["repeat"] for x in v) for v in per.values())
    return values


def source_of(key, table):
    best = None
    for prefix in table:
        if key.startswith(prefix) and (best is None or len(prefix) > len(best)):
            best = prefix
    return best


def marked_keys():
    keys = {}
    for page in sorted(glob.glob(os.path.join(HERE, "*.md"))) + [os.path.join(ROOT, "bench", "README.md")]:
        with open(page) as f:
            for key, _ in SPAN.findall(f.read()):
                keys.setdefault(key, []).append(os.path.relpath(page, ROOT))
    return keys


def run_tests(build, prefixes):
    values = {}
    for binary, test_filter in sorted({TESTS[p] for p in prefixes}):
        out = subprocess.run([os.path.join(build, "tests", binary), "--gtest_filter=" + test_filter],
                             capture_output=True, text=True, cwd=os.path.join(build, "tests")).stdout
        for line in out.splitlines():
            if line.startswith("[doc] "):
                _, key, value = line.split()
                values[key] = value
    return values


def run_bench(build, prefixes):
    values = {}
    for program, bench_filter in sorted({BENCH[p] for p in prefixes}):
        out = subprocess.run(["bash", os.path.join(ROOT, "bench", "run.sh"), build, bench_filter, program],
                             capture_output=True, text=True).stdout
        for line in out.splitlines():
            m = re.match(r"(\S+)\s+median\s+([0-9.]+) ms\s+peak\s+([0-9.]+) MB", line)
            if m:
                # A workload is keyed by its short name ("C1") and its whole name
                # ("M1_albedo_alone"), for programs whose workloads share a short name.
                full = m.group(1).split("/")[0]
                for name in {full, full.split("_")[0]}:
                    values[f"bench.{name}.median"] = f"{float(m.group(2)) / 1000:.2f}"
                    values[f"bench.{name}.peak"] = f"{float(m.group(3)):.0f}"
    return values


def main():
    args = sys.argv[1:]
    keys = marked_keys()
    orphans = [k for k in keys
               if not source_of(k, TESTS) and not source_of(k, BENCH) and not k.startswith("eval.")]
    if "--check" in args:
        for k in orphans:
            print(f"numbers.py: {k} ({', '.join(keys[k])}) has no test or benchmark that prints it")
        return 1 if orphans else 0
    if not args:
        print(__doc__)
        return 2
    build = os.path.abspath(args[0])
    values = run_tests(build, {source_of(k, TESTS) for k in keys if source_of(k, TESTS)})
    bench = [a for a in args if a == "--bench" or a.startswith("--bench=")]
    if bench:
        only = bench[0].partition("=")[2].split(",") if "=" in bench[0] else None
        values.update(run_bench(build, {source_of(k, BENCH) for k in keys if source_of(k, BENCH)
                                        and (only is None or source_of(k, BENCH) in only)}))
    if "--eval" in args:
        values.update(run_eval([a for a in args[args.index("--eval") + 1:] if not a.startswith("--")]))
    missing = set()
    for page in sorted(glob.glob(os.path.join(HERE, "*.md"))) + [os.path.join(ROOT, "bench", "README.md")]:
        with open(page) as f:
            text = f.read()

        def replace(m):
            key = m.group(1)
            if key in values:
                return f"<!--n:{key}-->{values[key]}<!--/n-->"
            if source_of(key, TESTS) or (bench and source_of(key, BENCH) in (only or [source_of(key, BENCH)])) or (
                    "--eval" in args and key.startswith("eval.")):
                missing.add(key)
            return m.group(0)

        new = SPAN.sub(replace, text)
        if new != text:
            with open(page, "w") as f:
                f.write(new)
            print("numbers.py: rewrote", os.path.relpath(page, ROOT))
    for k in sorted(missing):
        print(f"numbers.py: no value printed for {k}")
    return 1 if missing or orphans else 0


if __name__ == "__main__":
    sys.exit(main())
