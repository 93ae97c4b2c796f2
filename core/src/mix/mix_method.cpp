// SPDX-License-Identifier: Apache-2.0
// The registry row of texture mixtures: as many samples (images or analyses) as the
// options name.
#include <texsyn/methods.h>
#include <texsyn/mix.h>

#include <algorithm>

#include "methods/method_helpers_pvt.h"
#include "methods/result_layout_pvt.h"

namespace texsyn::detail {

namespace {

bool run_mix(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages&, const RunSettings& settings, MethodResult& result, std::string& error)
{
    MixOptions opt = options_of<MixOptions>(options);
    apply_run_settings(settings, opt.synthesis);
    std::vector<MixSample> samples;
    for (const MethodInput& in : inputs)
        samples.push_back(in.image ? MixSample(in.image) : MixSample(in.analysis));
    if (mix_synthesize(result.image, samples, opt, settings.subbands ? &result.subbands : nullptr))
        return true;
    error = result.image.geterror();
    return false;
}

// The first sample's size, the palette sample's channels.
bool mix_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string&)
{
    const size_t palette = size_t(options_of<MixOptions>(options).palette.value_or(0));
    layout = layout_from_input(inputs[std::min(palette, inputs.size() - 1)], options);
    ResultLayout first = layout_from_input(inputs[0], options);
    layout.width = first.width;
    layout.height = first.height;
    return true;
}

} // namespace

const Method& mix_method()
{
    static const Method m { "mix", MethodInputs::Samples, MethodOutput::Image,
        [] { return MethodOptions(MixOptions()); }, run_mix, "mixtures.md",
        "Heeger & Bergen 1995 section 5: texture mixtures (palette of one sample and pattern "
        "of another, low and high bands, averaged histograms)",
        "Heeger & Bergen 1995 section 5 texture mixture of the top images or analyses (sample "
        "0 is the one pushed first): one mode of palette=I:pattern=J (colour of I, subband "
        "statistics of J), split=S (scales >= S and the low-pass of sample 0, finer bands of "
        "sample 1) or weights=W0,W1,... (averaged histograms; pops one image per weight, else "
        "2).",
        "texsyn data/samples/rust.png data/samples/marble_pink.png "
        "--mix:palette=0:pattern=1:size=256x256 -o rust_marble.exr",
        "one sample's colours with another's pattern", true,
        [](const MethodOptions& o) { return options_of<MixOptions>(o).nsamples(); },
        [](const MethodOptions& o) { return options_of<MixOptions>(o).palette.value_or(0); }, {},
        mix_layout };
    return m;
}

} // namespace texsyn::detail
