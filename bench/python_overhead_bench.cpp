// SPDX-License-Identifier: Apache-2.0
// Issue #19's C++ reference: the call bench/python_overhead.py makes from Python, made in
// C++. PY1: rust.png (256x256 RGB, its stored values as float32) -> 1024x1024 pyramid
// synthesis with the defaults, seed 1, 2 threads, I/O excluded. bench/python_overhead.sh
// runs both and compares them; `sum` is the result's pixel sum, which must equal the
// Python run's.
#include <texsyn/pyramid_synthesis.h>

#include <vector>

#include <OpenImageIO/imagebufalgo.h>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;
using texsyn::bench::sample_crop;

namespace {

// The sum of every channel of every pixel, in float64 (the Python run's numpy sum).
double pixel_sum(const OIIO::ImageBuf& image)
{
    std::vector<float> pixels(image.spec().image_pixels() * image.nchannels());
    image.get_pixels(image.roi(), OIIO::TypeFloat, pixels.data());
    double sum = 0;
    for (float v : pixels)
        sum += v;
    return sum;
}

void py1_cpp(benchmark::State& state)
{
    // As Python's oiio.ImageBuf("rust.png").get_pixels(oiio.FLOAT) gives it: the stored
    // values as float, taken as scene-linear by both.
    OIIO::ImageBuf sample;
    sample.copy(sample_crop("rust.png", 256), OIIO::TypeFloat);
    PyramidOptions opt;
    opt.width = opt.height = 1024;
    opt.seed = 1;
    opt.nthreads = 2;
    OIIO::ImageBuf out;
    for (auto _ : state) {
        out = pyramid_synthesize(sample, opt);
        if (out.has_error())
            state.SkipWithError(out.geterror().c_str());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["sum"] = pixel_sum(out);
}

void register_workloads()
{
    configure_workload(benchmark::RegisterBenchmark("PY1_cpp_256_to_1024", py1_cpp), 5);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
