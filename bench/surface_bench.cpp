// SPDX-License-Identifier: Apache-2.0
// Issue #17's workloads: whole runs of the registry row choosy-surface (mesh reading and
// checks included, sample reading and PLY writing excluded), rust.png (RGB, as stored)
// cropped to n x n, 2 threads, seed 0, default options (kd-trees, dims=20, eps=30, one
// iteration per level, remesh=auto) unless named.
//   S1 sphere.obj (1,620 faces), levels=4 (103,680 faces) from 96x96 (target: <= 10 s)
//   S2 cow.obj (5,804 faces), levels=5 (1,485,824 faces) from 160x160 (target: <= 120 s,
//      <= 4 GB); remesh=auto remeshes the cow (uneven faces) to 5,804 even ones
//   S2_asis = S2 with remesh=0: the cow as given (slivers: sigma is 7.6x the mean
//      distance between adjacent faces)
//   M_<search>_L<levels>: scaling in the faces M (eq. 8), sphere.obj at levels 2..5
//   N_<search>_N<n>: scaling in the sample N, sphere.obj at levels=2 (6,480 faces)
// `peak_MB` is the process's peak resident memory so far: run one workload per process
// (bench/run.sh BUILD_DIR . surface_bench).
#include <texsyn/methods.h>
#include <texsyn/surface.h>

#include <string>

#include <benchmark/benchmark.h>

#include "bench_common.h"

using namespace texsyn;
using texsyn::bench::configure_workload;
using texsyn::bench::peak_megabytes;
using texsyn::bench::sample_crop;

namespace {

struct Workload {
    std::string name;
    std::string mesh;
    int levels;
    int sample_size;
    ChoosySearch search;
    int repetitions;
    bool remesh = true; ///< remesh=auto (the default); false: remesh=0
    BoundarySlots boundary = BoundarySlots::Own;
};

void run_workload(benchmark::State& state, const Workload& w)
{
    const OIIO::ImageBuf sample = sample_crop("rust.png", w.sample_size);
    const Method* method = find_method("choosy-surface");
    SurfaceOptions opt;
    opt.mesh = std::string(TEXSYN_MESH_DIR) + "/" + w.mesh;
    opt.options.levels = w.levels;
    opt.options.search = w.search;
    if (!w.remesh)
        opt.remesh = 0;
    opt.boundary = w.boundary;
    const std::vector<MethodInput> inputs = { { &sample, nullptr, "rust.png" } };
    RunSettings settings;
    settings.nthreads = 2;
    size_t faces = 0;
    for (auto _ : state) {
        MethodResult result;
        std::string error;
        if (!method
            || !run_method(*method, MethodOptions(opt), inputs, {}, settings, result, error))
            state.SkipWithError(method ? error.c_str() : "no choosy-surface row");
        faces = result.surface ? result.surface->faces.size() : 0;
        benchmark::DoNotOptimize(result.surface.get());
    }
    state.counters["peak_MB"] = peak_megabytes();
    state.counters["faces"] = double(faces);
}

void register_workloads()
{
    using S = ChoosySearch;
    static std::vector<Workload> workloads = {
        { "S1_sphere_L4_N96", "sphere.obj", 4, 96, S::KdTree, 3 },
        { "S2_cow_L5_N160", "cow.obj", 5, 160, S::KdTree, 1 },
        { "S2_asis_cow_L5_N160", "cow.obj", 5, 160, S::KdTree, 1, false },
    };
    // Eq. 8 in M: the sphere at levels 2..5 (6,480 to 414,720 faces) from 128x128 with
    // kd-trees, and at levels 2..3 from 32x32 exhaustively.
    for (int levels : { 2, 3, 4, 5 })
        workloads.push_back(
            { "M_kdtree_L" + std::to_string(levels), "sphere.obj", levels, 128, S::KdTree, 2 });
    for (int levels : { 2, 3 })
        workloads.push_back({ "M_exhaustive_L" + std::to_string(levels), "sphere.obj", levels, 32,
            S::Exhaustive, 2 });
    // What boundary=wildcards costs: the mushroom (one boundary loop) with each rule, at 3
    // levels from 96x96 and at 4 levels from 128x128 (docs/surfaces.md).
    for (const auto& [levels, n] : { std::pair { 3, 96 }, std::pair { 4, 128 } })
        for (BoundarySlots b : { BoundarySlots::Own, BoundarySlots::Wildcards })
            workloads.push_back({ std::string(b == BoundarySlots::Own ? "W_own" : "W_wildcards")
                    + "_L" + std::to_string(levels) + "_N" + std::to_string(n),
                "mushroom.obj", levels, n, S::KdTree, 3, true, b });
    // Eq. 8 in N: the sphere at levels=2 (6,480 faces) from n x n, both searches.
    for (int n : { 16, 32, 48, 64 })
        for (S s : { S::KdTree, S::Exhaustive })
            workloads.push_back(
                { std::string(s == S::KdTree ? "N_kdtree_N" : "N_exhaustive_N") + std::to_string(n),
                    "sphere.obj", 2, n, s, 2 });
    for (const Workload& w : workloads)
        configure_workload(
            benchmark::RegisterBenchmark(w.name.c_str(), run_workload, w), w.repetitions);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
