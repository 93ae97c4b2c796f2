// SPDX-License-Identifier: Apache-2.0
// One setter per key serves JSON recipes and REST arguments alike; the method's option table
// (methods.h) says what each option key takes.
#include "recipe_keys_pvt.h"

#include <algorithm>
#include <filesystem>

#include <texsyn/color.h>
#include <texsyn/error_text.h>
#include <texsyn/methods.h>

namespace texsyn::detail {

namespace {

namespace fs = std::filesystem;

std::string resolve_path(const std::string& path, const std::string& base_dir)
{
    if (path.empty() || base_dir.empty() || fs::path(path).is_absolute())
        return path;
    return (fs::path(base_dir) / path).lexically_normal().string();
}

// The recipe's own keys, those of no method.
constexpr const char* recipe_keys
    = "texsyn_recipe, sample, method, seed, iscolorspace, tocolorspace, colorconfig, subbands";

bool parse_bool(const std::string& key, const std::string& value, bool& out, std::string& error)
{
    if (value == "1" || value == "true") {
        out = true;
        return true;
    }
    if (value == "0" || value == "false") {
        out = false;
        return true;
    }
    error = option_error(key, value, "not a boolean (use true, false, 1 or 0)");
    return false;
}

// The first method but the recipe's whose options include `key`, or "".
std::string owner_of(const std::string& key, const std::string& method)
{
    for (const Method* m : methods())
        if (m->makes_recipes() && m->name != method && m->defaults().table().find(key))
            return m->name;
    return "";
}

// Sets option `key` of the recipe's method from its text (an input file's path resolved
// against `base_dir`) and records it as given.
bool set_option(Recipe& r, const std::string& key, std::string value, const std::string& base_dir,
    std::string& error)
{
    const OptionField* field = r.options.table().find(key);
    if (!field) {
        const std::string owner = owner_of(key, r.method);
        if (!owner.empty())
            error = "key '" + key + "' is an option of method " + owner
                + ", not of this recipe's method " + r.method + " (give method=" + owner + ")";
        else
            error = "unknown key '" + key + "' (known: " + recipe_keys + ", "
                + r.options.table().names() + ")";
        return false;
    }
    if (field->type == OptionType::OutputFile) {
        error = "key '" + key
            + "' names a file the tool writes beside its output; a recipe "
              "makes one image (give it to the texsyn tool)";
        return false;
    }
    if (field->type == OptionType::InputFile)
        value = resolve_path(value, base_dir);
    if (!r.options.set(key, value, error))
        return false;
    r.given.erase(std::remove_if(r.given.begin(), r.given.end(),
                      [&](const auto& g) { return g.first == key; }),
        r.given.end());
    r.given.emplace_back(key, value);
    return true;
}

// Sets one key: the recipe's own, or an option. `values` holds one text, or several for
// the list keys (sample, iscolorspace).
bool set_key(Recipe& r, const std::string& key, const std::vector<std::string>& values,
    const std::string& base_dir, std::string& error)
{
    const std::string& value = values.front();
    if (values.size() > 1 && key != "sample" && key != "iscolorspace") {
        error = key + ": takes one value, not a list";
        return false;
    }
    if (key == "texsyn_recipe") {
        int64_t v = 0;
        if (!parse_int_option(key, value, 1, 1000000, v, error))
            return false;
        if (v > recipe_version) {
            error = option_error(key, value,
                "newer than this texsyn reads (version " + std::to_string(recipe_version) + ")");
            return false;
        }
        return true;
    }
    if (key == "sample") {
        r.samples.clear();
        for (const std::string& v : values)
            r.samples.push_back(resolve_path(v, base_dir));
        return true;
    }
    if (key == "iscolorspace") {
        r.iscolorspace = values;
        return true;
    }
    if (key == "colorconfig") {
        r.colorconfig = value == ColorConfig::bundled_name ? value : resolve_path(value, base_dir);
        return true;
    }
    if (key == "tocolorspace") {
        r.tocolorspace = value;
        return true;
    }
    if (key == "method")
        return set_method(r, value, error);
    if (key == "seed") {
        int64_t v = 0;
        if (!parse_int_option(key, value, 0, max_seed, v, error))
            return false;
        r.seed = uint64_t(v);
        return true;
    }
    if (key == "subbands")
        return parse_bool(key, value, r.subbands, error);
    return set_option(r, key, value, base_dir, error);
}

// False (with "KEY: contains a control character (…)") if a key or value holds one: a NUL
// would cut a file name where the C library reads it, so another file would be read.
bool free_of_control_characters(const KeyValues& pairs, std::string& error)
{
    auto control = [](const std::string& t) {
        return std::any_of(t.begin(), t.end(),
            [](char c) { return (static_cast<unsigned char>(c) < 0x20) || c == 0x7f; });
    };
    for (const auto& [key, values] : pairs)
        for (const std::string& text : values)
            if (control(key) || control(text)) {
                error = key + ": contains a control character (\"" + text
                    + "\"); a recipe's names and values cannot";
                return false;
            }
    return true;
}

} // namespace

bool is_recipe_key(const std::string& key)
{
    for (const char* k : { "texsyn_recipe", "sample", "method", "seed", "iscolorspace",
             "tocolorspace", "colorconfig", "subbands" })
        if (key == k)
            return true;
    return false;
}

// Makes `name` the recipe's method, with its default options.
bool set_method(Recipe& r, const std::string& name, std::string& error)
{
    const Method* m = find_method(name);
    if (!m || !m->makes_recipes()) {
        error = option_error("method", name, "not one of " + method_names());
        return false;
    }
    if (r.method != name || !r.options) {
        r.method = name;
        r.options = m->defaults();
    }
    return true;
}

bool set_keys(Recipe& r, const KeyValues& pairs, const std::string& base_dir, std::string& error)
{
    if (!free_of_control_characters(pairs, error))
        return false;
    auto rank = [&r](const std::string& key) {
        if (key == "method")
            return 0;
        const OptionField* f = r.options.table().find(key);
        return f && f->preset ? 1 : 2;
    };
    for (int pass = 0; pass < 3; ++pass)
        for (const auto& [key, values] : pairs)
            if (rank(key) == pass && !set_key(r, key, values, base_dir, error))
                return false;
    return true;
}

} // namespace texsyn::detail
