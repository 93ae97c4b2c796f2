// SPDX-License-Identifier: Apache-2.0
// The tool's one error type.
#pragma once

#include <stdexcept>

namespace texsyn::cli {

/// An error to report as "texsyn ERROR: <what>" with exit code 1.
struct CliError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

} // namespace texsyn::cli
