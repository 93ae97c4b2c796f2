// SPDX-License-Identifier: Apache-2.0
#include "stack.h"

#include "cli_error.h"

namespace texsyn::cli {

std::string too_few_items(const std::string& command, int needed, int have)
{
    if (have == 0 && needed == 1)
        return command + " : no current image (give an input file before it)";
    return command + " : needs " + std::to_string(needed) + " images on the stack, there "
        + (have == 1 ? "is 1" : "are " + std::to_string(have));
}

StackItem& Stack::top(const std::string& command)
{
    if (m_items.empty())
        throw CliError(too_few_items(command, 1, 0));
    return m_items.back();
}

std::vector<StackItem> Stack::pop(const std::string& command, int n)
{
    if (size() < n)
        throw CliError(too_few_items(command, n, size()));
    std::vector<StackItem> items(
        std::make_move_iterator(m_items.end() - n), std::make_move_iterator(m_items.end()));
    m_items.resize(m_items.size() - size_t(n));
    return items;
}

} // namespace texsyn::cli
