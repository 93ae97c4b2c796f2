// SPDX-License-Identifier: Apache-2.0
// Issue #18's material workload: M1, a 4-map material set (bricks.png with its bundled
// height and normal maps and a roughness map made from the height) synthesized 256x256 ->
// 2048x2048 with --patch's defaults, against the albedo alone (target: the set <= 1.5x the
// albedo's time). 2 threads, seed 0, I/O excluded. Run one workload per process
// (bench/run.sh BUILD_DIR . material_bench).
#include <texsyn/io.h>
#include <texsyn/material.h>
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

OIIO::ImageBuf read_float(const std::string& name)
{
    OIIO::ImageBuf file;
    std::string error;
    if (!read_image(std::string(TEXSYN_SAMPLE_DIR) + "/" + name, file, error))
        throw std::runtime_error(error);
    OIIO::ImageBuf out;
    out.copy(file, OIIO::TypeFloat);
    return out;
}

// The set: albedo and height searched (the default), normal and roughness carried.
Material bricks_material()
{
    Material m;
    m.maps.push_back({ "albedo", MapKind::Colour, 1.0f, read_float("bricks.png") });
    m.maps.push_back({ "normal", MapKind::Normal, 0.0f, read_float("bricks_normal.png") });
    const OIIO::ImageBuf height = read_float("bricks_height.png");
    m.maps.push_back({ "height", MapKind::Data, 1.0f, height });
    m.maps.push_back({ "roughness", MapKind::Data, 0.0f, OIIO::ImageBufAlgo::sub(1.0f, height) });
    return m;
}

PatchOptions options()
{
    PatchOptions opt;
    opt.width = opt.height = 2048;
    opt.nthreads = 2;
    return opt;
}

void albedo_alone(benchmark::State& state)
{
    const OIIO::ImageBuf albedo = read_float("bricks.png");
    for (auto _ : state) {
        OIIO::ImageBuf out;
        if (!patch_synthesize(out, albedo, options()))
            state.SkipWithError(out.geterror().c_str());
        benchmark::DoNotOptimize(out.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
}

void material_set(benchmark::State& state)
{
    const Material material = bricks_material();
    for (auto _ : state) {
        std::string error;
        OIIO::ImageBuf search, out, map;
        Material result;
        if (!material_search_image(material, search, error)
            || !patch_synthesize(out, search, options(), &map)
            || !apply_material(map, material, result, error))
            state.SkipWithError((error.empty() ? out.geterror() : error).c_str());
        benchmark::DoNotOptimize(result.maps.back().image.localpixels());
    }
    state.counters["peak_MB"] = peak_megabytes();
}

void register_workloads()
{
    configure_workload(benchmark::RegisterBenchmark("M1_albedo_alone", albedo_alone), 3);
    configure_workload(benchmark::RegisterBenchmark("M1_4_map_set", material_set), 3);
}

} // namespace

int main(int argc, char** argv)
{
    return texsyn::bench::run_benchmarks(argc, argv, register_workloads);
}
