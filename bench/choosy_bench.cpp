// SPDX-License-Identifier: Apache-2.0
// Issue #6's workloads: whole Castellanos & Williams syntheses (I/O excluded), RGB, 2 threads,
// seed 0, default options (4 levels, dims=20) but isotropic=1 unless named.
//   C1 flowers 128x128 -> 256x256, 1 iteration, exhaustive
//   C2 = C1 with the set of dynamic kd-trees (target: >= 20x faster than C1)
//   C3 flowers 128x128 -> 512x512, kd-trees (target: <= 5 s)
//   C4 = C3 with iterations 8/8/8/1 coarse to fine (iterations=1,8)
//   S_<search>_M<m>_N<n>: scaling, rust.png cropped to n x n -> m x m (log-log table)
// `peak_MB` is the process's peak resident memory so far: run one workload per process
// (bench/run.sh BUILD_DIR . choosy_bench).
#include <texsyn/choosy.h>
#include <texsyn/io.h>

#include <stdexcept>
#include <string>

#include <OpenImageIO/imagebufalgo.h>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;
using texsyn::bench::sample_crop;

namespace {

struct Workload {
    std::string name;
    std::string sample;
    int sample_size;
    int size;
    std::vector<int> iterations;
    ChoosySearch search;
    int repetitions;
};

void run_workload(benchmark::State& state, const Workload& w)
{
    const OIIO::ImageBuf sample = sample_crop(w.sample, w.sample_size);
    ChoosyOptions opt;
    opt.width = opt.height = w.size;
    opt.iterations = w.iterations;
    opt.search = w.search;
    opt.isotropic = 1; // the workloads of bench/README.md, measured when it was the default
    opt.nthreads = 2;
    for (auto _ : state) {
        OIIO::ImageBuf out;
        if (!choosy_synthesize(out, sample, opt))
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["Mpixels"] = double(w.size) * w.size / 1e6;
}

void register_workloads()
{
    using S = ChoosySearch;
    static std::vector<Workload> workloads = {
        { "C1_128_to_256_exhaustive", "flowers.png", 128, 256, { 1 }, S::Exhaustive, 2 },
        { "C2_128_to_256_kdtree", "flowers.png", 128, 256, { 1 }, S::KdTree, 5 },
        { "C3_128_to_512_kdtree", "flowers.png", 128, 512, { 1 }, S::KdTree, 3 },
        { "C4_128_to_512_kdtree_8881", "flowers.png", 128, 512, { 1, 8 }, S::KdTree, 2 },
    };
    // Scaling in M (output pixels) and N (sample pixels), rust.png cropped to N (4 levels
    // need N >= 40x40): kd-trees at N = 128^2 and M = 256^2, exhaustive at N = 64^2 and
    // M = 128^2.
    auto add = [](const std::string& search, S s, int m, int n, int repetitions) {
        workloads.push_back({ "S_" + search + "_M" + std::to_string(m) + "_N" + std::to_string(n),
            "rust.png", n, m, { 1 }, s, repetitions });
    };
    for (int m : { 128, 256, 512, 1024 })
        add("kdtree", S::KdTree, m, 128, 3);
    for (int n : { 48, 64, 256 })
        add("kdtree", S::KdTree, 256, n, 3);
    for (int m : { 64, 128, 256 })
        add("exhaustive", S::Exhaustive, m, 64, 2);
    for (int n : { 48, 96, 128 })
        add("exhaustive", S::Exhaustive, 128, n, 2);
    for (const Workload& w : workloads)
        configure_workload(
            benchmark::RegisterBenchmark(w.name.c_str(), run_workload, w), w.repetitions);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
