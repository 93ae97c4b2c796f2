// SPDX-License-Identifier: Apache-2.0
// The limits on nested recipes (recipe.h: kDefaultMaxRecipeDepth, ...), shared by the
// runner and the cache key, which walk the same nesting.
#pragma once

#include <string>

namespace texsyn::detail {

/// $TEXSYN_MAX_RECIPE_DEPTH, else kDefaultMaxRecipeDepth; false with a one-line error if
/// the variable is set to anything but a whole number from 1 to 64.
bool max_recipe_depth(int& depth, std::string& error);

/// Whether `path` (without its "?arguments") names a recipe: it ends in .texsyn.
bool is_recipe_name(const std::string& path);

} // namespace texsyn::detail
