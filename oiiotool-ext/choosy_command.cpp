// SPDX-License-Identifier: Apache-2.0
// --choosy: Castellanos & Williams choosy sampling on the pixel grid, with an optional
// source map.
#include "cli_state.h"

namespace texsyn::cli {

void run_choosy(CliState& state, const std::string& command, const std::string& modifiers)
{
    run_map_command(state, command, modifiers, "choosy", &Recipe::choosy,
        MapSynthesis<ChoosyOptions>(choosy_synthesize));
}

} // namespace texsyn::cli
