// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen 1995 §5 texture mixtures: one TextureStatistics made from several
// samples, which synthesize_from_statistics then imposes like a single sample's.
#include <texsyn/mix.h>

#include "pyramid_synthesis/pyramid_synthesis_pvt.h"

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

// "3 channels (R,G,B)" or "4 channels (R,G,B,A)".
std::string channel_text(const std::vector<std::string>& names)
{
    std::string s;
    for (const std::string& name : names)
        s += (s.empty() ? "" : ",") + name;
    return detail::count_text(int(names.size()), "channel") + " (" + s + ")";
}

// Reads every image sample (finite pixels; an analysis keeps an empty PlanarImage) and
// checks that every sample has sample 0's channels. With flatten=1 the planes are
// flattened as analyze_texture will flatten them, so that a colour basis fitted to them
// fits what is analysed.
bool read_samples(const std::vector<MixSample>& samples, const MixOptions& opt,
    std::vector<PlanarImage>& planes, std::string& error)
{
    planes.resize(samples.size());
    std::vector<std::vector<std::string>> names(samples.size());
    std::vector<int> alpha(samples.size());
    for (size_t k = 0; k < samples.size(); ++k) {
        const MixSample& s = samples[k];
        if (!s.image == !s.analysis) {
            error = sample_name(k) + " is missing (give an image or an analysis)";
            return false;
        }
        if (s.analysis) {
            names[k] = s.analysis->channel_names;
            alpha[k] = s.analysis->alpha_channel;
        } else {
            if (!planes_from_imagebuf(*s.image, planes[k], error)) {
                error = sample_name(k) + ": " + error;
                return false;
            }
            if (opt.synthesis.flatten)
                flatten_illumination(planes[k], opt.synthesis.nthreads);
            names[k] = planes[k].channel_names;
            alpha[k] = planes[k].alpha_channel;
        }
        if (names[k].size() != names[0].size() || alpha[k] != alpha[0]) {
            error = sample_name(k) + " has " + channel_text(names[k]) + ", " + sample_name(0) + " "
                + channel_text(names[0]) + ": the samples of a mix need the same channels";
            return false;
        }
    }
    return true;
}

// The analyses among the samples fix the pyramid: they must agree with each other and
// with the options (and be unflattened if flatten=1 would flatten the images), and the
// weights mode, which fits one colour basis to every sample's pixels, cannot take them.
// `fixed` is the first analysis, or null.
bool check_analyses(const std::vector<MixSample>& samples, const MixOptions& opt,
    const TextureStatistics*& fixed, std::string& error)
{
    fixed = nullptr;
    for (size_t k = 0; k < samples.size(); ++k) {
        const TextureStatistics* a = samples[k].analysis;
        if (!a)
            continue;
        if (!opt.weights.empty()) {
            error = option_error("weights", format_number_list(opt.weights),
                "averages the samples' colours in one basis, which needs their pixels, and "
                    + sample_name(k) + " is an analysis (give the image)");
            return false;
        }
        if (opt.synthesis.flatten) {
            error = detail::flatten_of_analysis_error(sample_name(k));
            return false;
        }
        if (!detail::check_against_analysis(*a, opt.synthesis, error)) {
            error = sample_name(k) + ": " + error;
            return false;
        }
        if (fixed && a->scales != fixed->scales) {
            error = sample_name(k) + " is an analysis with " + std::to_string(a->scales)
                + " scales and another sample one with " + std::to_string(fixed->scales)
                + ": the samples of a mix share one pyramid";
            return false;
        }
        if (!fixed)
            fixed = a;
    }
    return true;
}

// One number of scales for every sample: an analysis's, opt's, or the most every image
// sample and the output allow (as analyze_texture chooses for one sample).
bool common_scales(const std::vector<MixSample>& samples, const std::vector<PlanarImage>& planes,
    const MixOptions& opt, const TextureStatistics* fixed, int& scales, std::string& error)
{
    const PyramidOptions& s = opt.synthesis;
    const MixSample& first = samples[0]; // its size is the default output size
    const int w = s.width ? s.width
        : first.analysis  ? first.analysis->sample_width
                          : first.image->spec().width;
    const int h = s.height ? s.height
        : first.analysis   ? first.analysis->sample_height
                           : first.image->spec().height;
    const int wanted = fixed ? fixed->scales : s.scales;
    int most = max_pyramid_scales(w, h);
    for (size_t k = 0; k < planes.size(); ++k) {
        if (samples[k].analysis)
            continue;
        const int sw = planes[k].width(), sh = planes[k].height();
        const int allowed = max_pyramid_scales(sw, sh);
        if (allowed < 1) {
            error = sample_name(k) + " is " + size_text(sw, sh)
                + ": the pyramid method needs at least 16x16";
            return false;
        }
        if (wanted > allowed) {
            error = "scales=" + std::to_string(wanted) + " is too many for " + sample_name(k) + " ("
                + size_text(sw, sh) + ", at most " + std::to_string(allowed) + ")";
            return false;
        }
        most = std::min(most, allowed);
    }
    scales = wanted ? wanted : std::max(1, most);
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

bool mix(const std::vector<MixSample>& samples, const MixOptions& opt, TextureStatistics& out,
    std::string& error)
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
    const TextureStatistics* fixed = nullptr;
    std::vector<PlanarImage> planes;
    int scales = 0;
    if (!check_analyses(samples, opt, fixed, error) || !read_samples(samples, opt, planes, error)
        || !common_scales(samples, planes, opt, fixed, scales, error))
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
    for (size_t k = 0; k < samples.size(); ++k) {
        if (samples[k].analysis) {
            stats[k] = *samples[k].analysis;
            continue;
        }
        if (!analyze_texture(
                *samples[k].image, popt, stats[k], error, opt.weights.empty() ? nullptr : &basis)) {
            error = sample_name(k) + ": " + error;
            return false;
        }
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

bool mix_statistics(const std::vector<MixSample>& samples, const MixOptions& opt,
    TextureStatistics& out, std::string& error)
{
    return detail::guarded(error, "mix_statistics", [&] { return mix(samples, opt, out, error); });
}

} // namespace texsyn
