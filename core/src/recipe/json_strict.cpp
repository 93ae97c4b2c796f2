// SPDX-License-Identifier: Apache-2.0
#include "json_strict_pvt.h"

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace texsyn::detail {

namespace {

// The deepest nesting of arrays and objects in `text` (brackets inside strings not
// counted); stops counting past `limit` + 1.
size_t json_nesting_depth(std::string_view text, size_t limit)
{
    size_t depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (char c : text) {
        if (in_string) {
            if (escaped)
                escaped = false;
            else if (c == '\\')
                escaped = true;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > deepest && (deepest = depth) > limit)
                return deepest;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

} // namespace

nlohmann::json parse_json_strict(std::string_view text, size_t max_depth)
{
    // nlohmann's parser takes a NUL byte for the end of the input and would ignore what
    // follows it.
    if (const size_t nul = text.find('\0'); nul != std::string_view::npos)
        throw std::runtime_error("a NUL byte at offset " + std::to_string(nul));
    if (json_nesting_depth(text, max_depth) > max_depth)
        throw std::runtime_error("nested more than " + std::to_string(max_depth) + " deep");
    std::vector<std::set<std::string>> keys; // of each object being parsed
    auto check = [&](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
        using event_t = nlohmann::json::parse_event_t;
        if (event == event_t::object_start)
            keys.emplace_back();
        else if (event == event_t::object_end && !keys.empty())
            keys.pop_back();
        else if (event == event_t::key && !keys.empty()
            && !keys.back().insert(parsed.get<std::string>()).second)
            throw std::runtime_error("duplicate key \"" + parsed.get<std::string>() + "\"");
        return true;
    };
    return nlohmann::json::parse(text.begin(), text.end(), check);
}

} // namespace texsyn::detail
