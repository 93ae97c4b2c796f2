// SPDX-License-Identifier: Apache-2.0
// --mix: Heeger & Bergen §5 texture mixtures of the images on the stack.
#include "cli_state.h"

namespace texsyn::cli {

MixOptions parse_mix_options(const std::string& command, const std::string& modifiers)
{
    MixOptions opt = parse_modifiers(command, modifiers, MixOptions::table());
    std::string error;
    if (!opt.validate(error))
        throw CliError(command + " : " + error);
    return opt;
}

void run_mix(CliState& state, const std::string& command, const std::string& modifiers)
{
    MixOptions opt = parse_mix_options(command, modifiers);
    apply_run_settings(state, command, opt.synthesis);
    std::vector<StackImage> samples = state.pop(command, opt.nsamples());
    std::vector<const OIIO::ImageBuf*> bufs;
    std::vector<std::string> sources;
    std::string legend;
    for (size_t k = 0; k < samples.size(); ++k) {
        bufs.push_back(&samples[k].buf);
        sources.insert(sources.end(), samples[k].sources.begin(), samples[k].sources.end());
        legend += (k ? ", " : " (") + ("sample " + std::to_string(k)) + " = "
            + sample_names(samples[k]);
    }
    legend += ")";
    // The output's colour spaces and pixel type follow the sample its colour comes from.
    const StackImage& base = samples[size_t(opt.palette.value_or(0))];
    run_synthesis(state, command, synthesis_result(base, sources), legend, [&](StackImage& result) {
        return mix_synthesize(result.buf, bufs, opt, state.subbands ? &result.subbands : nullptr);
    });
}

} // namespace texsyn::cli
