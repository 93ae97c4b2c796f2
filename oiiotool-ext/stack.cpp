// SPDX-License-Identifier: Apache-2.0
#include "stack.h"

#include "cli_error.h"

namespace texsyn::cli {

const char* item_kind_text(ItemKind kind)
{
    return kind == ItemKind::Analysis ? "an analysis"
        : kind == ItemKind::Volume    ? "a solid texture"
        : kind == ItemKind::Mesh      ? "a textured mesh"
        : kind == ItemKind::Material  ? "a material set"
                                      : "an image";
}

std::string result_name(const Method& m, const std::vector<std::string>& inputs)
{
    std::string names;
    for (const std::string& input : inputs)
        names += (names.empty() ? "" : ", ") + input;
    const std::string what = m.output == MethodOutput::Analysis ? "analysis"
        : m.output == MethodOutput::Material                    ? "material set"
                                                                : m.name + " synthesis";
    return names.empty() ? what : what + " of " + names;
}

ItemKind item_kind(MethodOutput output)
{
    return output == MethodOutput::Volume  ? ItemKind::Volume
        : output == MethodOutput::Analysis ? ItemKind::Analysis
        : output == MethodOutput::Mesh     ? ItemKind::Mesh
        : output == MethodOutput::Material ? ItemKind::Material
                                           : ItemKind::Image;
}

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
