// SPDX-License-Identifier: Apache-2.0
// Recipe JSON and REST arguments: one setter per key serves both.
#include <texsyn/recipe.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <OpenImageIO/strutil.h>
#include <nlohmann/json.hpp>

namespace texsyn {

namespace {

namespace fs = std::filesystem;

std::string resolve_path(const std::string& path, const std::string& base_dir)
{
    if (path.empty() || base_dir.empty() || fs::path(path).is_absolute())
        return path;
    return (fs::path(base_dir) / path).lexically_normal().string();
}

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
    error = key + "=" + value + " is not a boolean (use true, false, 1 or 0)";
    return false;
}

// Sets one key from its text form. `base_dir` resolves relative paths.
bool set_key(Recipe& r, const std::string& key, const std::string& value,
    const std::string& base_dir, std::string& error)
{
    if (key == "texsyn_recipe") {
        int64_t v = 0;
        if (!parse_int_option(key, value, 1, 1000000, v, error))
            return false;
        if (v > recipe_version) {
            error = "texsyn_recipe=" + value + " is newer than this texsyn reads (version "
                + std::to_string(recipe_version) + ")";
            return false;
        }
        return true;
    }
    if (key == "sample") {
        r.sample = resolve_path(value, base_dir);
        return true;
    }
    if (key == "colorconfig") {
        r.colorconfig = resolve_path(value, base_dir);
        return true;
    }
    if (key == "iscolorspace" || key == "tocolorspace") {
        (key == "iscolorspace" ? r.iscolorspace : r.tocolorspace) = value;
        return true;
    }
    if (key == "method") {
        if (value != "pyramid") {
            error = "method=" + value + " is not one of pyramid";
            return false;
        }
        r.method = value;
        return true;
    }
    if (key == "seed") {
        int64_t v = 0;
        if (!parse_int_option(key, value, 0, 2147483647, v, error))
            return false;
        r.pyramid.seed = uint64_t(v);
        return true;
    }
    if (key == "subbands")
        return parse_bool(key, value, r.subbands, error);
    std::string option_error;
    if (PyramidOptions::table().set(r.pyramid, key, value, option_error))
        return true;
    error = option_error.rfind("unknown option", 0) == 0 ? "unknown key '" + key
            + "' (known: texsyn_recipe, sample, method, seed, iscolorspace, tocolorspace, "
              "colorconfig, subbands, "
            + PyramidOptions::table().names() + ")"
                                                         : option_error;
    return false;
}

// A JSON value in the text form set_key takes: strings as they are, integers in decimal,
// booleans as 1/0, [w, h] as "WxH".
bool json_text(
    const std::string& key, const nlohmann::json& v, std::string& out, std::string& error)
{
    static const char* const string_keys[]
        = { "sample", "method", "iscolorspace", "tocolorspace", "colorconfig" };
    const bool is_string_key
        = std::find(std::begin(string_keys), std::end(string_keys), key) != std::end(string_keys);
    if (is_string_key && !v.is_string()) {
        error = key + ": expected a string, not " + v.dump();
        return false;
    }
    if (v.is_boolean() && key != "subbands") {
        error = key + ": expected a number or a string, not " + v.dump();
        return false;
    }
    if (v.is_string())
        out = v.get<std::string>();
    else if (v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(INT64_MAX))
        out = std::to_string(v.get<uint64_t>());
    else if (v.is_number_integer())
        out = std::to_string(v.get<int64_t>());
    else if (v.is_boolean())
        out = v.get<bool>() ? "1" : "0";
    else if (v.is_array() && v.size() == 2 && v[0].is_number_integer() && v[1].is_number_integer())
        out = std::to_string(v[0].get<int64_t>()) + "x" + std::to_string(v[1].get<int64_t>());
    else {
        error = key + ": expected a string, an integer, a boolean or [width, height], not "
            + v.dump();
        return false;
    }
    return true;
}

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

} // namespace

bool parse_recipe(
    const std::string& text, const std::string& base_dir, Recipe& recipe, std::string& error)
{
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        error = "malformed JSON (" + what.substr(what.find(' ') + 1) + ")";
        return false;
    }
    if (!j.is_object()) {
        error = "a recipe is a JSON object ({ \"sample\": ..., ... })";
        return false;
    }
    Recipe r;
    for (auto& [key, value] : j.items()) {
        std::string v;
        if (!json_text(key, value, v, error) || !set_key(r, key, v, base_dir, error))
            return false;
    }
    if (r.sample.empty()) {
        error = "the recipe names no sample (\"sample\": \"file.png\")";
        return false;
    }
    recipe = std::move(r);
    return true;
}

bool apply_recipe_arguments(
    const std::string& arguments, const std::string& base_dir, Recipe& recipe, std::string& error)
{
    Recipe r = recipe;
    std::vector<std::string> seen;
    for (const std::string& piece : OIIO::Strutil::splits(arguments, "&")) {
        size_t eq = piece.find('=');
        if (eq == std::string::npos || eq == 0) {
            error = "malformed argument '" + piece + "' (expected name=value)";
            return false;
        }
        const std::string key = piece.substr(0, eq);
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
            error = key + " is given twice";
            return false;
        }
        seen.push_back(key);
        if (!set_key(r, key, percent_decode(piece.substr(eq + 1)), base_dir, error))
            return false;
    }
    recipe = std::move(r);
    return true;
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
    if (fs::is_directory(base, ec)) {
        error = base + ": is a directory, not a recipe";
        return false;
    }
    if (fs::is_regular_file(base, ec)) {
        base_dir = fs::path(base).parent_path().string();
        std::ifstream in(base, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        if (!in || !parse_recipe(text.str(), base_dir, r, error)) {
            error = base + ": " + (error.empty() ? "cannot read" : error);
            return false;
        }
    } else {
        r.sample = base.substr(0, base.size() - 7); // "rust.png.texsyn" -> "rust.png"
    }
    if (q != std::string::npos && !apply_recipe_arguments(name.substr(q + 1), base_dir, r, error)) {
        error = base + ": " + error;
        return false;
    }
    if (!r.pyramid.validate(error)) {
        error = base + ": " + error;
        return false;
    }
    if (fs::equivalent(r.sample, base, ec)) {
        error = base + ": the recipe uses itself as its sample";
        return false;
    }
    recipe = std::move(r);
    return true;
}

std::string recipe_to_json(const Recipe& recipe, const std::string& base_dir)
{
    auto relative = [&](const std::string& path) {
        if (path.empty() || base_dir.empty())
            return path;
        // Relative even across "..", so that a project folder can move as a whole.
        std::error_code ec;
        const fs::path abs = fs::absolute(path, ec).lexically_normal();
        const fs::path rel = abs.lexically_relative(fs::absolute(base_dir, ec).lexically_normal());
        return ec || rel.empty() ? abs.string() : rel.string();
    };
    nlohmann::ordered_json j;
    j["texsyn_recipe"] = recipe_version;
    j["sample"] = relative(recipe.sample);
    j["method"] = recipe.method;
    j["seed"] = int64_t(recipe.pyramid.seed);
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string ignored;
    split_option_string(PyramidOptions::table().format(recipe.pyramid), pairs, ignored);
    for (auto& [key, value] : pairs) {
        const bool integer
            = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
        if (integer)
            j[key] = std::stoll(value);
        else
            j[key] = value;
    }
    if (!recipe.iscolorspace.empty())
        j["iscolorspace"] = recipe.iscolorspace;
    if (!recipe.tocolorspace.empty())
        j["tocolorspace"] = recipe.tocolorspace;
    if (!recipe.colorconfig.empty())
        j["colorconfig"] = relative(recipe.colorconfig);
    if (recipe.subbands)
        j["subbands"] = true;
    return j.dump(2) + "\n";
}

} // namespace texsyn
