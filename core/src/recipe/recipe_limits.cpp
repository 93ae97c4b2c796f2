// SPDX-License-Identifier: Apache-2.0
// Bounded work for recipes that nest recipes (issue #34): five files of 1.6 kB, each a
// mix of 16 recipes, asked for a million syntheses. The nesting is walked and counted
// before anything runs.
#include <texsyn/recipe.h>

#include <charconv>
#include <cstdlib>

#include <OpenImageIO/strutil.h>

#include "recipe_limits_pvt.h"

namespace texsyn {

namespace detail {

namespace {

// The whole number in environment variable `name` (low..high), `fallback` if unset.
bool limit_from_environment(
    const char* name, int fallback, int low, int high, int& value, std::string& error)
{
    value = fallback;
    const char* env = std::getenv(name);
    if (!env)
        return true;
    const std::string_view text(env);
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || value < low
        || value > high) {
        error = std::string(name) + "=" + std::string(text.substr(0, 40))
            + ": expected a whole number from " + std::to_string(low) + " to "
            + std::to_string(high);
        return false;
    }
    return true;
}

struct WorkWalk {
    int max_depth = 0, max_syntheses = 0;
    int syntheses = 0;
};

// Every input file of `recipe`: its samples, then its options' input files.
std::vector<std::string> input_files(const Recipe& recipe)
{
    std::vector<std::string> files = recipe.samples;
    if (recipe.options)
        for (const OptionField& f : recipe.options.table().fields())
            if (const std::string file = recipe.options.value(f.name);
                f.type == OptionType::InputFile && !file.empty())
                files.push_back(file);
    return files;
}

// Counts `recipe` (read from `name`, at nesting `depth`) and the recipes it nests.
bool walk(const Recipe& recipe, const std::string& name, int depth, WorkWalk& w, std::string& error)
{
    if (depth > w.max_depth) {
        error = name + ": recipes nest more than " + std::to_string(w.max_depth)
            + " deep (does a recipe use itself as its sample? $TEXSYN_MAX_RECIPE_DEPTH raises "
              "the limit)";
        return false;
    }
    if (++w.syntheses > w.max_syntheses) {
        error = name + ": would be synthesis " + std::to_string(w.syntheses)
            + " of one recipe, which may run at most " + std::to_string(w.max_syntheses)
            + " with the recipes it nests ($TEXSYN_MAX_RECIPE_SYNTHESES raises the limit)";
        return false;
    }
    for (const std::string& file : input_files(recipe)) {
        if (!is_recipe_name(file))
            continue;
        Recipe inner;
        if (!recipe_from_filename(file, inner, error) || !walk(inner, file, depth + 1, w, error))
            return false;
    }
    return true;
}

} // namespace

bool max_recipe_depth(int& depth, std::string& error)
{
    return limit_from_environment(
        "TEXSYN_MAX_RECIPE_DEPTH", kDefaultMaxRecipeDepth, 1, 64, depth, error);
}

bool is_recipe_name(const std::string& path)
{
    return OIIO::Strutil::iends_with(path.substr(0, path.find('?')), ".texsyn");
}

} // namespace detail

bool check_recipe_work(const Recipe& recipe, std::string& error)
{
    detail::WorkWalk w;
    if (!detail::max_recipe_depth(w.max_depth, error)
        || !detail::limit_from_environment("TEXSYN_MAX_RECIPE_SYNTHESES",
            kDefaultMaxRecipeSyntheses, 1, 1000000, w.max_syntheses, error))
        return false;
    return detail::walk(recipe, "recipe", 0, w, error);
}

} // namespace texsyn
