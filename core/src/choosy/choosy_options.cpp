// SPDX-License-Identifier: Apache-2.0
// Choosy sampling's options: table, validation, memory estimate.
#include <texsyn/choosy.h>

#include <algorithm>
#include <cmath>

#include "choosy_pvt.h"
#include "methods/common_options_pvt.h"

namespace texsyn {

const OptionTable<ChoosyOptions>& ChoosyOptions::table()
{
    return declared_table<ChoosyOptions>([](OptionTable<ChoosyOptions>& t) {
        using O = ChoosyOptions;
        constexpr int max_levels = 8;
        detail::add_output_size(t,
            "output size WxH, each side a multiple of 2^(levels-1) (default: the sample's size, "
            "cropped to one)");
        detail::add_levels(
            t, max_levels, "Gaussian/Laplacian pyramid levels, synthesized coarse to fine");
        t.integers("iterations", &O::iterations, 1, 64, max_levels,
            "choosy passes per level, finest first (one value = every level; coarser levels "
            "missing from the list repeat the last: 1,8 is the paper's Fig. 10(c))");
        t.real("penalty", &O::penalty, 0.0f, 16.0f,
            "a sample neighbourhood used c times scores distance x 2^(penalty (c - c_min)): "
            "1 = choosy sampling, 0 = greedy best match (Wei & Levoy's selection)");
        t.integer("isotropic", &O::isotropic, 0, 1,
            "1 = also match the sample rotated and mirrored (8 orientations): isotropic "
            "variants of anisotropic samples; 0 = keep the sample's orientation");
        detail::add_flatten(t);
        detail::add_scale(t);
        t.choice("search", &O::search,
            { { "exhaustive", ChoosySearch::Exhaustive }, { "kdtree", ChoosySearch::KdTree } },
            "exhaustive (every neighbourhood, full dimension, exact) or kdtree (principal "
            "components in a set of dynamic kd-trees, one per use count)");
        t.integer("dims", &O::dims, 1, 4096,
            "kdtree: principal components kept (24 x channels or more = all: exact)");
        detail::add_kdtree_eps(t);
    });
}

bool ChoosyOptions::validate(std::string& error) const
{
    return table().check(*this, error)
        && check_level_list(
            "iterations", format_int_list(iterations), iterations.size(), levels, error);
}

int ChoosyOptions::iterations_at(int level) const
{
    return at_level(iterations, level, 1);
}

size_t choosy_memory_estimate(int sample_width, int sample_height, int nchannels, int out_width,
    int out_height, const ChoosyOptions& opt)
{
    // The finest level dominates: its points (every orientation) in full dimension for the
    // exhaustive search, or projected (and copied once more into the trees) for the
    // kd-trees; plus the output's planes (Gaussian, Laplacian children, next level's start,
    // source: ~ (3 channels + 1) values per output pixel at the finest level, 4/3 of it over
    // all levels) and the sample's two pyramids.
    const double orientations = opt.isotropic ? 8.0 : 1.0;
    const double points = double(sample_width) * double(sample_height) * orientations;
    const double dim = double(detail::ring_slots().size()) * double(nchannels);
    const double per_point = opt.search == ChoosySearch::Exhaustive
        ? dim
        : 2.0 * std::min(dim, double(opt.dims)) + 2.0;
    const double out = double(out_width) * double(out_height) * 4.0 / 3.0 * (3.0 * nchannels + 1.0);
    const double sample = double(sample_width) * double(sample_height) * 8.0 / 3.0 * nchannels;
    const double bytes = 4.0 * (points * per_point + out + sample);
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
