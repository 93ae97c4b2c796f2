// SPDX-License-Identifier: Apache-2.0
// What the benchmark programs share: peak memory for their `peak_MB` counters, and how
// a workload is run.
#pragma once

#include <sys/resource.h>

#include <benchmark/benchmark.h>

namespace texsyn::bench {

/// The process's peak resident memory so far, in MB (getrusage): run one workload per
/// process (bench/run.sh) to read it per workload.
inline double peak_megabytes()
{
    rusage ru {};
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_maxrss) / 1024.0;
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
