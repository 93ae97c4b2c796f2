// SPDX-License-Identifier: Apache-2.0
#include "cli_state.h"

#include <chrono>
#include <cstdio>

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

std::function<void(float)> progress_reporter(const std::string& command)
{
    return [command](float fraction) {
        std::fprintf(stderr, "\rtexsyn: %s %3d%%", command.c_str(), int(fraction * 100.0f + 0.5f));
        std::fflush(stderr);
    };
}

const char* const solid_input_message
    = "the current image is a solid texture (from --solid); it needs a 2-D image";

StackImage synthesis_of(const StackImage& sample)
{
    StackImage result;
    result.source = sample.source;
    result.input_colorspace = sample.input_colorspace;
    result.input_format = sample.input_format;
    result.output_colorspace = sample.output_colorspace;
    return result;
}

double seconds_now()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

void report_synthesis(const CliState& state, const std::string& command, const std::string& options,
    const std::string& source, double start)
{
    if (state.verbose)
        std::fprintf(stderr, "texsyn: %s %s from %s in %.2f s\n", command.c_str(), options.c_str(),
            source.c_str(), seconds_now() - start);
}

StackImage& CliState::top(const std::string& command)
{
    if (stack.empty())
        throw CliError(command + " : no current image (give an input file before it)");
    return stack.back();
}

StackImage CliState::pop(const std::string& command)
{
    if (top(command).statistics)
        throw CliError(command + " : " + top(command).source
            + " is an analysis, not an image (only --pyramid synthesizes from an analysis)");
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

} // namespace texsyn::cli
