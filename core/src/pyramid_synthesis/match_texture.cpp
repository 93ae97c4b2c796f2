// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen 1995 §3.3 match-texture, with §3.4 edge handling and §3.5 colour: the
// synthesis half, from a TextureStatistics (analyze_texture.cpp makes one).
#include "pyramid_synthesis_pvt.h"

#include <algorithm>
#include <new>

namespace texsyn {

namespace {

// Iterates match-texture on `image` (the start: noise or a transfer image) towards one
// component's tables.
void match_texture(Plane& image, const QuantileTable& pixels,
    const std::vector<QuantileTable>& bands, const Pyramid& synthesis, int iterations,
    HistogramMode mode, int nthreads, const StopFlag* stop, std::vector<Plane>& work,
    const std::function<void(int)>& iteration_done)
{
    match_histogram(image, pixels, mode, nthreads);
    for (int it = 0; it < iterations; ++it) {
        // Bands are matched in parallel, each on one thread (see transform_bands).
        synthesis.transform_bands(
            image, work,
            [&](int b, Plane& band) { match_histogram(band, bands[size_t(b)], mode, 1); }, nthreads,
            stop);
        detail::throw_if_stopped(stop);
        match_histogram(image, pixels, mode, nthreads);
        iteration_done(it + 1);
    }
}

// The component's band tables with opt.gain / opt.balance applied (a positive factor per
// band keeps the tables sorted).
std::vector<QuantileTable> adjusted_bands(
    const ComponentStatistics& comp, const TextureStatistics& stats, const PyramidOptions& opt)
{
    std::vector<QuantileTable> bands = comp.bands;
    for (size_t b = 0; b < bands.size(); ++b) {
        const float f = detail::band_gain(opt, int(b), int(bands.size()));
        if (f == 1.0f)
            continue;
        std::vector<float> v = bands[b].sorted();
        for (float& x : v)
            x *= f;
        bands[b] = QuantileTable::from_sorted(std::move(v));
    }
    return bands;
}

} // namespace

std::string detail::flatten_of_analysis_error(const std::string& name)
{
    return option_error("flatten", "1",
        "needs a sample, and " + name
            + " is an analysis (flatten when analysing: --analyze:flatten=1)");
}

bool detail::check_against_analysis(
    const TextureStatistics& stats, const PyramidOptions& opt, std::string& error)
{
    auto mismatch = [&](const std::string& what, const std::string& analysed) {
        error = what + " : differs from the analysis (" + analysed + ")";
        return false;
    };
    if (opt.pyramid != stats.pyramid)
        return mismatch(std::string("pyramid=") + pyramid_kind_name(opt.pyramid),
            std::string("pyramid=") + pyramid_kind_name(stats.pyramid));
    if (opt.scales && opt.scales != stats.scales)
        return mismatch(
            "scales=" + std::to_string(opt.scales), "scales=" + std::to_string(stats.scales));
    if (opt.pyramid == PyramidKind::Steerable && opt.orientations != stats.orientations)
        return mismatch("orientations=" + std::to_string(opt.orientations),
            "orientations=" + std::to_string(stats.orientations));
    return detail::check_band_adjustments(opt, stats.scales, error);
}

namespace {

bool synthesize(OIIO::ImageBuf& dst, const TextureStatistics& stats, const PyramidOptions& opt,
    const OIIO::ImageBuf* start, std::vector<NamedImage>* subbands)
{
    std::string error;
    auto fail = [&](const std::string& message) {
        dst.errorfmt("{}", message);
        return false;
    };
    if (!opt.validate(error) || !detail::check_against_analysis(stats, opt, error))
        return fail(error);
    PlanarImage initial;
    if (start) {
        if (!planes_from_imagebuf(*start, initial, error, opt.nthreads))
            return fail("start image: " + error);
        if (initial.nchannels() != stats.nchannels())
            return fail("start image has " + std::to_string(initial.nchannels())
                + " channels, the sample " + std::to_string(stats.nchannels()));
        if ((opt.width || opt.height)
            && (opt.width != initial.width() || opt.height != initial.height()))
            return fail("size=" + std::to_string(opt.width) + "x" + std::to_string(opt.height)
                + " differs from the start image's " + std::to_string(initial.width()) + "x"
                + std::to_string(initial.height()));
        decorrelate(initial, stats.color, opt.nthreads);
    }
    const int w = start ? initial.width() : opt.width ? opt.width : stats.sample_width;
    const int h = start ? initial.height() : opt.height ? opt.height : stats.sample_height;
    const int scales = stats.scales;
    if (std::min(w, h) < (1 << scales))
        return fail("size=" + std::to_string(w) + "x" + std::to_string(h) + " is too small for "
            + std::to_string(scales) + " scales (each side at least " + std::to_string(1 << scales)
            + ")");
    if (!detail::check_memory(pyramid_memory_estimate(w, h, stats.nchannels(), opt),
            "size=" + std::to_string(w) + "x" + std::to_string(h), error))
        return fail(error);
    std::unique_ptr<Pyramid> synthesis
        = detail::make_pyramid(opt, w, h, scales, Boundary::Circular, error);
    if (!synthesis)
        return fail(error);

    PlanarImage out;
    out.channel_names = stats.channel_names;
    out.alpha_channel = stats.alpha_channel;
    const int nc = stats.nchannels();
    std::vector<std::vector<Plane>> synth_bands(static_cast<size_t>(nc));
    std::vector<std::string> component_names;
    for (int c = 0; c < nc; ++c) {
        const ComponentStatistics& comp = stats.components[size_t(c)];
        component_names.push_back(comp.name);
        if (comp.constant) {
            out.channels.emplace_back(w, h, comp.mean);
        } else {
            auto iteration_done = [&](int it) {
                detail::report_progress(opt.progress, opt.stop,
                    float(c * opt.iterations + it) / float(std::max(1, nc * opt.iterations)));
            };
            Plane image = start ? std::move(initial.channels[size_t(c)])
                                : detail::seeded_noise(w, h, opt.seed, uint64_t(c), opt.nthreads);
            std::vector<Plane> work; // freed after each component: one set is alive
            match_texture(image, comp.pixels, adjusted_bands(comp, stats, opt), *synthesis,
                opt.iterations, opt.histogram, opt.nthreads, opt.stop, work, iteration_done);
            out.channels.push_back(std::move(image));
        }
        if (subbands)
            synthesis->build(out.channels.back(), synth_bands[size_t(c)], opt.nthreads);
    }
    if (subbands)
        detail::append_subbands(
            "synth", synthesis->band_names(), synth_bands, component_names, *subbands);
    synth_bands.clear();

    // Back to the sample's channels, then one last match of each channel's histogram to the
    // sample's (in scene-linear), which recorrelation alone does not guarantee.
    recorrelate(out, stats.color, opt.nthreads);
    for (int c = 0; c < nc; ++c)
        match_histogram(
            out.channels[size_t(c)], stats.channels[size_t(c)], opt.histogram, opt.nthreads);

    // Same alpha convention as the sample: un-associated colour stays so (and survives
    // where alpha is 0), associated colour (OIIO's default) is re-associated.
    imagebuf_from_planes(out, dst, !stats.unassociated_alpha, opt.nthreads);
    PyramidOptions resolved = opt;
    resolved.width = w;
    resolved.height = h;
    resolved.scales = scales;
    resolved.flatten = stats.flattened ? 1 : 0;
    OIIO::ImageSpec& spec = dst.specmod();
    spec.attribute("synth:version", version());
    spec.attribute("synth:method", start ? "transfer" : "pyramid");
    spec.attribute("synth:seed", int(opt.seed));
    spec.attribute("synth:options", PyramidOptions::table().format(resolved));
    return true;
}

} // namespace

bool synthesize_from_statistics(OIIO::ImageBuf& dst, const TextureStatistics& stats,
    const PyramidOptions& opt, const OIIO::ImageBuf* start, std::vector<NamedImage>* subbands)
{
    return detail::guarded(dst, "synthesize_from_statistics",
        [&] { return synthesize(dst, stats, opt, start, subbands); });
}

bool pyramid_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    TextureStatistics stats;
    std::string error;
    if (subbands)
        subbands->clear();
    if (!analyze_texture(sample, opt, stats, error, nullptr, subbands)) {
        dst.errorfmt("{}", error);
        return false;
    }
    return synthesize_from_statistics(dst, stats, opt, nullptr, subbands);
}

OIIO::ImageBuf pyramid_synthesize(
    const OIIO::ImageBuf& sample, const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::value_form("pyramid_synthesize",
        [&](OIIO::ImageBuf& dst) { return pyramid_synthesize(dst, sample, opt, subbands); });
}

} // namespace texsyn
