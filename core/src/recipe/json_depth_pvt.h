// SPDX-License-Identifier: Apache-2.0
// The nesting depth of JSON text, measured before parsing: nlohmann's parser recurses once
// per level, so a file of a million '[' overflows the stack of whatever process reads it
// (stock oiiotool and iinfo, through the plugin).
#pragma once

#include <cstddef>
#include <string_view>

namespace texsyn::detail {

/// The deepest nesting of arrays and objects in `text` (brackets inside strings not
/// counted); stops counting past `limit` + 1.
inline size_t json_nesting_depth(std::string_view text, size_t limit)
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

} // namespace texsyn::detail
