// SPDX-License-Identifier: Apache-2.0
// The registry row of texture transfer: an image, then a sample (or an analysis).
#include <texsyn/methods.h>
#include <texsyn/transfer.h>

#include "methods/result_layout_pvt.h"
#include "pyramid_synthesis/pyramid_synthesis_pvt.h"

namespace texsyn::detail {

namespace {

// The pyramid options but size: the image gives the output's size.
const OptionTable<PyramidOptions>& transfer_table()
{
    return declared_table<PyramidOptions>([](OptionTable<PyramidOptions>& t) {
        std::vector<std::string> names;
        for (const OptionField& f : PyramidOptions::table().fields())
            if (f.name != "size")
                names.push_back(f.name);
        t.subset(PyramidOptions::table(), names);
    });
}

bool run_transfer(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages&, const RunSettings& settings, MethodResult& result, std::string& error)
{
    PyramidOptions opt = options_of<PyramidOptions>(options);
    apply_run_settings(settings, opt);
    std::vector<NamedImage>* subbands = settings.subbands ? &result.subbands : nullptr;
    const MethodInput &image = inputs[0], &sample = inputs[1];
    if (sample.analysis && opt.flatten) { // an analysis keeps no pixels to divide
        error = flatten_of_analysis_error(sample.name);
        return false;
    }
    const bool ok = sample.analysis
        ? transfer_synthesize(result.image, *sample.analysis, *image.image, opt, subbands)
        : transfer_synthesize(result.image, *sample.image, *image.image, opt, subbands);
    if (!ok)
        error = result.image.geterror();
    return ok;
}

// The image's size, the sample's channels; it tiles only if the image does, which is not
// known, so it is not marked.
bool transfer_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string&)
{
    layout = layout_from_input(inputs[1], options);
    layout.width = inputs[0].width;
    layout.height = inputs[0].height;
    layout.set_tiles(false);
    return true;
}

} // namespace

const Method& transfer_method()
{
    static const Method m { "transfer", MethodInputs::ImageAndSample, MethodOutput::Image,
        [] { return MethodOptions(PyramidOptions(), transfer_table()); }, run_transfer,
        "mixtures.md",
        "Heeger & Bergen 1995 section 5: match-texture applied to an image instead of noise "
        "(its layout, the sample's statistics)",
        "Texture transfer: pops a sample or analysis (top) and an image (below it) and gives "
        "the image's layout the sample's statistics, at the image's size.",
        "texsyn data/samples/marble_pink.png data/samples/rust.png --transfer -o "
        "marble_in_rust.exr",
        "an image's layout in a sample's texture", true, {}, {}, {}, transfer_layout };
    return m;
}

} // namespace texsyn::detail
