// SPDX-License-Identifier: Apache-2.0
// Recipe JSON and REST arguments: one setter per key serves both.
#include <texsyn/recipe.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <type_traits>

#include <OpenImageIO/strutil.h>
#include <nlohmann/json.hpp>

#include <texsyn/stats.h>

#include "recipe_pvt.h"

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

// The recipe's own keys, those of no method.
constexpr const char* recipe_keys
    = "texsyn_recipe, sample, method, seed, iscolorspace, tocolorspace, colorconfig, subbands";

// The type of the method option called `key`: `method`'s if it has one (iterations is a
// list for choosy, an integer for pyramid), else the first method's that has it; or null.
const OptionType* option_type(const std::string& key, const std::string& method)
{
    const OptionType* type = nullptr;
    for (bool own : { true, false })
        detail::for_each_recipe_method([&](const char* name, auto member) {
            if (auto* field = detail::table_of(member).find(key);
                field && !type && (!own || method == name))
                type = &field->type;
        });
    return type;
}

// Sets a method option: for the recipe's method, and for every other method with an option
// of that name that takes the value (so that a later method=… keeps it).
bool set_option(Recipe& r, const std::string& key, const std::string& value, std::string& error)
{
    bool has = false, ok = false;
    std::string names;
    detail::visit_recipe_options(r, [&](auto& opt) {
        const auto& table = std::decay_t<decltype(opt)>::table();
        names = table.names();
        has = table.find(key) != nullptr;
        ok = has && table.set(opt, key, value, error);
    });
    if (has && !ok)
        return false;
    std::string owner;
    detail::for_each_recipe_method([&](const char* name, auto member) {
        const auto& table = detail::table_of(member);
        if (r.method == name || !table.find(key))
            return;
        std::string ignored; // a value that only the recipe's method takes stays its own
        if (has)
            table.set(r.*member, key, value, ignored);
        else if (owner.empty())
            owner = name;
    });
    if (has)
        return true;
    if (!owner.empty())
        error = "key '" + key + "' is an option of method " + owner
            + ", not of this recipe's method " + r.method + " (give method=" + owner + ")";
    else
        error = "unknown key '" + key + "' (known: " + recipe_keys + ", " + names + ")";
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
        bool known = false;
        detail::for_each_recipe_method([&](const char* name, auto) { known |= value == name; });
        if (!known) {
            error = "method=" + value + " is not one of " + detail::recipe_method_names();
            return false;
        }
        r.method = value;
        return true;
    }
    if (key == "seed") {
        int64_t v = 0;
        if (!parse_int_option(key, value, 0, 2147483647, v, error))
            return false;
        detail::for_each_recipe_method(
            [&](const char*, auto member) { (r.*member).seed = uint64_t(v); });
        return true;
    }
    if (key == "subbands")
        return parse_bool(key, value, r.subbands, error);
    return set_option(r, key, value, error);
}

// Sets the keys of one JSON object or one REST string: `method` first, wherever it stands,
// so that the options after it and before it are the same method's.
bool set_keys(Recipe& r, const std::vector<std::pair<std::string, std::string>>& pairs,
    const std::string& base_dir, std::string& error)
{
    for (bool method : { true, false })
        for (auto& [key, value] : pairs)
            if ((key == "method") == method && !set_key(r, key, value, base_dir, error))
                return false;
    return true;
}

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
// arrays of numbers for sizes ([w, h] as "WxH") and lists ([9, 7] as "9,7").
bool json_text(const std::string& key, const nlohmann::json& v, const std::string& method,
    std::string& out, std::string& error)
{
    static const char* const string_keys[]
        = { "sample", "method", "iscolorspace", "tocolorspace", "colorconfig" };
    const bool is_string_key
        = std::find(std::begin(string_keys), std::end(string_keys), key) != std::end(string_keys);
    const OptionType* type = option_type(key, method);
    const bool is_list = type && (*type == OptionType::Integers || *type == OptionType::Numbers);
    const bool fractional = type && (*type == OptionType::Real || *type == OptionType::Numbers);
    const bool takes_number = !is_string_key && !(type && *type == OptionType::Size)
        && !(type && *type == OptionType::Choice);
    if (v.is_string()) {
        out = v.get<std::string>();
        return true;
    }
    if (v.is_boolean() && key == "subbands") {
        out = v.get<bool>() ? "1" : "0";
        return true;
    }
    if (takes_number && number_text(v, fractional, out))
        return true;
    if (v.is_array() && !v.empty() && (is_list || (type && *type == OptionType::Size))) {
        out.clear();
        bool numbers = true;
        for (const nlohmann::json& item : v) {
            std::string text;
            numbers = numbers && number_text(item, fractional, text);
            out += (out.empty() ? "" : is_list ? "," : "x") + text;
        }
        if (numbers)
            return true;
    }
    const char* expected = is_string_key ? "a string"
        : key == "subbands"              ? "a boolean, an integer or a string"
        : !type                          ? "an integer or a string"
        : *type == OptionType::Size      ? "a string \"WxH\" or [width, height]"
        : *type == OptionType::Choice    ? "a string"
        : is_list                        ? "a number, a string \"a,b,c\" or an array of numbers"
        : fractional                     ? "a number or a string"
                                         : "an integer or a string";
    error = key + ": expected " + expected + ", not " + v.dump();
    return false;
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

std::string detail::recipe_method_names()
{
    std::string names;
    detail::for_each_recipe_method(
        [&](const char* name, auto) { names += (names.empty() ? "" : "|") + std::string(name); });
    return names;
}

bool Recipe::validate(std::string& error) const
{
    bool ok = true;
    if (!detail::visit_recipe_options(*this, [&](const auto& opt) { ok = opt.validate(error); })) {
        error = "method=" + method + " is not one of " + detail::recipe_method_names();
        return false;
    }
    if (!ok || method == "pyramid")
        return ok;
    if (subbands) {
        error = "subbands=1 : method " + method + " has no subbands (only method pyramid does)";
        return false;
    }
    if (is_analysis_filename(sample)) {
        error = "sample=" + sample
            + " : an analysis file (.tsa) is for method pyramid only; method " + method
            + " needs a sample image";
        return false;
    }
    return true;
}

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
    const auto method = j.find("method"); // checked by set_keys
    const std::string method_name
        = method != j.end() && method->is_string() ? method->get<std::string>() : r.method;
    std::vector<std::pair<std::string, std::string>> pairs;
    for (auto& [key, value] : j.items()) {
        pairs.emplace_back(key, "");
        if (!json_text(key, value, method_name, pairs.back().second, error))
            return false;
    }
    if (!set_keys(r, pairs, base_dir, error))
        return false;
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
    std::vector<std::pair<std::string, std::string>> pairs;
    for (const std::string& piece : OIIO::Strutil::splits(arguments, "&")) {
        size_t eq = piece.find('=');
        if (eq == std::string::npos || eq == 0) {
            error = "malformed argument '" + piece + "' (expected name=value)";
            return false;
        }
        const std::string key = piece.substr(0, eq);
        for (auto& seen : pairs)
            if (seen.first == key) {
                error = key + " is given twice";
                return false;
            }
        pairs.emplace_back(key, percent_decode(piece.substr(eq + 1)));
    }
    Recipe r = recipe;
    if (!set_keys(r, pairs, base_dir, error))
        return false;
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
    if (!r.validate(error)) {
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
    detail::visit_recipe_options(recipe, [&](const auto& opt) {
        j["seed"] = int64_t(opt.seed);
        std::vector<std::pair<std::string, std::string>> pairs;
        std::string ignored;
        split_option_string(std::decay_t<decltype(opt)>::table().format(opt), pairs, ignored);
        for (auto& [key, value] : pairs) {
            const bool integer
                = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
            if (integer)
                j[key] = std::stoll(value);
            else
                j[key] = value;
        }
    });
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
