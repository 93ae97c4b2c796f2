// SPDX-License-Identifier: Apache-2.0
#include "cli_state.h"

#include <OpenImageIO/filesystem.h>

namespace texsyn::cli {

const ColorConfig& CliState::colors()
{
    if (!m_colors) {
        std::string error;
        m_colors = ColorConfig::load(colorconfig_path, error);
        if (!m_colors)
            throw CliError(error);
    }
    return *m_colors;
}

const char* const solid_input_message
    = "the current image is a solid texture (from --solid); it needs a 2-D image";

std::string CliState::too_few_images(const std::string& command, int needed, int have)
{
    if (have == 0 && needed == 1)
        return command + " : no current image (give an input file before it)";
    return command + " : needs " + std::to_string(needed) + " images on the stack, there "
        + (have == 1 ? "is 1" : "are " + std::to_string(have));
}

StackImage& CliState::top(const std::string& command)
{
    if (stack.empty())
        throw CliError(too_few_images(command, 1, 0));
    return stack.back();
}

namespace {

void refuse_analysis(const std::string& command, const StackImage& img)
{
    if (img.volume)
        throw CliError(command + " : " + solid_input_message);
    if (img.statistics)
        throw CliError(command + " : " + img.sources[0]
            + " is an analysis, not an image (only --pyramid synthesizes from an analysis)");
}

} // namespace

StackImage CliState::pop(const std::string& command)
{
    refuse_analysis(command, top(command));
    return pop_sample(command);
}

StackImage CliState::pop_sample(const std::string& command)
{
    if (top(command).volume)
        throw CliError(command + " : " + solid_input_message);
    StackImage img = std::move(top(command));
    stack.pop_back();
    return img;
}

std::vector<StackImage> CliState::pop(const std::string& command, int n)
{
    if (int(stack.size()) < n)
        throw CliError(too_few_images(command, n, int(stack.size())));
    for (size_t i = stack.size() - size_t(n); i < stack.size(); ++i)
        refuse_analysis(command, stack[i]);
    std::vector<StackImage> images;
    for (size_t i = stack.size() - size_t(n); i < stack.size(); ++i)
        images.push_back(std::move(stack[i]));
    stack.resize(stack.size() - size_t(n));
    return images;
}

std::string sample_names(const StackImage& img)
{
    std::string s;
    for (const std::string& source : img.sources)
        s += (s.empty() ? "" : ",") + OIIO::Filesystem::filename(source);
    return s;
}

} // namespace texsyn::cli
