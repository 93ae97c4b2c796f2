// SPDX-License-Identifier: Apache-2.0
// What the benchmark programs share: peak memory for their `peak_MB` counters, bundled
// samples, and how a workload is run.
#pragma once

#include <sys/resource.h>

#include <stdexcept>
#include <string>

#include <OpenImageIO/imagebufalgo.h>

#include <benchmark/benchmark.h>

#include <texsyn/io.h>

namespace texsyn::bench {

/// The process's peak resident memory so far, in MB (getrusage): run one workload per
/// process (bench/run.sh) to read it per workload.
inline double peak_megabytes()
{
    rusage ru {};
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_maxrss) / 1024.0;
}

/// The top-left n x n (first three channels) of a bundled sample (data/samples/<name>),
/// as stored; throws if it cannot be read.
inline OIIO::ImageBuf sample_crop(const std::string& name, int n)
{
    OIIO::ImageBuf sample;
    std::string error;
    if (!texsyn::read_image(std::string(TEXSYN_SAMPLE_DIR) + "/" + name, sample, error))
        throw std::runtime_error(error);
    return OIIO::ImageBufAlgo::cut(sample, OIIO::ROI(0, n, 0, n, 0, 1, 0, 3));
}

/// A whole synthesis per iteration, wall time in ms, `repetitions` runs reported as
/// aggregates (median, mean, spread).
inline void configure_workload(benchmark::internal::Benchmark* b, int repetitions)
{
    b->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Iterations(1)
        ->Repetitions(repetitions)
        ->ReportAggregatesOnly(true);
}

/// A benchmark program's main(): registers its workloads, then runs what the command line
/// selects.
inline int run_benchmarks(int argc, char** argv, void (*register_workloads)())
{
    register_workloads();
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

} // namespace texsyn::bench
