// SPDX-License-Identifier: Apache-2.0
// Recipes as JSON: read (strictly, within a size) and written.
#include <texsyn/recipe.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>

#include <nlohmann/json.hpp>

#include <texsyn/color.h>
#include <texsyn/error_text.h>
#include <texsyn/memory.h>

#include "json_strict_pvt.h"
#include "recipe_keys_pvt.h"

namespace texsyn {

namespace {

namespace fs = std::filesystem;
using detail::KeyValues;

// A JSON number as text, if it is an integer or (with `fractional`) any number.
bool number_text(const nlohmann::json& v, bool fractional, std::string& out)
{
    if (v.is_number_unsigned() && v.get<uint64_t>() > uint64_t(INT64_MAX))
        out = std::to_string(v.get<uint64_t>());
    else if (v.is_number_integer())
        out = std::to_string(v.get<int64_t>());
    else if (v.is_number_float() && fractional)
        out = v.dump(); // the shortest text that reads back as the same double
    else
        return false;
    return true;
}

// A JSON value in the text form set_key takes: strings as they are; integers in decimal;
// booleans (subbands only) as 1/0; fractional numbers for real and number-list options;
// arrays of numbers for sizes ([w, h] as "WxH") and lists ([9, 7] as "9,7"); arrays of
// strings for sample and iscolorspace (one text each).
bool json_values(const std::string& key, const nlohmann::json& v, const OptionField* field,
    std::vector<std::string>& out, std::string& error)
{
    out.assign(1, "");
    const bool list_key = key == "sample" || key == "iscolorspace";
    const bool string_key
        = list_key || key == "method" || key == "tocolorspace" || key == "colorconfig";
    const OptionType type = field ? field->type : OptionType::Integer;
    const bool is_list = field && (type == OptionType::Integers || type == OptionType::Numbers);
    const bool fractional = field && (type == OptionType::Real || type == OptionType::Numbers);
    const bool takes_number = !string_key
        && !(field
            && (type == OptionType::Size || type == OptionType::Choice
                || type == OptionType::Choices || type == OptionType::InputFile
                || type == OptionType::OutputFile));
    if (v.is_string()) {
        out[0] = v.get<std::string>();
        return true;
    }
    if (v.is_boolean() && key == "subbands") {
        out[0] = v.get<bool>() ? "1" : "0";
        return true;
    }
    if (takes_number && number_text(v, fractional, out[0]))
        return true;
    if (v.is_array() && !v.empty() && list_key
        && std::all_of(v.begin(), v.end(), [](const nlohmann::json& s) { return s.is_string(); })) {
        out.clear();
        for (const nlohmann::json& s : v)
            out.push_back(s.get<std::string>());
        return true;
    }
    if (v.is_array() && !v.empty() && (is_list || type == OptionType::Size) && field) {
        bool numbers = true;
        for (const nlohmann::json& item : v) {
            std::string text;
            numbers = numbers && number_text(item, fractional, text);
            out[0] += (out[0].empty() ? "" : is_list ? "," : "x") + text;
        }
        if (numbers)
            return true;
    }
    const char* expected = list_key ? "a string or an array of strings"
        : string_key                ? "a string"
        : key == "subbands"         ? "a boolean, an integer or a string"
        : !field                    ? "an integer or a string"
        : type == OptionType::Size  ? "a string \"WxH\" or [width, height]"
        : type == OptionType::Choice || type == OptionType::Choices || type == OptionType::InputFile
            || type == OptionType::OutputFile
        ? "a string"
        : is_list    ? "a number, a string \"a,b,c\" or an array of numbers"
        : fractional ? "a number or a string"
                     : "an integer or a string";
    error = key + ": expected " + expected + ", not " + v.dump();
    return false;
}

// "is 10.0 GB, more than a recipe can be (1.0 MB)".
std::string too_large_for_a_recipe(uintmax_t bytes)
{
    return "is " + format_bytes(double(bytes)) + ", more than a recipe can be ("
        + format_bytes(double(kMaxRecipeBytes)) + ")";
}

bool parse_recipe_text(
    const std::string& text, const std::string& base_dir, Recipe& recipe, std::string& error)
{
    if (text.size() > kMaxRecipeBytes) {
        error = too_large_for_a_recipe(text.size());
        return false;
    }
    nlohmann::json j;
    try {
        j = detail::parse_json_strict(text, 64); // a recipe needs 2
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        error = "malformed JSON (" + what.substr(what.find(' ') + 1) + ")";
        return false;
    } catch (const std::exception& e) {
        error = "malformed JSON (" + std::string(e.what()) + ")";
        return false;
    }
    if (!j.is_object()) {
        error = "a recipe is a JSON object ({ \"sample\": ..., ... })";
        return false;
    }
    Recipe r;
    const auto method = j.find("method");
    if (!detail::set_method(r,
            method != j.end() && method->is_string() ? method->get<std::string>() : r.method,
            error))
        return false;
    KeyValues pairs;
    for (auto& [key, value] : j.items()) {
        pairs.emplace_back(key, std::vector<std::string>());
        const OptionField* field
            = detail::is_recipe_key(key) ? nullptr : r.options.table().find(key);
        if (!json_values(key, value, field, pairs.back().second, error))
            return false;
    }
    if (!detail::set_keys(r, pairs, base_dir, error))
        return false;
    recipe = std::move(r);
    return true;
}

} // namespace

bool parse_recipe(
    const std::string& text, const std::string& base_dir, Recipe& recipe, std::string& error)
{
    if (parse_recipe_text(text, base_dir, recipe, error))
        return true;
    error = printable_text(error);
    return false;
}

bool check_recipe_file_size(const std::string& filename, std::string& error)
{
    std::error_code ec;
    const uintmax_t bytes = fs::file_size(filename, ec);
    if (ec || bytes <= kMaxRecipeBytes)
        return true;
    error = filename + ": " + too_large_for_a_recipe(bytes);
    return false;
}

bool recipe_to_json(
    const Recipe& recipe, const std::string& base_dir, std::string& json, std::string& error)
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
    auto one_or_array = [](const std::vector<std::string>& v) {
        return v.size() == 1 ? nlohmann::ordered_json(v[0]) : nlohmann::ordered_json(v);
    };
    nlohmann::ordered_json j;
    j["texsyn_recipe"] = recipe_version;
    if (!recipe.samples.empty()) {
        std::vector<std::string> samples;
        for (const std::string& s : recipe.samples)
            samples.push_back(relative(s));
        j["sample"] = one_or_array(samples);
    }
    j["method"] = recipe.method;
    j["seed"] = int64_t(recipe.seed);
    const Method* m = recipe.row();
    const MethodOptions options = recipe.options || !m ? recipe.options : m->defaults();
    for (const OptionField& f : options.table().fields()) {
        const std::string value = options.value(f.name);
        if (f.type == OptionType::OutputFile || (f.type == OptionType::InputFile && value.empty()))
            continue;
        const bool integer
            = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
        if (f.type == OptionType::InputFile)
            j[f.name] = relative(value);
        else if (integer)
            j[f.name] = std::stoll(value);
        else
            j[f.name] = value;
    }
    if (!recipe.iscolorspace.empty())
        j["iscolorspace"] = one_or_array(recipe.iscolorspace);
    if (!recipe.tocolorspace.empty())
        j["tocolorspace"] = recipe.tocolorspace;
    if (!recipe.colorconfig.empty())
        j["colorconfig"] = recipe.colorconfig == ColorConfig::bundled_name
            ? recipe.colorconfig
            : relative(recipe.colorconfig);
    if (recipe.subbands)
        j["subbands"] = true;
    try {
        json = j.dump(2) + "\n";
        return true;
    } catch (const nlohmann::json::type_error&) { // JSON text is UTF-8
        error = "a file or colour-space name is not valid UTF-8, which a JSON recipe cannot hold";
        return false;
    }
}

} // namespace texsyn
