// SPDX-License-Identifier: Apache-2.0
// --pyramid: Heeger & Bergen pyramid synthesis.
#include "cli_state.h"

#include <cstdio>
#include <cstdlib>

namespace texsyn::cli {

void run_pyramid(CliState& state, const std::string& command, const std::string& modifiers)
{
    PyramidOptions opt = synthesis_options<PyramidOptions>(state, command, modifiers);
    StackImage sample = state.pop_sample(command);
    if (sample.statistics && opt.flatten) // an analysis keeps no pixels to divide
        throw CliError(command + " : flatten=1 needs a sample, and " + sample.source
            + " is an analysis (flatten when analysing: --analyze:flatten=1)");
    StackImage result = synthesis_of(sample);
    const double start = seconds_now();
    std::vector<NamedImage>* subbands = state.subbands ? &result.subbands : nullptr;
    bool ok = sample.statistics
        ? synthesize_from_statistics(result.buf, *sample.statistics, opt, nullptr, subbands)
        : pyramid_synthesize(result.buf, sample.buf, opt, subbands);
    if (state.progress)
        std::fprintf(stderr, "\n");
    if (!ok)
        throw CliError(command + " : " + result.buf.geterror());
    if (sample.from_file) { // a synthesis of a file: a recipe can say it
        result.has_recipe = true;
        result.recipe.sample = sample.source;
        result.recipe.iscolorspace = sample.input_colorspace;
        result.recipe.pyramid = opt;
        result.recipe.pyramid.nthreads = 0;
        result.recipe.pyramid.progress = nullptr;
        result.recipe.subbands = state.subbands;
        result.recipe.colorconfig = state.colorconfig_path;
        if (const char* env = std::getenv("OCIO"); result.recipe.colorconfig.empty() && env)
            result.recipe.colorconfig = env;
    }
    report_synthesis(state, command, result.buf.spec().get_string_attribute("synth:options"),
        sample.source, start);
    state.stack.push_back(std::move(result));
}

} // namespace texsyn::cli
