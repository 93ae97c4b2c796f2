// SPDX-License-Identifier: Apache-2.0
// The neighbourhood method's options: table, validation, memory estimate.
#include <texsyn/neighborhood.h>

#include <algorithm>

#include "methods/common_options_pvt.h"
#include "neighborhood_pvt.h"

namespace texsyn {

const OptionTable<NeighborhoodOptions>& NeighborhoodOptions::table()
{
    return declared_table<NeighborhoodOptions>([](OptionTable<NeighborhoodOptions>& t) {
        using O = NeighborhoodOptions;
        constexpr int max_levels = 8;
        constexpr int max_n = 63; // the widest neighbourhood, ~2000 pixels per vector
        detail::add_output_size(t);
        detail::add_levels(t, max_levels,
            "Gaussian pyramid levels, synthesized coarse to fine (1 = single resolution)");
        t.odd_integers("n", &O::n, 3, max_n, max_levels,
            "neighbourhood width per level, odd, finest first (one value = every level; "
            "coarser levels missing from the list repeat the last)");
        t.odd_integer("coarse", &O::coarse, 1, max_n,
            "side of the full square taken around the parent at the next coarser level");
        t.choice("search", &O::search,
            { { "exhaustive", SearchMethod::Exhaustive }, { "tsvq", SearchMethod::Tsvq },
                { "kdtree", SearchMethod::KdTree }, { "coherent", SearchMethod::Coherent } },
            "search back-end: exhaustive (exact), tsvq (tree-structured VQ), kdtree (PCA + "
            "kd-tree), coherent (k-coherence)");
        t.integer("candidates", &O::candidates, 1, 64,
            "tsvq: leaves visited (backtracking); kdtree and coherent's kd-tree: nearest in PCA "
            "space re-ranked by full distance");
        t.integer("dims", &O::dims, 0, 4096,
            "kdtree: PCA components kept; 0 = enough for 95% of the variance");
        detail::add_kdtree_eps(t);
        t.integer("coherence", &O::coherence, 1, 16,
            "coherent: k of k-coherence (each shifted neighbour's source and its k-1 most "
            "similar sample positions)");
        t.integer("merge", &O::merge, 0, 1, "coherent: 1 = also take the kd-tree's match");
        t.integer("tile", &O::tile, 0, 1,
            "1 = re-synthesize the pixels near the wrap-around seams with square neighbourhoods "
            "that see both sides, so the output tiles; 0 = Wei & Levoy's single pass");
        detail::add_flatten(t);
        detail::add_scale(t);
        t.choice("shape", &O::shape,
            { { "causal", NeighborhoodShape::Causal }, { "square", NeighborhoodShape::Square } },
            "debug: causal (the L of already synthesized pixels) or square (unsynthesized noise "
            "included, the report's Figure 3c)");
    });
}

bool NeighborhoodOptions::validate(std::string& error) const
{
    return table().check(*this, error)
        && check_level_list("n", format_int_list(n), n.size(), levels, error);
}

int NeighborhoodOptions::n_at(int level) const
{
    return at_level(n, level, 9);
}

size_t neighborhood_memory_estimate(int sample_width, int sample_height, int nchannels,
    int out_width, int out_height, const NeighborhoodOptions& opt)
{
    // The finest level dominates: its sample vectors (of the square layout when seams are
    // repaired) (count x dim floats) and a searcher
    // about as large again (TSVQ centroids, kd-tree PCA copies, k-coherence lists), plus
    // the output's pyramid and source maps (~ 4/3 x (channels + 2) values per pixel), the
    // result as a float image and the copy every front end makes to write or return it (2
    // x channels values per pixel: measured whole processes, RGB, 56 bytes per output
    // pixel at 4096x4096 and 8192x8192; bench/README.md), and the sample's pyramid.
    const detail::NeighborhoodLayout layout = detail::make_layout(
        opt.n_at(0), opt.coarse, opt.levels > 1, opt.tile ? NeighborhoodShape::Square : opt.shape);
    const double count = double(sample_width) * double(sample_height);
    const double dim = double(layout.npixels()) * double(nchannels);
    const double vectors = count * dim * 4.0;
    const double out = double(out_width) * double(out_height)
        * (4.0 / 3.0 * (4.0 * nchannels + 8.0) + 8.0 * nchannels);
    const double bytes = 2.0 * vectors + out + count * 4.0 / 3.0 * 4.0 * nchannels;
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
