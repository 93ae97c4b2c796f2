// SPDX-License-Identifier: Apache-2.0
// Issue #4's workloads: whole solid syntheses (I/O excluded), RGB, 5 iterations, default
// scales, 4 orientations, KissFFT, 2 threads.
//   S1 marble_pink 128x128 -> 128^3, combined (target: <= 60 s)
//   S2 = S1 with pyramid=laplacian
//   S3 rust 256x256 -> 256^3, combined (target: <= 2 GB)
// `peak_MB` is the process's peak resident memory so far: run one workload per process
// (bench/run.sh BUILD_DIR . solid_bench).
#include <texsyn/io.h>
#include <texsyn/solid.h>
#include <texsyn/volume.h>

#include <stdexcept>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;

namespace {

void run_workload(benchmark::State& state, const char* sample_name, int size, SolidPyramid kind)
{
    OIIO::ImageBuf sample;
    std::string error;
    if (!read_image(std::string(TEXSYN_SAMPLE_DIR) + "/" + sample_name, sample, error))
        throw std::runtime_error(error);
    SolidOptions opt;
    opt.width = opt.height = opt.depth = size;
    opt.pyramid = kind;
    opt.nthreads = 2;
    for (auto _ : state) {
        OIIO::ImageBuf out;
        if (!solid_synthesize(out, sample, opt))
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["Mvoxels"] = double(size) * size * size / 1e6;
}

void register_workloads()
{
    struct Workload {
        const char* name;
        const char* sample;
        int size;
        SolidPyramid kind;
        int repetitions;
    };
    const Workload workloads[] = {
        { "S1_128_to_128cubed", "marble_pink.png", 128, SolidPyramid::Combined, 3 },
        { "S2_128_to_128cubed_laplacian", "marble_pink.png", 128, SolidPyramid::Laplacian, 3 },
        { "S3_256_to_256cubed", "rust.png", 256, SolidPyramid::Combined, 2 },
    };
    for (const Workload& w : workloads)
        configure_workload(
            benchmark::RegisterBenchmark(w.name, run_workload, w.sample, w.size, w.kind),
            w.repetitions);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
