// SPDX-License-Identifier: Apache-2.0
// --solid: Heeger & Bergen §4 solid textures.
#include "cli_state.h"

namespace texsyn::cli {

void run_solid(CliState& state, const std::string& command, const std::string& modifiers)
{
    SolidOptions opt = parse_modifiers(command, modifiers, SolidOptions::table());
    apply_run_settings(state, command, opt);
    StackImage sample = state.pop(command);
    StackImage result = synthesis_result(sample, sample.sources);
    result.volume = std::make_shared<PlanarVolume>();
    run_synthesis(state, command, std::move(result), "", [&](StackImage& r) {
        std::string error;
        if (solid_synthesize(*r.volume, sample.buf, opt, error))
            return true;
        r.buf.errorfmt("{}", error);
        return false;
    });
}

} // namespace texsyn::cli
