// SPDX-License-Identifier: Apache-2.0
#include "output_transaction.h"

#include <filesystem>

#include <texsyn/io.h>

#include "cli_error.h"

namespace texsyn::cli {

std::string OutputTransaction::add(const std::string& filename)
{
    std::string tmp = temporary_path_for(filename);
    m_pending.emplace_back(tmp, filename);
    return tmp;
}

void OutputTransaction::commit()
{
    std::string error;
    for (auto& [tmp, final] : m_pending)
        if (!commit_file(tmp, final, error))
            throw CliError(error);
    m_pending.clear();
}

void OutputTransaction::discard()
{
    std::error_code ec;
    for (auto& [tmp, final] : m_pending)
        std::filesystem::remove(tmp, ec);
    m_pending.clear();
}

} // namespace texsyn::cli
