// SPDX-License-Identifier: Apache-2.0
// --pyramid: Heeger & Bergen pyramid synthesis.
#include "cli_state.h"

#include <cstdlib>

namespace texsyn::cli {

PyramidOptions parse_pyramid_options(const std::string& command, const std::string& modifiers)
{
    return parse_modifiers(command, modifiers, PyramidOptions::table());
}

void run_pyramid(CliState& state, const std::string& command, const std::string& modifiers)
{
    PyramidOptions opt = parse_pyramid_options(command, modifiers);
    apply_run_settings(state, command, opt);
    StackImage sample = state.pop_sample(command);
    if (sample.statistics && opt.flatten) // an analysis keeps no pixels to divide
        throw CliError(command + " : flatten=1 needs a sample, and " + sample.sources[0]
            + " is an analysis (flatten when analysing: --analyze:flatten=1)");
    run_synthesis(
        state, command, synthesis_result(sample, sample.sources), "", [&](StackImage& result) {
            std::vector<NamedImage>* subbands = state.subbands ? &result.subbands : nullptr;
            if (!(sample.statistics ? synthesize_from_statistics(
                      result.buf, *sample.statistics, opt, nullptr, subbands)
                                    : pyramid_synthesize(result.buf, sample.buf, opt, subbands)))
                return false;
            if (sample.from_file) { // a synthesis of a file: a recipe can say it
                result.has_recipe = true;
                result.recipe.sample = sample.sources[0];
                result.recipe.iscolorspace = sample.input_colorspace;
                result.recipe.pyramid = opt;
                result.recipe.pyramid.nthreads = 0;
                result.recipe.pyramid.progress = nullptr;
                result.recipe.subbands = state.subbands;
                result.recipe.colorconfig = state.colorconfig_path;
                if (const char* env = std::getenv("OCIO"); result.recipe.colorconfig.empty() && env)
                    result.recipe.colorconfig = env;
            }
            return true;
        });
}

} // namespace texsyn::cli
