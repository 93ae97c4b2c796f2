// SPDX-License-Identifier: Apache-2.0
// The registry row of choosy sampling.
#include <texsyn/choosy.h>

#include <algorithm>

#include "choosy_pvt.h"
#include "methods/result_layout_pvt.h"
#include "methods/source_map_pvt.h"

namespace texsyn::detail {

namespace {

// Without size=, the sample's size cropped to a multiple of 2^(levels-1).
bool choosy_layout(const ChoosyOptions& opt, const InputLayout& sample,
    const MethodOptions& options, ResultLayout& layout, std::string& error)
{
    layout = layout_from_input(sample, options);
    const int unit = 1 << (opt.levels - 1);
    if (!opt.width)
        layout.width = std::max(sample.width / unit * unit, 1);
    if (!opt.height)
        layout.height = std::max(sample.height / unit * unit, 1);
    return check_choosy_sizes(sample.width, sample.height, layout.width, layout.height, opt, error);
}

} // namespace

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
        "texsyn data/samples/leaves_autumn.png --choosy:size=256x256 -o leaves_big.exr",
        "the sample's colour histogram kept exactly", choosy_synthesize, choosy_layout);
    return m;
}

} // namespace texsyn::detail
