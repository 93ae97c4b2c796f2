// SPDX-License-Identifier: Apache-2.0
// The registry row of the pyramid method: a sample, or an analysis of one.
#include <texsyn/methods.h>
#include <texsyn/pyramid_synthesis.h>

#include "pyramid_synthesis_pvt.h"

namespace texsyn::detail {

namespace {

bool run_pyramid(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages&, const RunSettings& settings, MethodResult& result, std::string& error)
{
    PyramidOptions opt = options_of<PyramidOptions>(options);
    apply_run_settings(settings, opt);
    std::vector<NamedImage>* subbands = settings.subbands ? &result.subbands : nullptr;
    const MethodInput& sample = inputs[0];
    if (sample.analysis && opt.flatten) { // an analysis keeps no pixels to divide
        error = flatten_of_analysis_error(sample.name);
        return false;
    }
    const bool ok = sample.analysis
        ? synthesize_from_statistics(result.image, *sample.analysis, opt, nullptr, subbands)
        : pyramid_synthesize(result.image, *sample.image, opt, subbands);
    if (!ok)
        error = result.image.geterror();
    return ok;
}

} // namespace

const Method& pyramid_method()
{
    static const Method m { "pyramid", MethodInputs::Sample, MethodOutput::Image,
        [] { return MethodOptions(PyramidOptions()); }, run_pyramid, "how-it-works.md",
        "Heeger & Bergen 1995: pyramid-based histogram matching (steerable or Laplacian), "
        "seamless",
        "Heeger & Bergen 1995 pyramid synthesis of the current image or analysis (*.tsa): noise "
        "matched to the sample's pixel and subband histograms, circular, so it tiles.",
        "texsyn data/samples/rust.png --pyramid:size=512x512 -o rust_512.exr",
        "stochastic, noise-like: rust, stucco, sand", true };
    return m;
}

} // namespace texsyn::detail
