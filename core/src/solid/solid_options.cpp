// SPDX-License-Identifier: Apache-2.0
#include <texsyn/solid.h>

#include "methods/common_options_pvt.h"
#include "pyramid_synthesis/pyramid_synthesis_pvt.h"

namespace texsyn {

const char* solid_pyramid_name(SolidPyramid kind)
{
    return kind == SolidPyramid::Laplacian ? "laplacian" : "combined";
}

const OptionTable<SolidOptions>& SolidOptions::table()
{
    return declared_table<SolidOptions>([](OptionTable<SolidOptions>& t) {
        using O = SolidOptions;
        t.size3("size", &O::width, &O::height, &O::depth, 16384, // memory refuses far less
            "the sample's width x height x the smaller of them",
            "block size WxHxD in voxels (default: the sample's width and height, and the "
            "smaller of them as depth)");
        detail::add_iterations_option(t);
        t.choice("pyramid", &O::pyramid,
            { { "combined", SolidPyramid::Combined }, { "laplacian", SolidPyramid::Laplacian } },
            "combined: 3-D Laplacian plus steerable pyramids of every xy, xz and yz slice, four "
            "solids averaged (§4's better variant); laplacian: 3-D Laplacian only");
        detail::add_scale_options(t,
            "pyramid scales; 0 = the most that keeps the coarsest band of the sample and of the "
            "block's smallest side >= 8 px",
            "oriented bands per scale of the slices' steerable pyramids (combined only)");
        detail::add_matching_options(t);
        detail::add_flatten(t, "before analysis");
    });
}

bool SolidOptions::validate(std::string& error) const
{
    return table().check(*this, error) && detail::check_fft_backend(fft, error);
}

size_t solid_memory_estimate(int width, int height, int depth, int nchannels)
{
    // Per voxel, in bytes: the output channels (4 each, twice: the volume and the
    // ImageBuf it is returned in); for the one component being
    // synthesized its solid and the average being formed (8), the 3-D Laplacian bands (4 x
    // 8/7) with the copy and expanded level its build keeps alive and its resampling
    // temporaries (12), and the exact matcher's radix-sort scratch (16). The slices'
    // steerable pyramids work on one slice per thread: negligible at block sizes.
    const double n = double(width) * double(height) * double(depth);
    const double bytes = n * (8.0 * nchannels + 8.0 + 4.0 * 8.0 / 7.0 + 12.0 + 16.0);
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
