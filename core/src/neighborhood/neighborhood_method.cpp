// SPDX-License-Identifier: Apache-2.0
// The registry row of the neighbourhood method.
#include <texsyn/neighborhood.h>

#include "methods/result_layout_pvt.h"
#include "methods/source_map_pvt.h"
#include "neighborhood_pvt.h"

namespace texsyn::detail {

namespace {

// It tiles unless tile=0 (Wei & Levoy's single pass).
bool neighborhood_layout(const NeighborhoodOptions& opt, const InputLayout& sample,
    const MethodOptions& options, ResultLayout& layout, std::string& error)
{
    layout = layout_from_input(sample, options);
    layout.set_tiles(opt.tile != 0);
    return check_neighborhood_sizes(
        sample.width, sample.height, layout.width, layout.height, opt, error);
}

} // namespace

const Method& neighborhood_method()
{
    static const Method m = copying_method<NeighborhoodOptions>("neighborhood", "neighborhood.md",
        "Wei & Levoy 2000: multi-resolution neighbourhood search (exhaustive, tsvq, kdtree, "
        "coherent), toroidal, with source maps",
        "Wei & Levoy 2000 neighbourhood synthesis of the current image (scanline order, causal "
        "L-shaped neighbourhoods, Gaussian pyramid, toroidal).",
        "texsyn data/samples/pebbles.png --neighborhood:size=256x256 -o pebbles_big.exr",
        "small structures: foliage, grass, pebbles", neighborhood_synthesize, neighborhood_layout);
    return m;
}

} // namespace texsyn::detail
