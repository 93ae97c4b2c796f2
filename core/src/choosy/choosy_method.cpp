// SPDX-License-Identifier: Apache-2.0
// The registry row of choosy sampling.
#include <texsyn/choosy.h>

#include "methods/source_map_pvt.h"

namespace texsyn::detail {

const Method& choosy_method()
{
    static const Method m = copying_method<ChoosyOptions>("choosy", "choosy.md",
        "Castellanos & Williams: choosy sampling (use-count penalty keeps the sample's "
        "histogram), toroidal, with source maps; isotropic=1 for isotropic variants",
        "Castellanos & Williams choosy sampling of the current image: coarse to fine by "
        "Laplacian inversion, each sample pixel's score penalised by its use count (keeps the "
        "sample's histogram), toroidal; the sample's orientation unless isotropic=1. Each side of "
        "size must be a "
        "multiple of 2^(levels-1).",
        choosy_synthesize);
    return m;
}

} // namespace texsyn::detail
