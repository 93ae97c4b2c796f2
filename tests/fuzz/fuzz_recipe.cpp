// SPDX-License-Identifier: Apache-2.0
// Recipes: JSON text (first byte even) or REST arguments on top of a default recipe (odd),
// then the recipe's own validation, as the format plugin does inside stock OIIO tools.
#include "fuzz_target.h"

#include <stdexcept>

#include <texsyn/recipe.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size == 0)
        return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    texsyn::Recipe recipe;
    std::string error;
    const bool parsed = data[0] % 2 == 0
        ? texsyn::parse_recipe(text, "/nonexistent", recipe, error)
        : texsyn::apply_recipe_arguments(text, "/nonexistent", recipe, error);
    if (!parsed)
        texsyn::fuzz::expect_one_line(error, "recipe");
    else if (!recipe.validate(error))
        texsyn::fuzz::expect_one_line(error, "recipe validation");
    else {
        std::string json;
        if (!texsyn::recipe_to_json(recipe, "/nonexistent", json, error))
            texsyn::fuzz::expect_one_line(error, "recipe_to_json");
    }
    return 0;
}
