// SPDX-License-Identifier: Apache-2.0
// Issue #18's fill workloads: texture_fill() of a 256x256 square hole in the middle of a
// float RGB plate (data/samples/bricks.png tiled), 2 threads, seed 0, default options, I/O
// excluded (bench/README.md gives the whole process too).
//   F1_<side>: plates of 1024, 2048 (F1 proper: target <= 5 s whole process) and 4096
//     pixels a side: the time must follow the hole, not the plate.
// `peak_MB` is the process's peak resident memory so far: run one workload per process
// (bench/run.sh BUILD_DIR . fill_bench).
#include <texsyn/fill.h>
#include <texsyn/io.h>

#include <stdexcept>
#include <string>

#include <OpenImageIO/imagebufalgo.h>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;

namespace {

// bricks.png tiled to side x side, as float.
OIIO::ImageBuf plate(int side)
{
    OIIO::ImageBuf sample;
    std::string error;
    if (!read_image(std::string(TEXSYN_SAMPLE_DIR) + "/bricks.png", sample, error))
        throw std::runtime_error(error);
    OIIO::ImageBuf out(OIIO::ImageSpec(side, side, 3, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < side; y += sample.spec().height)
        for (int x = 0; x < side; x += sample.spec().width)
            OIIO::ImageBufAlgo::paste(out, x, y, 0, 0, sample);
    return out;
}

// A one-channel side x side mask with a 256x256 square of ones in the middle.
OIIO::ImageBuf square_hole(int side)
{
    OIIO::ImageBuf mask(OIIO::ImageSpec(side, side, 1, OIIO::TypeDesc::FLOAT));
    const float one = 1.0f;
    const int a = side / 2 - 128;
    OIIO::ImageBufAlgo::fill(mask, &one, OIIO::ROI(a, a + 256, a, a + 256));
    return mask;
}

void run_workload(benchmark::State& state, int side)
{
    const OIIO::ImageBuf image = plate(side), mask = square_hole(side);
    FillOptions opt;
    opt.nthreads = 2;
    for (auto _ : state) {
        OIIO::ImageBuf out;
        if (!texture_fill(out, image, mask, opt))
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["Mpixels"] = double(side) * side / 1e6;
}

void register_workloads()
{
    for (int side : { 1024, 2048, 4096 })
        configure_workload(benchmark::RegisterBenchmark(
                               ("F1_" + std::to_string(side)).c_str(), run_workload, side),
            3);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
