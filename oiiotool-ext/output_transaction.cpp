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
    for (auto& [tmp, final] : m_pending)
        discard_temporary(tmp);
    m_pending.clear();
}

std::string OutputTransaction::final_names(std::string message) const
{
    for (const auto& [tmp, final] : m_pending) {
        // A writer's own temporary beside ours: ".STEM.texsyn-tmp….texsyn-tmp….EXT".
        const std::string tmp_name = std::filesystem::path(tmp).filename().string();
        const std::string stem = tmp_name.substr(0, tmp_name.rfind('.'));
        for (size_t at; (at = message.find(stem)) != std::string::npos;) {
            size_t end = at + stem.size();
            while (end < message.size() && message[end] != '"' && message[end] != ' '
                && message[end] != ')' && message[end] != ':')
                ++end;
            size_t begin = at;
            while (begin > 0 && message[begin - 1] != '"' && message[begin - 1] != ' '
                && message[begin - 1] != '(')
                --begin;
            message.replace(begin, end - begin, final);
        }
    }
    return message;
}

} // namespace texsyn::cli
