// SPDX-License-Identifier: Apache-2.0
// Self-tuning: the EM schedule of the copying methods (patch, fill, tileable, material
// sets) chosen from the sample's feature scale and size when the options leave it
// automatic (levels=0, patch=auto, iterations=auto).
#pragma once

#include <string>
#include <vector>

#include <texsyn/feature_scale.h>

namespace texsyn::detail {

/// The patch sizes, largest first, for a sample whose shorter side is `side` when none are
/// given: 11 and 7; under 33 pixels, the largest at most a third of the side and the
/// smaller about two thirds of it (odd, at least 3; one size if they meet).
std::vector<int> automatic_patch_sizes(int side);

/// The EM iterations at `level` (0 finest) of `levels` when none are given: 1 at the
/// finest, which starts from its coarser level's matches voted with its own pixels and
/// only sharpens them; 3 at the next; 8 at the coarser ones, where the layout forms.
int automatic_iterations(int level, int levels);

/// The pyramid levels a patch synthesis of a sample of `side` pixels (its shorter side)
/// wants when levels=0, and in `reason` why, for -v. The coarsest level must see a feature
/// whole (at most three quarters of the `largest_patch`) and still hold enough of the
/// sample to copy from: at least 16 pixels on a side, and, unless the pattern repeats (a
/// repeating pattern is copied whole anyway), at least an eighth of the sample's side, so
/// that patches have somewhere else to come from than the same few places. At least 3
/// levels (where they fit): with fewer, the layout of even a fine texture forms from
/// 11-pixel patches of full-resolution noise.
int automatic_levels(int side, const FeatureScale& scale, int largest_patch, std::string& reason);

/// The other level count worth trying when the automatic one is `levels` (0 if none), for
/// a sample that does not repeat and whose shorter side is at most 512 pixels: one fewer
/// where `levels` is more than the least (3); one more where it is the least and the
/// coarsest level would still keep what automatic_levels asks of it. Such a sample holds
/// few of its features, and one level more or fewer decides whether they are laid out as
/// the sample lays them, merged into streaks, or copied in blocks that repeat; which, the
/// sample alone does not say (patch_synthesize tries both).
int alternative_levels(int side, const FeatureScale& scale, int levels);

} // namespace texsyn::detail
