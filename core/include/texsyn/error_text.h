// SPDX-License-Identifier: Apache-2.0
// Text that goes into error messages.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// `text` with control characters (line breaks, tabs, NUL, DEL) and bytes that are not
/// valid UTF-8 written as "\xHH": errors echo what the user gave, and an echoed line break
/// would split the one-line message (and raw bytes garble a terminal or a JSON log).
std::string printable_text(std::string_view text);

/// An error message ready to print: printable_text(), with every word longer than 120
/// characters cut to its first 60 and its length ("aaaa...(100000 characters)"; quotes
/// around the word and a colon or comma ending it are kept and not counted), so that
/// echoing a 100 kB argument or name does not make a 100 kB line.
std::string readable_message(std::string_view message);

/// The name in `names` nearest `word` — by Damerau–Levenshtein distance (insertions,
/// deletions, substitutions and swaps of neighbours), ignoring case — if it is at most
/// max(2, size of word / 3) edits away: what a "did you mean …?" suggests. "" if none is
/// that near, or if `word` is itself one of the names. Ties go to the earlier name.
std::string closest_name(std::string_view word, const std::vector<std::string>& names);

} // namespace texsyn
#pragma GCC visibility pop
