// SPDX-License-Identifier: Apache-2.0
// The multiscale cascade of iterated maps and convolutions (cascade.h).
#include <texsyn/cascade.h>

#include <algorithm>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/parallel.h>

#include <texsyn/pyramid.h>

#include "cascade_pvt.h"
#include "image/parallel_pvt.h"
#include "methods/method_helpers_pvt.h"

namespace texsyn {

namespace {

struct Size {
    int w = 0, h = 0;
};

// The finest lattice's size: the output's divided by the feature factor (cascade.h), which
// is at least 1/4 so that a tiny output with a reference never asks for a huge lattice.
Size lattice_size(const CascadeOptions& opt)
{
    const double relative
        = opt.reference ? double(std::min(opt.width, opt.height)) / double(opt.reference) : 1.0;
    const double factor = std::max(0.25, double(opt.scale) * relative);
    auto side = [factor](int n) { return std::max(1, int(std::lround(double(n) / factor))); };
    return { side(opt.width), side(opt.height) };
}

// Lattice sizes, coarsest first: the finest lattice halved (rounding up) levels-1-l times.
std::vector<Size> level_sizes(const CascadeOptions& opt)
{
    std::vector<Size> sizes(size_t(opt.levels));
    sizes.back() = lattice_size(opt);
    for (size_t l = sizes.size() - 1; l-- > 0;)
        sizes[l] = { (sizes[l + 1].w + 1) / 2, (sizes[l + 1].h + 1) / 2 };
    return sizes;
}

// `image` resampled to w x h (OIIO's default filter) as planes; false with a message.
bool planes_at(const OIIO::ImageBuf& image, Size s, PlanarImage& out, std::string& error)
{
    OIIO::ImageBuf resized = image;
    const OIIO::ImageSpec& spec = image.spec();
    if (spec.width != s.w || spec.height != s.h)
        resized = OIIO::ImageBufAlgo::resize(
            image, "", 0.0f, OIIO::ROI(0, s.w, 0, s.h, 0, 1, 0, spec.nchannels));
    return planes_from_imagebuf(resized, out, error);
}

// The initial lattices of level 0 from an input image, clamped to [0, 1].
std::vector<Plane> initial_lattices(const PlanarImage& image, CascadeTransfer transfer)
{
    std::vector<Plane> lattices;
    if (transfer == CascadeTransfer::Channels || image.channels.size() < 3) {
        lattices = transfer == CascadeTransfer::Channels ? image.channels
                                                         : std::vector<Plane> { image.channels[0] };
    } else {
        Plane y(image.width(), image.height());
        for (size_t i = 0; i < y.size(); ++i)
            y.data()[i] = 0.2126f * image.channels[0].data()[i]
                + 0.7152f * image.channels[1].data()[i] + 0.0722f * image.channels[2].data()[i];
        lattices.push_back(std::move(y));
    }
    for (Plane& p : lattices)
        for (size_t i = 0; i < p.size(); ++i)
            p.data()[i] = std::clamp(p.data()[i], 0.0f, 1.0f);
    return lattices;
}

// The ramp's colour at value v in [0, 1]: linear between evenly spaced stops.
void ramp_colour(const std::vector<float>& ramp, float v, float* rgb)
{
    const size_t stops = ramp.size() / 3;
    const float pos = std::clamp(v, 0.0f, 1.0f) * float(stops - 1);
    const size_t k = std::min(size_t(pos), stops - 2);
    const float t = pos - float(k);
    for (int c = 0; c < 3; ++c)
        rgb[c] = ramp[3 * k + size_t(c)]
            + t * (ramp[3 * (k + 1) + size_t(c)] - ramp[3 * k + size_t(c)]);
}

// The palette's pixels sorted by luminance (ties: pixel order), as RGB triples.
bool palette_by_luminance(const OIIO::ImageBuf& image, std::vector<float>& rgb, std::string& error)
{
    PlanarImage p;
    if (!planes_from_imagebuf(image, p, error))
        return false;
    const size_t n = p.channels[0].size();
    auto channel = [&](size_t c, size_t i) {
        return p.channels[std::min(c, p.channels.size() - 1)].data()[i];
    };
    std::vector<std::pair<float, size_t>> order(n);
    for (size_t i = 0; i < n; ++i)
        order[i]
            = { 0.2126f * channel(0, i) + 0.7152f * channel(1, i) + 0.0722f * channel(2, i), i };
    std::sort(order.begin(), order.end());
    rgb.resize(3 * n);
    for (size_t k = 0; k < n; ++k)
        for (size_t c = 0; c < 3; ++c)
            rgb[3 * k + c] = channel(c, order[k].second);
    return true;
}

// A one-channel control image at level size s, clamped to [0, 1] and mapped to
// lo + c (hi - lo).
bool control_at(const OIIO::ImageBuf& image, const char* what, Size s, float lo, float hi,
    Plane& out, std::string& error)
{
    PlanarImage control;
    if (!planes_at(image, s, control, error)) {
        error = std::string(what) + ": " + error;
        return false;
    }
    out = std::move(control.channels[0]);
    for (size_t i = 0; i < out.size(); ++i)
        out.data()[i] = lo + std::clamp(out.data()[i], 0.0f, 1.0f) * (hi - lo);
    return true;
}

// The fraction of the work done when `level` has run `iterations` iterations on each of
// `nlattices` lattices: iterations weighted by their level's area.
float work_done(const CascadeOptions& opt, const std::vector<Size>& sizes, int level,
    int iterations, size_t nlattices)
{
    double total = 0.0, done = 0.0;
    for (int l = 0; l < opt.levels; ++l) {
        const double work = double(at_level(opt.iterations, l, 1)) * double(nlattices)
            * double(sizes[size_t(l)].w) * double(sizes[size_t(l)].h);
        total += work;
        if (l < level)
            done += work;
    }
    done += double(iterations) * double(sizes[size_t(level)].w) * double(sizes[size_t(level)].h);
    return float(done / total);
}

bool synthesize(OIIO::ImageBuf& dst, const CascadeOptions& given, const OIIO::ImageBuf* initial,
    const OIIO::ImageBuf* dilation, const OIIO::ImageBuf* rotation, const OIIO::ImageBuf* palette)
{
    std::string error;
    if (!given.validate(error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    // 0x0: the initial image's size, or 512x512 for a generator.
    CascadeOptions opt = given;
    if (!opt.width) {
        opt.width = initial ? initial->spec().width : 512;
        opt.height = initial ? initial->spec().height : 512;
    }
    const std::vector<Size> sizes = level_sizes(opt);
    const size_t nlattices = initial && opt.transfer == CascadeTransfer::Channels
        ? size_t(initial->spec().nchannels)
        : 1;
    if (!opt.ramp.empty() && !palette && nlattices != 1) {
        dst.errorfmt("{}",
            option_error("ramp", format_number_list(opt.ramp),
                "colours one lattice; with transfer=channels there are "
                    + std::to_string(nlattices)));
        return false;
    }
    for (auto [image, what] : { std::pair { dilation, "dilation" }, { rotation, "rotation" } })
        if (image && image->spec().nchannels != 1) {
            dst.errorfmt(
                "the {} control image has {} channels; expected 1", what, image->spec().nchannels);
            return false;
        }
    if (palette && nlattices != 1) {
        dst.errorfmt(
            "a palette image colours one lattice; with transfer=channels there are {}", nlattices);
        return false;
    }
    // Checked before anything of the output's size is allocated, the input's resize to the
    // first level included (its float copy and its planes).
    const double per_pixel = 4.0 * (3.0 * double(nlattices) + 3.0 + (opt.ramp.empty() ? 0 : 3));
    const double input_bytes = initial
        ? 8.0 * double(initial->spec().nchannels) * double(sizes[0].w) * double(sizes[0].h)
        : 0.0;
    const Size lattice = sizes.back();
    const double pixels
        = std::max(double(lattice.w) * double(lattice.h), double(opt.width) * double(opt.height));
    if (!detail::check_memory(size_t(per_pixel * pixels + input_bytes),
            "size=" + std::to_string(opt.width) + "x" + std::to_string(opt.height), error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    PlanarImage input;
    if (initial && !planes_at(*initial, sizes[0], input, error)) {
        dst.errorfmt("initial image: {}", error);
        return false;
    }
    // A palette replaces the ramp (a preset's, say): value v takes its colour of rank v.
    std::vector<float> colours = opt.ramp;
    if (palette && !palette_by_luminance(*palette, colours, error)) {
        dst.errorfmt("palette: {}", error);
        return false;
    }

    std::vector<Plane> lattices;
    if (initial)
        lattices = initial_lattices(input, opt.transfer);
    else // (moved in: a braced list would copy the plane)
        lattices.push_back(detail::seeded_noise(sizes[0].w, sizes[0].h, opt.seed, 0, opt.nthreads));
    Plane scratch;
    for (int l = 0; l < opt.levels; ++l) {
        const Size s = sizes[size_t(l)];
        if (l > 0) {
            const float n = at_level(opt.noise, l, 0.0f);
            for (size_t c = 0; c < lattices.size(); ++c) {
                lattices[c] = expand_plane(lattices[c], s.w, s.h, Boundary::Circular, opt.nthreads);
                if (n > 0.0f) {
                    const Plane fresh = detail::seeded_noise(
                        s.w, s.h, opt.seed, uint64_t(l) * 1024 + c + 1, opt.nthreads);
                    for (size_t i = 0; i < fresh.size(); ++i)
                        lattices[c].data()[i]
                            = (1.0f - n) * lattices[c].data()[i] + n * fresh.data()[i];
                }
            }
        }
        Plane spread, angle;
        if ((dilation && !control_at(*dilation, "dilation", s, opt.dmin, opt.dmax, spread, error))
            || (rotation
                && !control_at(*rotation, "rotation", s, 0.0f, 6.28318531f, angle, error))) {
            dst.errorfmt("{}", error);
            return false;
        }
        const float r = at_level(opt.r, l, 0.0f);
        const CascadeMap map = at_level(opt.map, l, CascadeMap::Logistic);
        const detail::CascadeKernelWeights kernel = detail::cascade_kernel(opt, l);
        int lattices_done = 0; // at this level, for the progress
        for (Plane& a : lattices) {
            const int iterations = at_level(opt.iterations, l, 1);
            for (int it = 0; it < iterations; ++it) {
                detail::throw_if_stopped(opt.stop);
                if (dilation || rotation)
                    detail::convolve_warped(a, kernel, spread, angle, scratch, opt.nthreads);
                else
                    detail::convolve_circular(a, kernel, scratch, opt.nthreads);
                // N(A) is smooth at the lattice's scale, so it resamples cleanly; the last
                // map then draws its contours at the output's resolution.
                const bool last = l == opt.levels - 1 && it == iterations - 1;
                if (last && (s.w != opt.width || s.h != opt.height)) {
                    detail::throw_if_stopped(opt.stop);
                    scratch
                        = detail::resample_circular(scratch, opt.width, opt.height, opt.nthreads);
                }
                detail::apply_cascade_map(scratch, map, r, opt.curve, opt.nthreads);
                std::swap(a, scratch);
                detail::report_progress(opt.progress, opt.stop,
                    work_done(opt, sizes, l, lattices_done * iterations + it + 1, lattices.size()));
            }
            ++lattices_done;
        }
    }

    PlanarImage result;
    if (!colours.empty()) {
        result.channels.assign(3, Plane(opt.width, opt.height));
        result.channel_names = { "R", "G", "B" };
        const Plane& v = lattices[0];
        OIIO::parallel_for(
            0, opt.height,
            [&](int64_t y) {
                for (int x = 0; x < opt.width; ++x) {
                    float rgb[3];
                    ramp_colour(colours, v(x, int(y)), rgb);
                    for (int c = 0; c < 3; ++c)
                        result.channels[size_t(c)](x, int(y)) = rgb[c];
                }
            },
            detail::split_every_item(opt.nthreads));
    } else {
        result.channels = std::move(lattices);
        result.channel_names
            = nlattices == 1 ? std::vector<std::string> { "Y" } : input.channel_names;
        result.alpha_channel = nlattices == 1 ? -1 : input.alpha_channel;
    }
    imagebuf_from_planes(result, dst, false, opt.nthreads);
    dst.specmod().erase_attribute("oiio:UnassociatedAlpha");
    detail::tag_synthesis(dst.specmod(), "cascade", opt.seed, CascadeOptions::table().format(opt));
    return true;
}

} // namespace

bool cascade_synthesize(OIIO::ImageBuf& dst, const CascadeOptions& opt,
    const OIIO::ImageBuf* initial, const OIIO::ImageBuf* dilation, const OIIO::ImageBuf* rotation,
    const OIIO::ImageBuf* palette)
{
    return detail::guarded(dst, "cascade_synthesize",
        [&] { return synthesize(dst, opt, initial, dilation, rotation, palette); });
}

OIIO::ImageBuf cascade_synthesize(const CascadeOptions& opt, const OIIO::ImageBuf* initial,
    const OIIO::ImageBuf* dilation, const OIIO::ImageBuf* rotation, const OIIO::ImageBuf* palette)
{
    return detail::value_form("cascade_synthesize", [&](OIIO::ImageBuf& dst) {
        return cascade_synthesize(dst, opt, initial, dilation, rotation, palette);
    });
}

} // namespace texsyn
