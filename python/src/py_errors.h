// SPDX-License-Identifier: Apache-2.0
// How the library's one-line messages become Python exceptions.
#pragma once

#include <string>

namespace texsyn::python {

/// Which Python exception a message becomes.
enum class ErrorKind {
    Value,   ///< ValueError: a bad option, keyword, array or recipe
    File,    ///< OSError: a file that cannot be read or written
    Runtime, ///< RuntimeError: anything else (a synthesis that fails)
};

/// Raises `message` (made readable: printable_text, long words cut) as `kind`'s exception.
[[noreturn]] void raise_error(ErrorKind kind, const std::string& message);

} // namespace texsyn::python
