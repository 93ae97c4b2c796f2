// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen 1995 §5 texture mixtures: one TextureStatistics made from several
// samples, which synthesize_from_statistics then imposes like a single sample's.
#include "synthesis_pvt.h"

#include <algorithm>
#include <numeric>

#include <texsyn/homogeneity.h>

namespace texsyn {

namespace {

std::string sample_name(size_t k)
{
    return "sample " + std::to_string(k);
}

std::string size_text(int w, int h)
{
    return std::to_string(w) + "x" + std::to_string(h);
}

std::string channel_list(const PlanarImage& p)
{
    std::string s;
    for (const std::string& name : p.channel_names)
        s += (s.empty() ? "" : ",") + name;
    return s;
}

// Reads every sample (finite pixels) and checks that it has sample 0's channels. With
// flatten=1 the planes are flattened as analyze_texture will flatten them, so that a
// colour basis fitted to them fits what is analysed.
bool read_samples(const std::vector<const OIIO::ImageBuf*>& samples, const MixOptions& opt,
    std::vector<PlanarImage>& planes, std::string& error)
{
    planes.resize(samples.size());
    for (size_t k = 0; k < samples.size(); ++k) {
        if (!samples[k]) {
            error = sample_name(k) + " is missing (null)";
            return false;
        }
        if (!planes_from_imagebuf(*samples[k], planes[k], error)) {
            error = sample_name(k) + ": " + error;
            return false;
        }
        if (opt.synthesis.flatten)
            flatten_illumination(planes[k], opt.synthesis.nthreads);
        const PlanarImage &a = planes[k], &b = planes[0];
        if (a.nchannels() != b.nchannels() || a.alpha_channel != b.alpha_channel) {
            error = sample_name(k) + " has " + detail::count_text(a.nchannels(), "channel") + " ("
                + channel_list(a) + "), " + sample_name(0) + " " + std::to_string(b.nchannels())
                + " (" + channel_list(b) + "): the samples of a mix need the same channels";
            return false;
        }
    }
    return true;
}

// One number of scales for every sample: opt's, or the most every sample and the output
// allow (as analyze_texture chooses for one sample).
bool common_scales(
    const std::vector<PlanarImage>& planes, const MixOptions& opt, int& scales, std::string& error)
{
    const PyramidOptions& s = opt.synthesis;
    const int w = s.width ? s.width : planes[0].width();
    const int h = s.height ? s.height : planes[0].height();
    int most = max_pyramid_scales(w, h);
    for (size_t k = 0; k < planes.size(); ++k) {
        const int sw = planes[k].width(), sh = planes[k].height();
        const int allowed = max_pyramid_scales(sw, sh);
        if (allowed < 1) {
            error = sample_name(k) + " is " + size_text(sw, sh)
                + ": the pyramid method needs at least 16x16";
            return false;
        }
        if (s.scales > allowed) {
            error = "scales=" + std::to_string(s.scales) + " is too many for " + sample_name(k)
                + " (" + size_text(sw, sh) + ", at most " + std::to_string(allowed) + ")";
            return false;
        }
        most = std::min(most, allowed);
    }
    scales = s.scales ? s.scales : std::max(1, most);
    return true;
}

// weights: the colour basis every sample is analysed in, the PCA of the weighted mixture
// of the samples' colour distributions.
ColorTransform mixture_basis(const std::vector<PlanarImage>& planes, const MixOptions& opt)
{
    std::vector<ColorMoments> moments;
    for (const PlanarImage& p : planes)
        moments.push_back(color_moments(p, p.ncolor()));
    return color_transform_from_moments(
        mixture_moments(moments, std::vector<double>(opt.weights.begin(), opt.weights.end())));
}

// palette/pattern and split: everything from the palette sample, but each band of each
// component from the sample the mode names for it (the palette's own where that sample
// has no variance in the component: no pattern to take).
void take_bands(const std::vector<TextureStatistics>& stats, const MixOptions& opt, int palette,
    TextureStatistics& out)
{
    out = stats[size_t(palette)];
    const int nbands = int(out.band_names.size());
    for (size_t c = 0; c < out.components.size(); ++c) {
        ComponentStatistics& comp = out.components[c];
        if (comp.constant)
            continue;
        for (int b = 0; b < nbands; ++b) {
            int from = opt.pattern ? *opt.pattern : 0;
            if (opt.split) {
                const int scale
                    = detail::band_position(out.pyramid, out.orientations, b, nbands).scale;
                from = scale >= *opt.split ? 0 : 1;
            }
            const ComponentStatistics& src = stats[size_t(from)].components[c];
            if (!src.constant)
                comp.bands[size_t(b)] = src.bands[size_t(b)];
        }
    }
}

// The tables of a constant component, as one-value distributions: the pixels and the
// low-pass are its mean, the band-pass bands 0.
std::vector<QuantileTable> constant_tables(const ComponentStatistics& comp, int nbands)
{
    std::vector<QuantileTable> t;
    const float zero = 0.0f;
    t.emplace_back(&comp.mean, 1);
    for (int b = 0; b + 1 < nbands; ++b)
        t.emplace_back(&zero, 1);
    t.emplace_back(&comp.mean, 1);
    return t;
}

// weights: every table is the barycentre of the samples' tables.
void average_tables(
    const std::vector<TextureStatistics>& stats, const MixOptions& opt, TextureStatistics& out)
{
    std::vector<double> w(opt.weights.begin(), opt.weights.end());
    const double total = std::accumulate(w.begin(), w.end(), 0.0);
    for (double& x : w)
        x /= total;
    out = stats[0];
    const int nbands = int(out.band_names.size());
    auto barycenter = [&](auto&& table_of) {
        std::vector<const QuantileTable*> tables;
        for (size_t k = 0; k < stats.size(); ++k)
            tables.push_back(&table_of(k));
        return wasserstein_barycenter(tables, w);
    };
    for (size_t c = 0; c < out.channels.size(); ++c)
        out.channels[c]
            = barycenter([&](size_t k) -> const QuantileTable& { return stats[k].channels[c]; });
    for (size_t c = 0; c < out.components.size(); ++c) {
        ComponentStatistics& comp = out.components[c];
        comp.constant = true;
        double mean = 0.0;
        std::vector<std::vector<QuantileTable>> flat(stats.size());
        for (size_t k = 0; k < stats.size(); ++k) {
            const ComponentStatistics& src = stats[k].components[c];
            mean += w[k] * double(src.mean);
            if (src.constant)
                flat[k] = constant_tables(src, nbands);
            else if (w[k] > 0.0)
                comp.constant = false;
        }
        comp.mean = float(mean);
        if (comp.constant) {
            comp.pixels = {};
            comp.bands.clear();
            continue;
        }
        // Table t of sample k: 0 = pixels, 1 + b = band b.
        auto table = [&](size_t k, int t) -> const QuantileTable& {
            const ComponentStatistics& src = stats[k].components[c];
            if (src.constant)
                return flat[k][size_t(t)];
            return t == 0 ? src.pixels : src.bands[size_t(t - 1)];
        };
        comp.pixels = barycenter([&](size_t k) -> const QuantileTable& { return table(k, 0); });
        comp.bands.resize(size_t(nbands));
        for (int b = 0; b < nbands; ++b)
            comp.bands[size_t(b)]
                = barycenter([&](size_t k) -> const QuantileTable& { return table(k, 1 + b); });
    }
}

bool mix(const std::vector<const OIIO::ImageBuf*>& samples, const MixOptions& opt,
    TextureStatistics& out, std::string& error)
{
    if (!opt.validate(error))
        return false;
    if (int(samples.size()) != opt.nsamples()) {
        error = "the mix takes " + std::to_string(opt.nsamples()) + " samples ("
            + (opt.weights.empty() ? std::string("palette=, pattern= and split= mix two")
                                   : "one per weight")
            + "), got " + std::to_string(samples.size());
        return false;
    }
    std::vector<PlanarImage> planes;
    int scales = 0;
    if (!read_samples(samples, opt, planes, error) || !common_scales(planes, opt, scales, error))
        return false;
    if (opt.split && !detail::check_split(*opt.split, scales, error))
        return false;

    PyramidOptions popt = opt.synthesis;
    popt.scales = scales;
    // weights: one basis for all, so that averaged tables are in the same units. Otherwise
    // each sample in its own basis: unit-variance components, paired by rank (pc0 with
    // pc0, …), so one sample's bands and another's pixel histograms agree in scale.
    ColorTransform basis;
    if (!opt.weights.empty())
        basis = mixture_basis(planes, opt);
    planes.clear();
    std::vector<TextureStatistics> stats(samples.size());
    for (size_t k = 0; k < samples.size(); ++k)
        if (!analyze_texture(
                *samples[k], popt, stats[k], error, opt.weights.empty() ? nullptr : &basis)) {
            error = sample_name(k) + ": " + error;
            return false;
        }

    TextureStatistics result;
    if (opt.weights.empty())
        take_bands(stats, opt, opt.palette.value_or(0), result);
    else
        average_tables(stats, opt, result);
    result.sample_width = stats[0].sample_width;
    result.sample_height = stats[0].sample_height;
    out = std::move(result);
    return true;
}

} // namespace

bool mix_statistics(const std::vector<const OIIO::ImageBuf*>& samples, const MixOptions& opt,
    TextureStatistics& out, std::string& error)
{
    return detail::guarded(error, "mix_statistics", [&] { return mix(samples, opt, out, error); });
}

} // namespace texsyn
