// SPDX-License-Identifier: Apache-2.0
// --analyze: the pyramid method's analysis of a sample, for an analysis file (.tsa).
#include "cli_state.h"

#include <algorithm>

#include <OpenImageIO/filesystem.h>

namespace texsyn::cli {

namespace {

// The options that shape an analysis; the others only matter to a synthesis.
const std::vector<std::string> analysis_keys
    = { "pyramid", "scales", "orientations", "fft", "flatten" };

} // namespace

PyramidOptions parse_analyze_options(const std::string& command, const std::string& modifiers)
{
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string error;
    if (!split_option_string(modifiers, pairs, error))
        throw CliError(command + " : " + error);
    for (const auto& [key, value] : pairs)
        if (std::find(analysis_keys.begin(), analysis_keys.end(), key) == analysis_keys.end())
            throw CliError(command + " : " + key
                + "= is not an analysis option (known: pyramid, scales, orientations, fft, "
                  "flatten; "
                  "give synthesis options to --pyramid)");
    return parse_pyramid_options(command, modifiers);
}

void run_analyze(CliState& state, const std::string& command, const std::string& modifiers)
{
    PyramidOptions opt = parse_analyze_options(command, modifiers);
    opt.nthreads = state.threads;
    StackImage sample = state.pop(command);
    auto stats = std::make_shared<TextureStatistics>();
    std::string error;
    // No output size: the analysis keeps every scale the sample allows.
    if (!analyze_texture(sample.buf, opt, *stats, error))
        throw CliError(command + " : " + error);
    stats->source = sample_names(sample);
    stats->colorspace = sample.input_colorspace;
    stats->sample_format = sample.input_format.c_str();
    StackImage result = synthesis_result(sample, sample.sources);
    result.statistics = std::move(stats);
    result.from_file = sample.from_file;
    state.stack.push_back(std::move(result));
}

} // namespace texsyn::cli
