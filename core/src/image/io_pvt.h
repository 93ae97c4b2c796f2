// SPDX-License-Identifier: Apache-2.0
// Shared by the file input/output sources.
#pragma once

#include <string>

namespace texsyn {

/// `s` with line breaks turned into spaces and trailing spaces removed: the tool prints
/// one line per error, and library messages can span several.
std::string one_line(std::string s);

} // namespace texsyn
