// SPDX-License-Identifier: Apache-2.0
// The automatic EM schedule: patch sizes, levels and iterations from the sample.
#include "patch_schedule_pvt.h"

#include <algorithm>
#include <cmath>

namespace texsyn::detail {

namespace {

// The default patch sizes (Kaspar et al. 2015 use one size about this; the smaller one
// refines what the larger laid out).
constexpr int kLargePatch = 11, kSmallPatch = 7;
// The coarsest level keeps at least this many pixels on a side…
constexpr int kMinCoarsestSide = 16;
// …and, for a pattern that does not repeat, this fraction of the sample's side.
constexpr int kMaxReduction = 8;
// A feature at the coarsest level at most this fraction of the largest patch.
constexpr double kFeatureInPatch = 0.75;
constexpr int kMinLevels = 3, kMaxLevels = 8;
// Samples up to this shorter side may try one level fewer (their trials stay within what
// structure_distance measures unreduced).
constexpr int kMaxTrialSide = 512;

int odd_at_most(int v)
{
    return std::max(3, v % 2 ? v : v - 1);
}

} // namespace

std::vector<int> automatic_patch_sizes(int side)
{
    if (side >= 3 * kLargePatch)
        return { kLargePatch, kSmallPatch };
    const int large = odd_at_most(side / 3), small = odd_at_most(large * 2 / 3);
    return small < large ? std::vector<int> { large, small } : std::vector<int> { large };
}

int automatic_iterations(int level, int levels)
{
    return level == levels - 1 || level >= 2 ? 8 : level == 0 ? 1 : 3;
}

int automatic_levels(int side, const FeatureScale& scale, int largest_patch, std::string& reason)
{
    const bool repeats = scale.periodic();
    const int least = std::max(kMinCoarsestSide, repeats ? 0 : side / kMaxReduction);
    int most = 1; // the deepest level whose sample keeps `least` pixels on a side
    while (most < kMaxLevels && (side >> most) >= least)
        ++most;
    const double shrink = scale.size / (kFeatureInPatch * largest_patch);
    const int for_feature = 1 + int(std::ceil(std::log2(std::max(shrink, 1.0))));
    const int levels = repeats ? most : std::clamp(for_feature, std::min(kMinLevels, most), most);
    const int coarsest = side >> (levels - 1);
    const double feature = scale.size / double(1 << (levels - 1));
    reason = std::to_string(levels) + " levels, "
        + (repeats ? std::string("a repeating pattern: as deep as leaves the coarsest ")
                   : std::string("the coarsest with features of ")
                    + std::to_string(int(std::lround(feature))) + " px and ")
        + std::to_string(coarsest) + " px of the sample's side";
    return levels;
}

int alternative_levels(int side, const FeatureScale& scale, int levels)
{
    if (scale.periodic() || side > kMaxTrialSide)
        return 0;
    if (levels > kMinLevels)
        return levels - 1;
    const int least = std::max(kMinCoarsestSide, side / kMaxReduction);
    return levels == kMinLevels && (side >> levels) >= least ? levels + 1 : 0;
}

} // namespace texsyn::detail
