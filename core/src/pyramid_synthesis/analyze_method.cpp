// SPDX-License-Identifier: Apache-2.0
// The registry row of the analysis: the pyramid method's statistics of a sample, for an
// analysis file.
#include <texsyn/methods.h>
#include <texsyn/pyramid_synthesis.h>

#include "pyramid_synthesis_pvt.h"

namespace texsyn::detail {

namespace {

// The pyramid options that shape an analysis; the others only matter to a synthesis.
const OptionTable<PyramidOptions>& analysis_table()
{
    return declared_table<PyramidOptions>([](OptionTable<PyramidOptions>& t) {
        t.subset(
            PyramidOptions::table(), { "pyramid", "scales", "orientations", "fft", "flatten" });
    });
}

bool run_analysis(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages&, const RunSettings& settings, MethodResult& result, std::string& error)
{
    PyramidOptions opt = options_of<PyramidOptions>(options);
    opt.nthreads = settings.nthreads;
    auto stats = std::make_shared<TextureStatistics>();
    // No output size: the analysis keeps every scale the sample allows.
    if (!analyze_texture(*inputs[0].image, opt, *stats, error))
        return false;
    result.analysis = std::move(stats);
    return true;
}

} // namespace

const Method& analyze_method()
{
    static const Method m { "analyze", MethodInputs::Image, MethodOutput::Analysis,
        [] { return MethodOptions(PyramidOptions(), analysis_table()); }, run_analysis,
        "analysis-files.md",
        "the pyramid method's analysis of a sample, to write as an analysis file (*.tsa) and "
        "synthesize from without the sample",
        "Replace the current image by its pyramid analysis, to write as *.tsa and synthesize "
        "from with --pyramid, --mix or --transfer. Only the options that shape an analysis "
        "apply.",
        "texsyn data/samples/rust.png --analyze -o rust.tsa", "" };
    return m;
}

} // namespace texsyn::detail
