// SPDX-License-Identifier: Apache-2.0
// The recipe methods, listed once: parsing, writing, validating and running a recipe
// visit them through these helpers instead of naming each method.
#pragma once

#include <texsyn/recipe.h>

namespace texsyn::detail {

/// Calls f(name, member) for every recipe method: its name and the Recipe member holding
/// its options. A new recipe method is one more line here (and its run in run_recipe.cpp).
template <class F>
void for_each_recipe_method(F&& f)
{
    f("pyramid", &Recipe::pyramid);
    f("neighborhood", &Recipe::neighborhood);
    f("choosy", &Recipe::choosy);
}

/// The option table of the options at `member`.
template <class T>
const OptionTable<T>& table_of(T Recipe::*)
{
    return T::table();
}

/// Calls f(options) with the options of `recipe`'s method; false if the method is unknown.
template <class R, class F>
bool visit_recipe_options(R& recipe, F&& f)
{
    bool found = false;
    for_each_recipe_method([&](const char* name, auto member) {
        if (!found && recipe.method == name) {
            found = true;
            f(recipe.*member);
        }
    });
    return found;
}

/// "pyramid|neighborhood|choosy".
std::string recipe_method_names();

} // namespace texsyn::detail
