// SPDX-License-Identifier: Apache-2.0
// Issue #14's workloads: whole patch syntheses (I/O excluded), RGB, 2 threads, seed 0,
// default options, on data/samples/bricks.png (256x256; resized for the sample-size rows).
//   T1 256x256 -> 1024x1024 (target: <= 3 s whole process, bench/README.md gives both)
//   T2 256x256 -> 2048x2048 (target: <= 12 s, peak memory <= 1 GB)
//   O-<side>: output side 256, 512, 1024, 2048 from the 256x256 sample (time vs output
//     pixels)
//   S-<side>: sample side 64, 128, 256, 512 to a 512x512 output (time vs sample pixels)
// `peak_MB` is the process's peak resident memory so far: run one workload per process
// (bench/run.sh BUILD_DIR . patch_bench).
#include <texsyn/io.h>
#include <texsyn/patch.h>

#include <stdexcept>
#include <string>

#include <OpenImageIO/imagebufalgo.h>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;

namespace {

// bricks.png resampled to side x side.
OIIO::ImageBuf bricks(int side)
{
    OIIO::ImageBuf sample;
    std::string error;
    if (!read_image(std::string(TEXSYN_SAMPLE_DIR) + "/bricks.png", sample, error))
        throw std::runtime_error(error);
    if (sample.spec().width == side && sample.spec().height == side)
        return sample;
    return OIIO::ImageBufAlgo::resize(sample, "", 0.0f, OIIO::ROI(0, side, 0, side, 0, 1, 0, 3));
}

struct Workload {
    std::string name;
    int sample_side, size, repetitions;
};

void run_workload(benchmark::State& state, const Workload& w)
{
    const OIIO::ImageBuf sample = bricks(w.sample_side);
    PatchOptions opt;
    opt.width = opt.height = w.size;
    opt.nthreads = 2;
    for (auto _ : state) {
        OIIO::ImageBuf out;
        if (!patch_synthesize(out, sample, opt))
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["Mpixels"] = double(w.size) * w.size / 1e6;
}

void register_workloads()
{
    static std::vector<Workload> workloads = {
        { "T1_256_to_1024", 256, 1024, 5 },
        { "T2_256_to_2048", 256, 2048, 3 },
    };
    for (int side : { 256, 512, 1024, 2048 })
        workloads.push_back({ "O_256_to_" + std::to_string(side), 256, side, 3 });
    for (int side : { 64, 128, 256, 512 })
        workloads.push_back({ "S_" + std::to_string(side) + "_to_512", side, 512, 3 });
    for (const Workload& w : workloads)
        configure_workload(
            benchmark::RegisterBenchmark(w.name.c_str(), run_workload, w), w.repetitions);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
