// SPDX-License-Identifier: Apache-2.0
// Text that goes into error messages.
#pragma once

#include <string>
#include <string_view>

namespace texsyn {

/// `text` with control characters (line breaks, tabs, NUL, DEL) written as "\xHH": errors
/// echo what the user gave, and an echoed line break would split the one-line message.
std::string printable_text(std::string_view text);

} // namespace texsyn
