// SPDX-License-Identifier: Apache-2.0
// Issue #2's workloads: whole pyramid syntheses (I/O excluded), RGB, 4 orientations,
// 5 iterations, default scales, 2 threads.
//   P1 128x128 -> 512x512, P2 256x256 -> 1024x1024, P3 256x256 -> 2048x2048 (steerable)
//   P4 = P2 with the Laplacian pyramid
// Each with every FFT backend this build has. `peak_MB` is the process's peak resident
// memory so far: run one workload per process (bench/run.sh) to read it per workload.
#include <texsyn/io.h>
#include <texsyn/pyramid_synthesis.h>

#include <OpenImageIO/imagebufalgo.h>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;

namespace {

OIIO::ImageBuf sample_of_size(int size)
{
    OIIO::ImageBuf file;
    std::string error;
    if (!read_image(std::string(TEXSYN_SAMPLE_DIR) + "/rust.png", file, error))
        throw std::runtime_error(error);
    // rust.png is 256x256; P1 uses its top-left 128x128 crop.
    return OIIO::ImageBufAlgo::cut(file, OIIO::ROI(0, size, 0, size));
}

void run_workload(
    benchmark::State& state, int sample_size, int out_size, PyramidKind kind, FftBackend fft)
{
    if (!fft_backend_available(fft)) {
        state.SkipWithError("FFT backend not built in");
        return;
    }
    OIIO::ImageBuf sample = sample_of_size(sample_size);
    PyramidOptions opt;
    opt.width = opt.height = out_size;
    opt.pyramid = kind;
    opt.fft = fft;
    opt.nthreads = 2;
    for (auto _ : state) {
        OIIO::ImageBuf out = pyramid_synthesize(sample, opt);
        if (out.has_error())
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["out_Mpx"] = double(out_size) * out_size / 1e6;
}

void register_workloads()
{
    struct Workload {
        const char* name;
        int sample, out;
        PyramidKind kind;
    };
    const Workload workloads[] = {
        { "P1_128_to_512", 128, 512, PyramidKind::Steerable },
        { "P2_256_to_1024", 256, 1024, PyramidKind::Steerable },
        { "P3_256_to_2048", 256, 2048, PyramidKind::Steerable },
        { "P4_256_to_1024_laplacian", 256, 1024, PyramidKind::Laplacian },
    };
    for (const Workload& w : workloads)
        for (FftBackend fft : { FftBackend::Kiss, FftBackend::Fftw }) {
            std::string name = std::string(w.name) + "/" + fft_backend_name(fft);
            configure_workload(benchmark::RegisterBenchmark(
                                   name.c_str(), run_workload, w.sample, w.out, w.kind, fft),
                5);
        }
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
