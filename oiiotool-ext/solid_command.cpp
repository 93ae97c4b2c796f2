// SPDX-License-Identifier: Apache-2.0
// --solid: Heeger & Bergen §4 solid textures.
#include "cli_state.h"

#include <chrono>
#include <cstdio>

namespace texsyn::cli {

void run_solid(CliState& state, const std::string& command, const std::string& modifiers)
{
    SolidOptions opt = parse_command_options<SolidOptions>(command, modifiers);
    opt.seed = state.seed;
    opt.nthreads = state.threads;
    if (state.progress)
        opt.progress = progress_reporter(command);

    StackImage sample = state.pop(command);
    StackImage result;
    result.source = sample.source;
    result.input_colorspace = sample.input_colorspace;
    result.input_format = sample.input_format;
    result.output_colorspace = sample.output_colorspace;
    result.volume = std::make_shared<PlanarVolume>();
    auto start = std::chrono::steady_clock::now();
    std::string error;
    const bool ok = solid_synthesize(*result.volume, sample.buf, opt, error);
    if (state.progress)
        std::fprintf(stderr, "\n");
    if (!ok)
        throw CliError(command + " : " + error);
    if (state.verbose) {
        const double secs
            = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::fprintf(stderr, "texsyn: --solid %s from %s in %.2f s\n",
            result.volume->attributes.get_string("synth:options").c_str(), sample.source.c_str(),
            secs);
    }
    state.stack.push_back(std::move(result));
}

} // namespace texsyn::cli
