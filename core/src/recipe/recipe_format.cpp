// SPDX-License-Identifier: Apache-2.0
// Recipe JSON and REST arguments: one setter per key serves both, and the method's option
// table (methods.h) says what each option key takes.
#include <texsyn/recipe.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include <OpenImageIO/strutil.h>
#include <nlohmann/json.hpp>

#include <texsyn/color.h>
#include <texsyn/error_text.h>
#include <texsyn/io.h>
#include <texsyn/memory.h>
#include <texsyn/stats.h>

#include "json_strict_pvt.h"

namespace texsyn {

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

bool is_recipe_key(const std::string& key)
{
    for (const char* k : { "texsyn_recipe", "sample", "method", "seed", "iscolorspace",
             "tocolorspace", "colorconfig", "subbands" })
        if (key == k)
            return true;
    return false;
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
    error = option_error(key, value, "not a boolean (use true, false, 1 or 0)");
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

using KeyValues = std::vector<std::pair<std::string, std::vector<std::string>>>;

// Sets the keys of one JSON object or one REST string: `method` first, wherever it stands,
// so that the options after it and before it are the same method's; then a preset (a named
// set of other options), so that the options given override it; then the rest.
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

// How many samples the recipe's method takes, as text for messages ("1", "0 or 1", …).
std::string sample_count_text(const Method& m, const MethodOptions& options)
{
    if (m.inputs == MethodInputs::OptionalImage)
        return "0 or 1";
    return std::to_string(m.input_count(options, 0));
}

} // namespace

bool Recipe::validate(std::string& error) const
{
    const Method* m = row();
    if (!m || !m->makes_recipes()) {
        error = option_error("method", printable_text(method), "not one of " + method_names());
        return false;
    }
    const MethodOptions options = this->options ? this->options : m->defaults();
    if (!options.validate(error))
        return false;
    const int n = int(samples.size());
    const bool count_ok
        = m->inputs == MethodInputs::OptionalImage ? n <= 1 : n == m->input_count(options, n);
    if (!count_ok) {
        error = n == 0 ? "the recipe names no sample (\"sample\": \"file.png\"); method " + method
                + " takes " + sample_count_text(*m, options)
                       : "method " + method + " takes " + sample_count_text(*m, options) + " sample"
                + (m->input_count(options, n) == 1 ? "" : "s") + ", the recipe names "
                + std::to_string(n) + " (\"sample\": [\"a.png\", \"b.png\", ...])";
        return false;
    }
    for (int i = 0; i < n; ++i)
        if (is_analysis_filename(samples[size_t(i)]) && !m->accepts_analysis(i)) {
            error = option_error("sample", printable_text(samples[size_t(i)]),
                "an analysis file (.tsa) is for the pyramid methods' samples; method " + method
                    + " needs an image here");
            return false;
        }
    if (iscolorspace.size() > 1 && int(iscolorspace.size()) != n) {
        error = "iscolorspace: give one colour space for all samples or one per sample ("
            + std::to_string(n) + "), not " + std::to_string(iscolorspace.size());
        return false;
    }
    if (subbands && !m->subbands) {
        std::string with;
        for (const Method* other : methods())
            if (other->subbands)
                with += (with.empty() ? "" : ", ") + other->name;
        error = option_error(
            "subbands", "1", "method " + method + " has no subbands (only " + with + " do)");
        return false;
    }
    return true;
}

namespace {

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
    if (!set_method(r,
            method != j.end() && method->is_string() ? method->get<std::string>() : r.method,
            error))
        return false;
    KeyValues pairs;
    for (auto& [key, value] : j.items()) {
        pairs.emplace_back(key, std::vector<std::string>());
        const OptionField* field = is_recipe_key(key) ? nullptr : r.options.table().find(key);
        if (!json_values(key, value, field, pairs.back().second, error))
            return false;
    }
    if (!set_keys(r, pairs, base_dir, error))
        return false;
    recipe = std::move(r);
    return true;
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
    if (!r.options && !set_method(r, r.method, error))
        return false;
    for (const auto& [key, values] : pairs) {
        if (key != "method" || values.front() == r.method)
            continue;
        // Another method: its defaults, and the options given so far that are the same
        // option in both (shared: size, levels, …), not those that only share a name
        // (a choosy recipe's iterations are not the pyramid's).
        const OptionList& before = r.options.table(); // a static table: it outlives r.options
        if (!set_method(r, values.front(), error))
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
    if (!set_keys(r, pairs, base_dir, error))
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

bool apply_recipe_arguments(
    const std::string& arguments, const std::string& base_dir, Recipe& recipe, std::string& error)
{
    if (apply_arguments(arguments, base_dir, recipe, error))
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
        return j.dump(2) + "\n";
    } catch (const nlohmann::json::type_error&) { // JSON text is UTF-8
        throw std::invalid_argument(
            "a file or colour-space name is not valid UTF-8, which a JSON recipe cannot hold");
    }
}

} // namespace texsyn
