// SPDX-License-Identifier: Apache-2.0
// --solid: Heeger & Bergen §4 solid textures.
#include "cli_state.h"

#include <cstdio>

namespace texsyn::cli {

void run_solid(CliState& state, const std::string& command, const std::string& modifiers)
{
    SolidOptions opt = synthesis_options<SolidOptions>(state, command, modifiers);
    StackImage sample = state.pop(command);
    StackImage result = synthesis_of(sample);
    result.volume = std::make_shared<PlanarVolume>();
    const double start = seconds_now();
    std::string error;
    const bool ok = solid_synthesize(*result.volume, sample.buf, opt, error);
    if (state.progress)
        std::fprintf(stderr, "\n");
    if (!ok)
        throw CliError(command + " : " + error);
    report_synthesis(state, command, result.volume->attributes.get_string("synth:options"),
        sample.source, start);
    state.stack.push_back(std::move(result));
}

} // namespace texsyn::cli
