// SPDX-License-Identifier: Apache-2.0
// Parsing untrusted JSON (recipes, analysis-file headers) strictly.
#pragma once

#include <cstddef>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace texsyn::detail {

/// Parses `text`, refusing what nlohmann's parser would accept but a careful reader must
/// not: nesting deeper than `max_depth` (checked before parsing: the parser recurses once
/// per level, so a file of a million '[' would overflow the stack of whatever process
/// reads it, stock oiiotool and iinfo included) and an object with a repeated key (one of
/// the values would be silently lost). Throws std::runtime_error ("nested more than 64
/// deep", "duplicate key \"seed\"") or nlohmann::json::exception for malformed JSON.
nlohmann::json parse_json_strict(std::string_view text, size_t max_depth);

} // namespace texsyn::detail
