// SPDX-License-Identifier: Apache-2.0
// --transfer: Heeger & Bergen §5 texture transfer, match-texture started from an image.
#include "cli_state.h"

namespace texsyn::cli {

PyramidOptions parse_transfer_options(const std::string& command, const std::string& modifiers)
{
    PyramidOptions opt = parse_pyramid_options(command, modifiers);
    std::string error;
    if (!validate_transfer_options(opt, error))
        throw CliError(command + " : " + error);
    return opt;
}

void run_transfer(CliState& state, const std::string& command, const std::string& modifiers)
{
    PyramidOptions opt = parse_transfer_options(command, modifiers);
    apply_run_settings(state, command, opt);
    std::vector<StackImage> images = state.pop(command, 2);
    const StackImage &image = images[0], &sample = images[1];
    const std::string legend
        = " (image = " + sample_names(image) + ", sample = " + sample_names(sample) + ")";
    run_synthesis(
        state, command, synthesis_result(sample, sample.sources), legend, [&](StackImage& result) {
            if (!transfer_synthesize(result.buf, sample.buf, image.buf, opt,
                    state.subbands ? &result.subbands : nullptr))
                return false;
            result.buf.specmod().attribute("synth:image", sample_names(image));
            return true;
        });
}

} // namespace texsyn::cli
