// SPDX-License-Identifier: Apache-2.0
#include "synthesis_pvt.h"

namespace texsyn {

namespace {
constexpr int kMaxSide = 16384; // per side of the block; memory refuses far less anyway
}

const char* solid_pyramid_name(SolidPyramid kind)
{
    return kind == SolidPyramid::Laplacian ? "laplacian" : "combined";
}

const OptionTable<SolidOptions>& SolidOptions::table()
{
    using O = SolidOptions;
    static const OptionTable<O> t = [] {
        OptionTable<O> t;
        t.size3("size", &O::width, &O::height, &O::depth, kMaxSide,
            "the sample's width x height x the smaller of them",
            "block size WxHxD in voxels (default: the sample's width and height, and the "
            "smaller of them as depth)");
        detail::add_iterations_option(t);
        t.choice("pyramid", &O::pyramid,
            { { "combined", SolidPyramid::Combined }, { "laplacian", SolidPyramid::Laplacian } },
            "combined: 3-D Laplacian plus steerable pyramids of every xy, xz and yz slice, four "
            "solids averaged (§4's better variant); laplacian: 3-D Laplacian only");
        t.integer("scales", &O::scales, 0, 16,
            "pyramid scales; 0 = the most that keeps the coarsest band of the sample and of the "
            "block's smallest side >= 8 px");
        t.integer("orientations", &O::orientations, 1, 8,
            "oriented bands per scale of the slices' steerable pyramids (combined only)");
        detail::add_matching_options(t);
        return t;
    }();
    return t;
}

bool SolidOptions::validate(std::string& error) const
{
    const bool zero = width == 0 && height == 0 && depth == 0;
    if (!zero
        && (width < 1 || height < 1 || depth < 1 || width > kMaxSide || height > kMaxSide
            || depth > kMaxSide)) {
        error = "size=" + std::to_string(width) + "x" + std::to_string(height) + "x"
            + std::to_string(depth) + " is out of range (each side 1.." + std::to_string(kMaxSide)
            + ")";
        return false;
    }
    // The rest are the pyramid method's own options, with its ranges and messages.
    PyramidOptions p;
    p.iterations = iterations;
    p.scales = scales;
    p.orientations = orientations;
    p.histogram = histogram;
    p.fft = fft;
    return p.validate(error);
}

size_t solid_memory_estimate(int width, int height, int depth, int nchannels)
{
    // Per voxel, in bytes: the output channels (4 each); for the one component being
    // synthesized its solid and the average being formed (8), the 3-D Laplacian bands (4 x
    // 8/7) with the copy and expanded level its build keeps alive and its resampling
    // temporaries (12), and the exact matcher's radix-sort scratch (16). The slices'
    // steerable pyramids work on one slice per thread: negligible at block sizes.
    const double n = double(width) * double(height) * double(depth);
    const double bytes = n * (4.0 * nchannels + 8.0 + 4.0 * 8.0 / 7.0 + 12.0 + 16.0);
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
