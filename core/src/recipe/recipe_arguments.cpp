// SPDX-License-Identifier: Apache-2.0
// Recipes in file names: "rust.png.texsyn?method=patch&size=512x512" (REST arguments after
// the '?', applied over the recipe file's keys or a sample named by the file name).
#include <texsyn/recipe.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <OpenImageIO/strutil.h>

#include <texsyn/error_text.h>
#include <texsyn/io.h>

#include "recipe_keys_pvt.h"

namespace texsyn {

namespace {

namespace fs = std::filesystem;
using detail::KeyValues;

// "%20" -> " ": REST values as URLs write them (a malformed escape is kept as it is).
std::string percent_decode(const std::string& text)
{
    std::string out;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '%' && i + 2 < text.size() && std::isxdigit((unsigned char)text[i + 1])
            && std::isxdigit((unsigned char)text[i + 2])) {
            out += char(std::stoi(text.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            out += text[i];
        }
    }
    return out;
}

bool apply_arguments(
    const std::string& arguments, const std::string& base_dir, Recipe& recipe, std::string& error)
{
    KeyValues pairs;
    std::set<std::string> seen; // a name may hold a million keys: no linear search
    for (const std::string& piece : OIIO::Strutil::splits(arguments, "&")) {
        size_t eq = piece.find('=');
        if (eq == std::string::npos || eq == 0) {
            error = "malformed argument '" + piece + "' (expected name=value)";
            return false;
        }
        const std::string key = piece.substr(0, eq);
        if (!seen.insert(key).second) {
            error = option_error(key, piece.substr(eq + 1), "given twice");
            return false;
        }
        std::vector<std::string> values;
        for (const std::string& v : (key == "sample" || key == "iscolorspace")
                ? OIIO::Strutil::splits(piece.substr(eq + 1), ",")
                : std::vector<std::string> { piece.substr(eq + 1) })
            values.push_back(percent_decode(v));
        if (values.empty())
            values.emplace_back();
        pairs.emplace_back(key, std::move(values));
    }
    Recipe r = recipe;
    if (!r.options && !detail::set_method(r, r.method, error))
        return false;
    for (const auto& [key, values] : pairs) {
        if (key != "method" || values.front() == r.method)
            continue;
        // Another method: its defaults, and the options given so far that are the same
        // option in both (shared: size, levels, …), not those that only share a name
        // (a choosy recipe's iterations are not the pyramid's).
        const OptionList& before = r.options.table(); // a static table: it outlives r.options
        if (!detail::set_method(r, values.front(), error))
            return false;
        std::vector<std::pair<std::string, std::string>> given;
        given.swap(r.given);
        for (const auto& [k, v] : given) {
            const OptionField *from = before.find(k), *to = r.options.table().find(k);
            std::string ignored;
            if (from && to && from->shared && to->shared && r.options.set(k, v, ignored))
                r.given.emplace_back(k, v);
        }
    }
    if (!detail::set_keys(r, pairs, base_dir, error))
        return false;
    recipe = std::move(r);
    return true;
}

} // namespace

bool apply_recipe_arguments(
    const std::string& arguments, const std::string& base_dir, Recipe& recipe, std::string& error)
{
    if (apply_arguments(arguments, base_dir, recipe, error))
        return true;
    error = printable_text(error);
    return false;
}

bool recipe_from_filename(const std::string& name, Recipe& recipe, std::string& error)
{
    const size_t q = name.find('?');
    const std::string base = name.substr(0, q);
    if (!OIIO::Strutil::iends_with(base, ".texsyn")) {
        error = base + ": a recipe's name ends in .texsyn";
        return false;
    }
    Recipe r;
    std::error_code ec;
    std::string base_dir;
    if (fs::exists(base, ec) && !check_regular_file(base, "a recipe", error))
        return false;
    // "rust.png.texsyn": the sample is "rust.png" unless the method takes none.
    const bool named_sample = !fs::is_regular_file(base, ec);
    const std::string sample = base.substr(0, base.size() - 7);
    if (!named_sample) {
        base_dir = fs::path(base).parent_path().string();
        if (!check_recipe_file_size(base, error))
            return false;
        std::ifstream in(base, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        if (!in || !parse_recipe(text.str(), base_dir, r, error)) {
            error = base + ": " + (error.empty() ? "cannot read" : error);
            return false;
        }
    } else {
        r.samples = { sample };
    }
    if (q != std::string::npos && !apply_recipe_arguments(name.substr(q + 1), base_dir, r, error)) {
        error = base + ": " + error;
        return false;
    }
    if (const Method* m = r.row(); named_sample && m && r.samples == std::vector { sample }
        && (m->inputs == MethodInputs::None
            || (m->inputs == MethodInputs::OptionalImage && !fs::exists(sample, ec))))
        r.samples.clear();
    if (!r.validate(error)) {
        error = base + ": " + error;
        return false;
    }
    for (const std::string& s : r.samples)
        if (fs::equivalent(s, base, ec)) {
            error = base + ": the recipe uses itself as its sample";
            return false;
        }
    recipe = std::move(r);
    return true;
}

} // namespace texsyn
