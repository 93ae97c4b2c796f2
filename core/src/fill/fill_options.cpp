// SPDX-License-Identifier: Apache-2.0
// The fill's options: table and validation.
#include <texsyn/fill.h>

#include "methods/common_options_pvt.h"
#include "patch/patch_options_pvt.h"

namespace texsyn {

namespace {

constexpr int kMaxLevels = 8;

} // namespace

const OptionTable<FillOptions>& FillOptions::table()
{
    return declared_table<FillOptions>([](OptionTable<FillOptions>& t) {
        using O = FillOptions;
        t.integer("levels", &O::levels, 0, kMaxLevels,
             "Gaussian pyramid levels, filled coarse to fine; 0 = from each hole's thickness "
             "(at most three of the largest patches at the coarsest level; at least 3 where "
             "the image is large enough)")
            .shared();
        detail::add_patch_schedule(t, kMaxLevels, "11,7 (smaller for an image under 33 px)",
            "4 at the finest level, 6 at the next, 8 at the coarser ones");
        t.integer("context", &O::context, 0, 1 << 16,
            "pixels around each hole's bounding box that patches are taken from; 0 = "
            "automatic (enough for the coarsest level, and at least half the hole's size)");
        t.real("repetition", &O::repetition, 0.0f, 10.0f,
            "spatial-uniformity penalty: a source patch used more often than an even use "
            "of the context would use it costs more (against repeats in large holes); 0 = "
            "none");
        t.real("guidance", &O::guidance, 0.0f, 10.0f,
            "weight of the guidance channel (distance to the nearest edge), filled with the "
            "colours so that joints and outlines stay whole; 0 = none");
        detail::add_patch_terms(t);
        t.choice("outline", &O::outline,
            { { "match", FillOutline::Match }, { "copy", FillOutline::Copy } },
            "how the fill meets the kept pixels at the mask's outline: match (the copies are "
            "offset smoothly so that they meet without a step, like a healing brush: no "
            "contour on a soft plate) or copy (exact copies of known pixels, as the source "
            "map records them)");
        detail::add_flatten(
            t, "from what the search compares (the copies are still the image's own pixels)");
    });
}

bool FillOptions::validate(std::string& error) const
{
    return table().check(*this, error)
        && detail::check_patch_schedule(patch, iterations, levels, error);
}

int FillOptions::iterations_at(int level) const
{
    if (iterations.empty())
        return level == 0 ? 4 : level == 1 ? 6 : 8;
    return at_level(iterations, level, 1);
}

} // namespace texsyn
