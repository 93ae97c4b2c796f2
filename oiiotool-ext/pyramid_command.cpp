// SPDX-License-Identifier: Apache-2.0
// --pyramid: Heeger & Bergen pyramid synthesis.
#include "cli_state.h"

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
            describe_by_recipe(state, sample, result, "pyramid", &Recipe::pyramid, opt);
            result.recipe.subbands = state.subbands;
            return true;
        });
}

} // namespace texsyn::cli
