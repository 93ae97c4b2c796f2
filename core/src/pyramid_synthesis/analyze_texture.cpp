// SPDX-License-Identifier: Apache-2.0
// The analysis half of Heeger & Bergen 1995: colour transform (§3.5) and the histograms
// of every component and of its subbands (§3.3), with §3.4's edge handling.
#include "pyramid_synthesis_pvt.h"

#include <algorithm>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include <texsyn/homogeneity.h>

namespace texsyn {

namespace {

// Fills the component's tables; `bands` receives its subbands.
void analyse_component(const Plane& component, const Pyramid& analysis, const PyramidOptions& opt,
    ComponentStatistics& stats, std::vector<Plane>& bands)
{
    // §3.4: the sample is not periodic. The steerable pyramid is circular, so it analyses
    // the periodic component, whose spectrum has no edge-jump cross; the Laplacian
    // pyramid reflects at the edges instead (the analysis plan was made with Reflect).
    if (opt.pyramid == PyramidKind::Steerable)
        analysis.build(periodic_component(component, opt.fft, opt.nthreads), bands, opt.nthreads);
    else
        analysis.build(component, bands, opt.nthreads);
    if (stats.constant)
        return;
    stats.pixels = QuantileTable(component);
    stats.bands.resize(bands.size());
    OIIO::parallel_for_chunked(
        int64_t(0), int64_t(bands.size()), int64_t(1),
        [&](int64_t b, int64_t) { stats.bands[size_t(b)] = QuantileTable(bands[size_t(b)]); },
        detail::split_every_item(opt.nthreads));
}

bool analyse(const OIIO::ImageBuf& sample, const PyramidOptions& opt, TextureStatistics& stats,
    std::string& error, const ColorTransform* basis, std::vector<NamedImage>* subbands)
{
    if (!opt.validate(error))
        return false;
    const OIIO::ImageSpec& spec = sample.spec();
    if (!detail::check_memory(
            pyramid_analysis_memory_estimate(spec.width, spec.height, spec.nchannels, opt),
            "the analysis of the " + std::to_string(spec.width) + "x" + std::to_string(spec.height)
                + " sample",
            error))
        return false;
    PlanarImage src;
    if (!planes_from_imagebuf(sample, src, error, opt.nthreads)) {
        error = "sample: " + error;
        return false;
    }
    if (opt.flatten) // §6: a lighting gradient in the sample makes the output blotchy
        flatten_illumination(src, opt.nthreads);
    const int sw = src.width(), sh = src.height();
    const int w = opt.width ? opt.width : sw, h = opt.height ? opt.height : sh;
    const int max_scales = max_pyramid_scales(sw, sh);
    if (max_scales < 1) {
        error = "sample is " + std::to_string(sw) + "x" + std::to_string(sh)
            + ": the pyramid method needs at least 16x16";
        return false;
    }
    if (opt.scales > max_scales) {
        error = "scales=" + std::to_string(opt.scales) + " is too many for a " + std::to_string(sw)
            + "x" + std::to_string(sh) + " sample (at most " + std::to_string(max_scales) + ")";
        return false;
    }
    if (basis && basis->n != src.ncolor()) {
        error = "the colour basis has " + std::to_string(basis->n) + " channels, the sample "
            + std::to_string(src.ncolor()) + " colour channels";
        return false;
    }
    // By default the most the sample allows, and no more than keeps the output's coarsest
    // band at 8 pixels too (a small output cannot hold the sample's coarsest scales).
    const int scales
        = opt.scales ? opt.scales : std::max(1, std::min(max_scales, max_pyramid_scales(w, h)));
    std::unique_ptr<Pyramid> analysis
        = detail::make_pyramid(opt, sw, sh, scales, Boundary::Reflect, error);
    if (!analysis)
        return false;

    TextureStatistics s;
    s.sample_width = sw;
    s.sample_height = sh;
    s.pyramid = opt.pyramid;
    s.scales = scales;
    s.orientations = opt.orientations;
    s.band_names = analysis->band_names();
    s.channel_names = src.channel_names;
    s.alpha_channel = src.alpha_channel;
    s.flattened = opt.flatten != 0;
    s.unassociated_alpha = sample.spec().get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
    for (const Plane& channel : src.channels)
        s.channels.emplace_back(channel);

    // §3.5: decorrelated colour components; alpha and extra channels are their own.
    s.color = basis ? *basis : fit_color_transform(src, src.ncolor());
    decorrelate(src, s.color, opt.nthreads);
    std::vector<std::vector<Plane>> sample_bands(size_t(src.nchannels()));
    for (int c = 0; c < src.nchannels(); ++c) {
        ComponentStatistics comp;
        comp.name = c < s.color.n    ? "pc" + std::to_string(c)
            : c == src.alpha_channel ? std::string("A")
                                     : src.channel_names[size_t(c)];
        const Plane& component = src.channels[size_t(c)];
        comp.mean = detail::plane_mean(component);
        // No variance to synthesize (a constant channel, or a colour direction the sample
        // does not use): the synthesis keeps the mean.
        comp.constant = detail::is_constant(component) || (c < s.color.n && s.color.constant[c]);
        analyse_component(component, *analysis, opt, comp, sample_bands[size_t(c)]);
        if (!subbands)
            sample_bands[size_t(c)].clear();
        s.components.push_back(std::move(comp));
    }
    if (subbands) {
        std::vector<std::string> names;
        for (const ComponentStatistics& comp : s.components)
            names.push_back(comp.name);
        detail::append_subbands("sample", s.band_names, sample_bands, names, *subbands);
    }
    stats = std::move(s);
    return true;
}

} // namespace

bool analyze_texture(const OIIO::ImageBuf& sample, const PyramidOptions& opt,
    TextureStatistics& stats, std::string& error, const ColorTransform* basis,
    std::vector<NamedImage>* subbands)
{
    return detail::guarded(error, "analyze_texture",
        [&] { return analyse(sample, opt, stats, error, basis, subbands); });
}

} // namespace texsyn
