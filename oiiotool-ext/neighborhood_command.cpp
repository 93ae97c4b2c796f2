// SPDX-License-Identifier: Apache-2.0
// --neighborhood: Wei & Levoy neighbourhood synthesis, with an optional source map.
#include "cli_state.h"

namespace texsyn::cli {

void run_neighborhood(CliState& state, const std::string& command, const std::string& modifiers)
{
    run_map_command(state, command, modifiers, "neighborhood", &Recipe::neighborhood,
        MapSynthesis<NeighborhoodOptions>(neighborhood_synthesize));
}

} // namespace texsyn::cli
