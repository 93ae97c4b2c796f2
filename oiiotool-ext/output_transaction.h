// SPDX-License-Identifier: Apache-2.0
// The run's outputs as one transaction: each is written to a temporary file beside its
// final name, and all are renamed into place only when the whole run succeeded.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace texsyn::cli {

class OutputTransaction {
public:
    /// A temporary path for `filename` (same folder and extension), registered so that
    /// commit() renames it to `filename` and discard() removes it.
    std::string add(const std::string& filename);
    /// Renames every temporary file into place; throws CliError if one cannot be.
    void commit();
    /// Removes every temporary file written so far.
    void discard();
    /// `message` with the temporary files' names (and names derived from them, as
    /// libraries' own temporaries) replaced by the final names the user gave.
    std::string final_names(std::string message) const;

private:
    std::vector<std::pair<std::string, std::string>> m_pending; ///< (temporary, final)
};

} // namespace texsyn::cli
