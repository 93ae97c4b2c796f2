// SPDX-License-Identifier: Apache-2.0
// The registry row of the neighbourhood method.
#include <texsyn/neighborhood.h>

#include "methods/source_map_pvt.h"

namespace texsyn::detail {

const Method& neighborhood_method()
{
    static const Method m = copying_method<NeighborhoodOptions>("neighborhood", "neighborhood.md",
        "Wei & Levoy 2000: multi-resolution neighbourhood search (exhaustive, tsvq, kdtree, "
        "coherent), toroidal, with source maps",
        "Wei & Levoy 2000 neighbourhood synthesis of the current image (scanline order, causal "
        "L-shaped neighbourhoods, Gaussian pyramid, toroidal).",
        "texsyn data/samples/pebbles.png --neighborhood:size=256x256 -o pebbles_big.exr",
        "small structures: foliage, grass, pebbles", neighborhood_synthesize);
    return m;
}

} // namespace texsyn::detail
