// SPDX-License-Identifier: Apache-2.0
// What every synthesis command shares: its result's settings, progress, -v timing, errors.
#include "cli_state.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace texsyn::cli {

StackImage synthesis_result(const StackImage& base, std::vector<std::string> sources)
{
    StackImage result;
    result.sources = std::move(sources);
    result.input_colorspace = base.input_colorspace;
    result.input_format = base.input_format;
    result.output_colorspace = base.output_colorspace;
    return result;
}

Recipe recipe_of_sample(const CliState& state, const StackImage& sample)
{
    Recipe recipe;
    recipe.sample = sample.sources[0];
    recipe.iscolorspace = sample.input_colorspace;
    recipe.colorconfig = state.colorconfig_path;
    if (const char* env = std::getenv("OCIO"); recipe.colorconfig.empty() && env)
        recipe.colorconfig = env;
    return recipe;
}

std::function<void(float)> progress_reporter(const std::string& command)
{
    return [command](float fraction) {
        std::fprintf(stderr, "\rtexsyn: %s %3d%%", command.c_str(), int(fraction * 100.0f + 0.5f));
        std::fflush(stderr);
    };
}

void run_synthesis(CliState& state, const std::string& command, StackImage result,
    const std::string& legend, const std::function<bool(StackImage&)>& synthesize)
{
    auto start = std::chrono::steady_clock::now();
    bool ok = synthesize(result);
    if (state.progress)
        std::fprintf(stderr, "\n");
    if (!ok) {
        std::string error = result.buf.geterror();
        const bool names_input
            = error.find("sample") != std::string::npos || error.find("image") != std::string::npos;
        throw CliError(command + " : " + error + (names_input ? legend : ""));
    }
    if (state.verbose) {
        double secs
            = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string options = result.volume
            ? std::string(result.volume->attributes.get_string("synth:options"))
            : std::string(result.buf.spec().get_string_attribute("synth:options"));
        std::fprintf(stderr, "texsyn: %s %s from %s in %.2f s\n", command.c_str(), options.c_str(),
            sample_names(result).c_str(), secs);
    }
    state.stack.push_back(std::move(result));
}

} // namespace texsyn::cli
