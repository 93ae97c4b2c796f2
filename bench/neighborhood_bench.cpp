// SPDX-License-Identifier: Apache-2.0
// Issue #5's workloads: whole Wei & Levoy syntheses (I/O excluded), RGB, 2 threads, seed 0,
// default options unless named (tile=1 seam pass included).
//   N1 grass 128x128 -> 256x256, levels=1, n=9, exhaustive
//   N2 = N1 with tsvq (target: >= 20x faster than N1)
//   N3 grass 256x256 -> 512x512, levels=4, n=9,7,5,5, kdtree (target: <= 3 s)
//   N4 = N3 with coherent (target: <= 1.5 s)
//   N5 grass 256x256 -> 1024x1024, coherent (target: <= 6 s)
//   M-<search>: the report's failing case, a 200x300 sample with a 25x25 neighbourhood
//     (levels=1, 64x64 output): peak memory (target: <= 2 GB with every back-end)
// `peak_MB` is the process's peak resident memory so far: run one workload per process
// (bench/run.sh BUILD_DIR . neighborhood_bench).
#include <texsyn/io.h>
#include <texsyn/neighborhood.h>

#include <stdexcept>

#include <OpenImageIO/imagebufalgo.h>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;

namespace {

// grass.png resampled to w x h (the benchmark's sample sizes).
OIIO::ImageBuf grass(int w, int h)
{
    OIIO::ImageBuf sample;
    std::string error;
    if (!read_image(std::string(TEXSYN_SAMPLE_DIR) + "/grass.png", sample, error))
        throw std::runtime_error(error);
    if (sample.spec().width == w && sample.spec().height == h)
        return sample;
    return OIIO::ImageBufAlgo::resize(sample, "", 0.0f, OIIO::ROI(0, w, 0, h, 0, 1, 0, 3));
}

struct Workload {
    const char* name;
    int sample_width, sample_height;
    int size;
    int levels;
    std::vector<int> n;
    SearchMethod search;
    int repetitions;
};

void run_workload(benchmark::State& state, const Workload& w)
{
    const OIIO::ImageBuf sample = grass(w.sample_width, w.sample_height);
    NeighborhoodOptions opt;
    opt.width = opt.height = w.size;
    opt.levels = w.levels;
    opt.n = w.n;
    opt.search = w.search;
    opt.nthreads = 2;
    for (auto _ : state) {
        OIIO::ImageBuf out;
        if (!neighborhood_synthesize(out, sample, opt))
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["Mpixels"] = double(w.size) * w.size / 1e6;
}

void register_workloads()
{
    using S = SearchMethod;
    static const Workload workloads[] = {
        { "N1_128_to_256_exhaustive", 128, 128, 256, 1, { 9 }, S::Exhaustive, 3 },
        { "N2_128_to_256_tsvq", 128, 128, 256, 1, { 9 }, S::Tsvq, 5 },
        { "N3_256_to_512_kdtree", 256, 256, 512, 4, { 9, 7, 5, 5 }, S::KdTree, 5 },
        { "N4_256_to_512_coherent", 256, 256, 512, 4, { 9, 7, 5, 5 }, S::Coherent, 5 },
        { "N5_256_to_1024_coherent", 256, 256, 1024, 4, { 9, 7, 5, 5 }, S::Coherent, 5 },
        { "M_200x300_n25_exhaustive", 200, 300, 64, 1, { 25 }, S::Exhaustive, 2 },
        { "M_200x300_n25_tsvq", 200, 300, 64, 1, { 25 }, S::Tsvq, 2 },
        { "M_200x300_n25_kdtree", 200, 300, 64, 1, { 25 }, S::KdTree, 2 },
        { "M_200x300_n25_coherent", 200, 300, 64, 1, { 25 }, S::Coherent, 2 },
    };
    for (const Workload& w : workloads)
        configure_workload(benchmark::RegisterBenchmark(w.name, run_workload, w), w.repetitions);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
