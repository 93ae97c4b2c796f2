// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen 1995 §3.3 match-texture, with §3.4 edge handling and §3.5 colour.
#include <texsyn/synthesis.h>

#include <algorithm>
#include <cstdio>
#include <new>

#include <unistd.h>

#include <OpenImageIO/parallel.h>

#include <texsyn/color.h>
#include <texsyn/random.h>

namespace texsyn {

namespace {

size_t physical_memory_bytes()
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && page > 0 ? size_t(pages) * size_t(page) : size_t(0);
}

std::string format_bytes(double bytes)
{
    const char* units[] = { "B", "KB", "MB", "GB", "TB", "PB", "EB" };
    int u = 0;
    while (bytes >= 1024.0 && u < 6) {
        bytes /= 1024.0;
        ++u;
    }
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.1f %s", bytes, units[u]);
    return buf;
}

// The statistics match-texture imposes on one channel: its pixel histogram and the
// histogram of every subband.
struct ChannelTarget {
    QuantileTable image;
    std::vector<QuantileTable> bands;
};

ChannelTarget analyse_channel(const Plane& sample, const Pyramid& analysis, PyramidKind kind,
    FftBackend fft, int nthreads, std::vector<Plane>& bands)
{
    ChannelTarget t;
    t.image = QuantileTable(sample);
    // §3.4: the sample is not periodic. The steerable pyramid is circular, so it analyses
    // the periodic component, whose spectrum has no edge-jump cross; the Laplacian
    // pyramid reflects at the edges instead (the analysis plan was made with Reflect).
    if (kind == PyramidKind::Steerable)
        analysis.build(periodic_component(sample, fft, nthreads), bands, nthreads);
    else
        analysis.build(sample, bands, nthreads);
    t.bands.resize(bands.size());
    OIIO::parallel_for_chunked(
        int64_t(0), int64_t(bands.size()), int64_t(1),
        [&](int64_t b, int64_t) { t.bands[size_t(b)] = QuantileTable(bands[size_t(b)]); },
        OIIO::paropt(nthreads, OIIO::paropt::SplitDir::Y, 1));
    return t;
}

Plane seeded_noise(int width, int height, uint64_t seed, uint64_t stream)
{
    Plane p(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            p(x, y) = random_uniform(seed, stream, uint64_t(y) * uint64_t(width) + uint64_t(x));
    return p;
}

Plane match_texture(const ChannelTarget& target, const Pyramid& synthesis, int iterations,
    HistogramMode mode, uint64_t seed, uint64_t stream, int nthreads, std::vector<Plane>& bands,
    const std::function<void(int)>& iteration_done)
{
    Plane image = seeded_noise(synthesis.width(), synthesis.height(), seed, stream);
    match_histogram(image, target.image, mode, nthreads);
    for (int it = 0; it < iterations; ++it) {
        // Bands are matched in parallel, each on one thread (see transform_bands).
        synthesis.transform_bands(
            image, bands,
            [&](int b, Plane& band) { match_histogram(band, target.bands[size_t(b)], mode, 1); },
            nthreads);
        match_histogram(image, target.image, mode, nthreads);
        iteration_done(it + 1);
    }
    return image;
}

bool is_constant(const Plane& p)
{
    auto [lo, hi] = std::minmax_element(p.data(), p.data() + p.size());
    return *lo == *hi;
}

float plane_mean(const Plane& p)
{
    double sum = 0.0;
    for (size_t i = 0; i < p.size(); ++i)
        sum += p.data()[i];
    return float(sum / double(p.size()));
}

std::unique_ptr<Pyramid> make_pyramid(const PyramidOptions& opt, int width, int height, int scales,
    Boundary boundary, std::string& error)
{
    if (opt.pyramid == PyramidKind::Laplacian)
        return make_laplacian_pyramid(width, height, scales, boundary);
    return make_steerable_pyramid(width, height, scales, opt.orientations, opt.fft, error);
}

// Collects band `b` of every channel into one NamedImage per band.
void append_subbands(const std::string& prefix, const Pyramid& pyr,
    const std::vector<std::vector<Plane>>& per_channel,
    const std::vector<std::string>& channel_names, std::vector<NamedImage>& out)
{
    for (int b = 0; b < pyr.nbands(); ++b) {
        NamedImage ni;
        ni.name = prefix + "." + pyr.band_names()[b];
        for (size_t c = 0; c < per_channel.size(); ++c) {
            ni.image.channels.push_back(per_channel[c][b]);
            ni.image.channel_names.push_back(channel_names[c]);
        }
        ni.image.alpha_channel = -1; // "A" is a band here: never multiplied into colour
        out.push_back(std::move(ni));
    }
}

bool synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const PyramidOptions& opt,
    std::vector<NamedImage>* subbands)
{
    std::string error;
    if (!opt.validate(error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    PlanarImage src;
    if (!planes_from_imagebuf(sample, src, error)) {
        dst.errorfmt("sample: {}", error);
        return false;
    }
    const int sw = src.width(), sh = src.height();
    const int w = opt.width ? opt.width : sw, h = opt.height ? opt.height : sh;
    const int max_scales = max_pyramid_scales(sw, sh);
    if (max_scales < 1) {
        dst.errorfmt("sample is {}x{}: the pyramid method needs at least 16x16", sw, sh);
        return false;
    }
    if (opt.scales > max_scales) {
        dst.errorfmt("scales={} is too many for a {}x{} sample (at most {})", opt.scales, sw, sh,
            max_scales);
        return false;
    }
    // By default the most the sample allows, and no more than keeps the output's coarsest
    // band at 8 pixels too (a small output cannot hold the sample's coarsest scales).
    const int scales
        = opt.scales ? opt.scales : std::max(1, std::min(max_scales, max_pyramid_scales(w, h)));
    if (std::min(w, h) < (1 << scales)) {
        dst.errorfmt("size={}x{} is too small for {} scales (each side at least {})", w, h, scales,
            1 << scales);
        return false;
    }
    const size_t need = pyramid_memory_estimate(w, h, src.nchannels(), opt);
    const size_t have = physical_memory_bytes();
    if (have && need > have) {
        dst.errorfmt("size={}x{} would need about {} of memory (this machine has {})", w, h,
            format_bytes(double(need)), format_bytes(double(have)));
        return false;
    }

    std::unique_ptr<Pyramid> analysis = make_pyramid(opt, sw, sh, scales, Boundary::Reflect, error);
    std::unique_ptr<Pyramid> synthesis = make_pyramid(opt, w, h, scales, Boundary::Circular, error);
    if (!analysis || !synthesis) {
        dst.errorfmt("{}", error);
        return false;
    }

    // §3.5: synthesize decorrelated colour components; alpha is its own channel.
    const PlanarImage original = src;
    const ColorTransform ct = fit_color_transform(src, src.ncolor());
    decorrelate(src, ct, opt.nthreads);

    PlanarImage out;
    out.channel_names = src.channel_names;
    out.alpha_channel = src.alpha_channel;
    std::vector<std::string> component_names;
    std::vector<std::vector<Plane>> sample_bands(src.nchannels()), synth_bands(src.nchannels());
    for (int c = 0; c < src.nchannels(); ++c) {
        const Plane& channel = src.channels[c];
        component_names.push_back(c < ct.n ? "pc" + std::to_string(c)
                : c == src.alpha_channel   ? std::string("A")
                                           : src.channel_names[size_t(c)]);
        ChannelTarget target = analyse_channel(
            channel, *analysis, opt.pyramid, opt.fft, opt.nthreads, sample_bands[c]);
        if (is_constant(channel) || (c < ct.n && ct.constant[c])) {
            // No variance to synthesize (a constant channel, or a colour direction the
            // sample does not use): keep the channel's mean, and its bands are zero.
            out.channels.emplace_back(w, h, plane_mean(channel));
            if (subbands)
                synthesis->build(out.channels.back(), synth_bands[c], opt.nthreads);
            continue;
        }
        auto iteration_done = [&](int it) {
            if (opt.progress)
                opt.progress(float(c * opt.iterations + it)
                    / float(std::max(1, src.nchannels() * opt.iterations)));
        };
        std::vector<Plane> work_bands; // freed after each channel: only one set is alive
        out.channels.push_back(match_texture(target, *synthesis, opt.iterations, opt.histogram,
            opt.seed, uint64_t(c), opt.nthreads, work_bands, iteration_done));
        if (subbands)
            synthesis->build(out.channels.back(), synth_bands[c], opt.nthreads);
    }
    if (subbands) {
        subbands->clear();
        append_subbands("sample", *analysis, sample_bands, component_names, *subbands);
        append_subbands("synth", *synthesis, synth_bands, component_names, *subbands);
    }
    sample_bands.clear();
    synth_bands.clear();

    // Back to the sample's channels, then one last match of each channel's histogram to the
    // sample's (in scene-linear), which recorrelation alone does not guarantee.
    recorrelate(out, ct, opt.nthreads);
    for (int c = 0; c < out.nchannels(); ++c)
        match_histogram(
            out.channels[c], QuantileTable(original.channels[c]), opt.histogram, opt.nthreads);

    // Same alpha convention as the sample: un-associated colour stays so (and survives
    // where alpha is 0), associated colour (OIIO's default) is re-associated.
    imagebuf_from_planes(out, dst, !sample.spec().get_int_attribute("oiio:UnassociatedAlpha", 0));
    PyramidOptions resolved = opt;
    resolved.width = w;
    resolved.height = h;
    resolved.scales = scales;
    OIIO::ImageSpec& spec = dst.specmod();
    spec.attribute("synth:version", version());
    spec.attribute("synth:method", "pyramid");
    spec.attribute("synth:seed", int(opt.seed));
    spec.attribute("synth:options", PyramidOptions::table().format(resolved));
    return true;
}

} // namespace

bool pyramid_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    try {
        return synthesize(dst, sample, opt, subbands);
    } catch (const std::bad_alloc&) {
        dst.errorfmt("pyramid_synthesize: out of memory");
    } catch (const std::exception& e) {
        dst.errorfmt("pyramid_synthesize: {}", e.what());
    }
    return false;
}

OIIO::ImageBuf pyramid_synthesize(
    const OIIO::ImageBuf& sample, const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    OIIO::ImageBuf result;
    if (!pyramid_synthesize(result, sample, opt, subbands) && !result.has_error())
        result.errorfmt("pyramid_synthesize() failed");
    return result;
}

} // namespace texsyn
