// SPDX-License-Identifier: Apache-2.0
// The neighbourhood method's options: table, validation, memory estimate.
#include <texsyn/neighborhood.h>

#include <algorithm>

#include "neighborhood_pvt.h"

namespace texsyn {

namespace {
constexpr int kMaxSide = 65536; // per side of the output; memory refuses far less anyway
constexpr int kMaxN = 63;       // widest neighbourhood (63x63: ~2000 pixels per vector)
constexpr int kMaxLevels = 8;
} // namespace

const OptionTable<NeighborhoodOptions>& NeighborhoodOptions::table()
{
    using O = NeighborhoodOptions;
    static const OptionTable<O> t = [] {
        OptionTable<O> t;
        t.size("size", &O::width, &O::height, kMaxSide, "the sample's size",
            "output size WxH (default: the sample's size)");
        t.integer("levels", &O::levels, 1, kMaxLevels,
            "Gaussian pyramid levels, synthesized coarse to fine (1 = single resolution)");
        t.integers("n", &O::n, 3, kMaxN, kMaxLevels,
            "neighbourhood width per level, odd, finest first (one value = every level; "
            "coarser levels missing from the list repeat the last)");
        t.integer("coarse", &O::coarse, 1, kMaxN,
            "side of the full square taken around the parent at the next coarser level (odd)");
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
        t.real("eps", &O::eps, 0.0f, 100.0f,
            "kdtree: approximation factor (a match's squared distance in PCA space may be "
            "(1+eps) times the nearest's)");
        t.integer("coherence", &O::coherence, 1, 16,
            "coherent: k of k-coherence (each shifted neighbour's source and its k-1 most "
            "similar sample positions)");
        t.integer("merge", &O::merge, 0, 1, "coherent: 1 = also take the kd-tree's match");
        t.integer("tile", &O::tile, 0, 1,
            "1 = re-synthesize the pixels near the wrap-around seams with square neighbourhoods "
            "that see both sides, so the output tiles; 0 = Wei & Levoy's single pass");
        t.choice("shape", &O::shape,
            { { "causal", NeighborhoodShape::Causal }, { "square", NeighborhoodShape::Square } },
            "debug: causal (the L of already synthesized pixels) or square (unsynthesized noise "
            "included, the report's Figure 3c)");
        return t;
    }();
    return t;
}

bool NeighborhoodOptions::validate(std::string& error) const
{
    if (!check_size_range(width, height, kMaxSide, error)
        || !check_int_range("levels", levels, 1, kMaxLevels, error)
        || !check_level_list("n", n, levels, error))
        return false;
    for (int v : n)
        if (v < 3 || v > kMaxN || v % 2 == 0) {
            error = "n=" + format_int_list(n) + " : " + std::to_string(v)
                + " is not an odd width in 3.." + std::to_string(kMaxN);
            return false;
        }
    if (coarse < 1 || coarse > kMaxN || coarse % 2 == 0) {
        error = "coarse=" + std::to_string(coarse) + " is not an odd width in 1.."
            + std::to_string(kMaxN);
        return false;
    }
    if (candidates < 1 || candidates > 64 || dims < 0 || !(eps >= 0.0f && eps <= 100.0f)
        || coherence < 1 || coherence > 16 || (merge != 0 && merge != 1)
        || (tile != 0 && tile != 1)) {
        error = "candidates, dims, eps, coherence, merge or tile is out of range (see --help)";
        return false;
    }
    return true;
}

int NeighborhoodOptions::n_at(int level) const
{
    if (n.empty())
        return 9;
    return n[size_t(std::min<int>(level, int(n.size()) - 1))];
}

size_t neighborhood_memory_estimate(int sample_width, int sample_height, int nchannels,
    int out_width, int out_height, const NeighborhoodOptions& opt)
{
    // The finest level dominates: its sample vectors (of the square layout when seams are
    // repaired) (count x dim floats) and a searcher
    // about as large again (TSVQ centroids, kd-tree PCA copies, k-coherence lists), plus
    // the output's pyramid and source maps (~ 4/3 x (channels + 2) values per pixel) and
    // the sample's pyramid.
    const detail::NeighborhoodLayout layout = detail::make_layout(
        opt.n_at(0), opt.coarse, opt.levels > 1, opt.tile ? NeighborhoodShape::Square : opt.shape);
    const double count = double(sample_width) * double(sample_height);
    const double dim = double(layout.npixels()) * double(nchannels);
    const double vectors = count * dim * 4.0;
    const double out = double(out_width) * double(out_height) * 4.0 / 3.0 * (4.0 * nchannels + 8.0);
    const double bytes = 2.0 * vectors + out + count * 4.0 / 3.0 * 4.0 * nchannels;
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
