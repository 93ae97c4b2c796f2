// SPDX-License-Identifier: Apache-2.0
// Setting a recipe's keys from text: what a JSON recipe and REST arguments both become.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <texsyn/recipe.h>

namespace texsyn::detail {

/// Keys with their values as text: one each, or several for the list keys (sample,
/// iscolorspace).
using KeyValues = std::vector<std::pair<std::string, std::vector<std::string>>>;

/// Whether `key` is one of the recipe's own keys (texsyn_recipe, sample, method, …), which
/// belong to no method.
bool is_recipe_key(const std::string& key);

/// Makes `name` the recipe's method, with its default options (kept if it already is).
/// False with "method: NAME not one of …" for a name no recipe can have.
bool set_method(Recipe& r, const std::string& name, std::string& error);

/// Sets the keys of one JSON object or one REST string: `method` first, wherever it stands,
/// so that the options after it and before it are the same method's; then a preset (a
/// named set of other options), so that the options given override it; then the rest.
/// Paths are resolved against `base_dir`. False with a one-line message for an unknown
/// key (naming the method that has it, if one does), a bad value or a control character.
bool set_keys(Recipe& r, const KeyValues& pairs, const std::string& base_dir, std::string& error);

} // namespace texsyn::detail
