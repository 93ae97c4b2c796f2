// SPDX-License-Identifier: Apache-2.0
// Issue #7's workloads: whole cascade_synthesize calls from noise (no I/O), 2 threads, seed 0.
//   K1 1024x1024, 1 level, 5 iterations, 7x7 Gaussian kernel (target: <= 0.3 s)
//   K2 a 6-level cascade to 4096x4096 (128x128 .. 4096x4096), 5 iterations per level, 7x7
//      Gaussian kernel (target: <= 3 s)
//   K3 = K1 with a dilation control image (the bilinear per-pixel path), dmin=1, dmax=3
// `peak_MB` is the process's peak resident memory so far: run one workload per process
// (bench/run.sh BUILD_DIR . cascade_bench).
#include <texsyn/cascade.h>
#include <texsyn/image.h>

#include <OpenImageIO/imagebuf.h>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;

namespace {

struct Workload {
    const char* name;
    int size;
    int levels;
    bool dilated;
    int repetitions;
};

// A horizontal ramp from 0 to 1: the dilation control of K3.
OIIO::ImageBuf ramp_control(int size)
{
    PlanarImage p;
    p.channels = { Plane(size, size) };
    p.channel_names = { "Y" };
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            p.channels[0](x, y) = float(x) / float(size - 1);
    OIIO::ImageBuf buf;
    imagebuf_from_planes(p, buf, false);
    return buf;
}

void run_workload(benchmark::State& state, const Workload& w)
{
    CascadeOptions opt;
    opt.width = opt.height = w.size;
    opt.levels = w.levels;
    opt.kernel = { CascadeKernel::Gauss7 };
    opt.dmin = 1.0f;
    opt.dmax = 3.0f;
    opt.nthreads = 2;
    const OIIO::ImageBuf control = ramp_control(w.dilated ? w.size : 2);
    for (auto _ : state) {
        OIIO::ImageBuf out;
        if (!cascade_synthesize(out, opt, nullptr, w.dilated ? &control : nullptr))
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["Mpixels"] = double(w.size) * w.size / 1e6;
}

void register_workloads()
{
    static const Workload workloads[] = {
        { "K1_1024_5it_7x7", 1024, 1, false, 5 },
        { "K2_6levels_to_4096_7x7", 4096, 6, false, 5 },
        { "K3_1024_5it_7x7_dilated", 1024, 1, true, 3 },
    };
    for (const Workload& w : workloads)
        configure_workload(benchmark::RegisterBenchmark(w.name, run_workload, w), w.repetitions);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
