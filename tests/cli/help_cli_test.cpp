// SPDX-License-Identifier: Apache-2.0
// End-to-end runs of the help: the suggestions for misspelt commands and options.
#include "cli_fixture.h"

TEST_F(Cli, MisspeltCommandsAndOptionsGetASuggestion)
{
    expect_failure("stucco.png --neighbourhood -o x.png",
        "texsyn ERROR: unknown command '--neighbourhood' (did you mean --neighborhood?)");
    expect_failure("stucco.png --neighbourhood:size=64x64 -o x.png",
        "texsyn ERROR: unknown command '--neighbourhood' (did you mean --neighborhood?)");
    expect_failure("--sed 3 stucco.png --pyramid -o x.png",
        "texsyn ERROR: unknown command '--sed' (did you mean --seed?)");
    expect_failure("stucco.png --pyramid:sise=512x512 -o x.png",
        "texsyn ERROR: --pyramid : sise=512x512 : unknown option 'sise' (did you mean size?)");
    expect_failure("stucco.png --choosy:iteartions=1,2 -o x.png",
        "texsyn ERROR: --choosy : iteartions=1,2 : unknown option 'iteartions' (did you mean "
        "iterations?)");
    // Far from every name: no guess.
    expect_failure("stucco.png --frobnicate -o out.exr",
        "texsyn ERROR: unknown command or option '--frobnicate' (see texsyn --help)");
}
