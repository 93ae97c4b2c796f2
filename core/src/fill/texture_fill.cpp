// SPDX-License-Identifier: Apache-2.0
// texture_fill(): the checks, the mask's regions and their crops, and the final copy into
// the image.
#include <texsyn/fill.h>

#include <algorithm>
#include <cstdio>

#include <OpenImageIO/imagebufalgo.h>

#include <texsyn/feature_scale.h>
#include <texsyn/homogeneity.h>
#include <texsyn/pyramid.h>

#include "fill_pvt.h"
#include "methods/method_helpers_pvt.h"
#include "methods/source_map_pvt.h"
#include "patch/patch_schedule_pvt.h"

namespace texsyn {

namespace {

using detail::PixelBox;

// The widest fade-in at a soft plate's outline (a plate enlarged 16 times).
constexpr int kMaxRim = 16;

std::string layout_text(const PlanarImage& p)
{
    return std::to_string(p.width()) + "x" + std::to_string(p.height()) + " with "
        + detail::count_text(p.nchannels(), "channel");
}

// The planes of a one-channel control image of the image's size (`what`: "mask").
bool control_plane(
    const OIIO::ImageBuf& buf, const char* what, int w, int h, Plane& plane, std::string& error)
{
    PlanarImage p;
    if (!planes_from_imagebuf(buf, p, error)) {
        error = std::string(what) + ": " + error;
        return false;
    }
    if (p.nchannels() != 1 || p.width() != w || p.height() != h) {
        error = std::string("the ") + what + " is " + layout_text(p)
            + "; it must be one channel of the image's size (" + std::to_string(w) + "x"
            + std::to_string(h) + ")";
        return false;
    }
    // A mask blends (1 - m) x image + m x fill: outside 0..1 it would extrapolate.
    const float* values = p.channels[0].data();
    const float* end = values + p.channels[0].size();
    const float* outside = std::find_if(values, end, [](float v) { return v < 0.0f || v > 1.0f; });
    if (outside != end) {
        const size_t at = size_t(outside - values);
        char value[32];
        std::snprintf(value, sizeof(value), "%g", double(*outside));
        error = std::string("the ") + what + " has the value " + value + " at "
            + std::to_string(at % size_t(w)) + "," + std::to_string(at / size_t(w))
            + "; its values must be in 0..1";
        return false;
    }
    plane = std::move(p.channels[0]);
    return true;
}

// The crop of a region: its hole box grown by `margin`, inside the w x h image.
PixelBox crop_box(const PixelBox& hole, int margin, int w, int h)
{
    const PixelBox grown = hole.grown(margin);
    return { std::max(grown.x0, 0), std::max(grown.y0, 0), std::min(grown.x1, w),
        std::min(grown.y1, h) };
}

// A region to fill: its hole box, its crop and the crop's levels.
struct Region {
    PixelBox hole, crop;
    std::vector<detail::CropLevel> levels;
};

bool fill(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask,
    const FillOptions& given, const OIIO::ImageBuf* sample, const OIIO::ImageBuf* exclude,
    FillReport* report, OIIO::ImageBuf* source_map)
{
    std::string error;
    auto fail = [&](const std::string& message) {
        dst.errorfmt("{}", message);
        return false;
    };
    if (!given.validate(error))
        return fail(error);
    PlanarImage in;
    if (!planes_from_imagebuf(image, in, error, given.nthreads))
        return fail("image: " + error);
    if (given.flatten)
        flatten_illumination(in, given.nthreads);
    FillOptions opt = given;
    if (opt.patch.empty())
        opt.patch = detail::automatic_patch_sizes(std::min(in.width(), in.height()));
    detail::throw_if_stopped(opt.stop);
    const int w = in.width(), h = in.height();
    Plane mask_plane, exclude_plane;
    if (!control_plane(mask, "mask", w, h, mask_plane, error)
        || (exclude && !control_plane(*exclude, "exclude mask", w, h, exclude_plane, error)))
        return fail(error);
    if (sample && source_map)
        return fail("map= : a fill from sample= copies from two images; its source map is "
                    "written only for a fill from the image itself");
    PlanarImage from;
    if (sample) {
        if (!planes_from_imagebuf(*sample, from, error, opt.nthreads))
            return fail("sample: " + error);
        if (from.nchannels() != in.nchannels())
            return fail("the sample has " + detail::count_text(from.nchannels(), "channel")
                + " and the image " + detail::count_text(in.nchannels(), "channel")
                + "; they must match");
    }
    detail::throw_if_stopped(opt.stop);
    const std::vector<uint8_t> hole = detail::above_zero(mask_plane);
    const size_t filled = size_t(std::count(hole.begin(), hole.end(), uint8_t(1)));
    if (!sample && filled == hole.size())
        return fail("the mask covers the whole image: give a sample to fill it from");
    const std::vector<uint8_t> excluded
        = exclude ? detail::above_zero(exclude_plane) : std::vector<uint8_t>();

    // The regions and their crops, sized and checked before any work.
    std::vector<Region> regions;
    size_t work = 0;
    int most_levels = 0;
    for (const PixelBox& box : detail::hole_regions(hole, w, h, opt.patch.front())) {
        detail::throw_if_stopped(opt.stop);
        const int thickness = detail::hole_thickness(hole, w, box);
        int levels = detail::fill_levels(opt, thickness);
        Region r { box, crop_box(box, detail::fill_margin(opt, levels, thickness), w, h), {} };
        // The automatic choice, lowered until the coarsest crop holds two largest patches.
        while (opt.levels == 0 && levels > 1
            && std::min(r.crop.width(), r.crop.height()) >> (levels - 1) < 2 * opt.patch.front())
            --levels;
        work += size_t(r.crop.width()) * size_t(r.crop.height());
        most_levels = std::max(most_levels, levels);
        r.levels.resize(size_t(levels));
        regions.push_back(std::move(r));
    }
    // Measured peaks (RGB plates of 1K to 3K, one hole, 2026-12-06): about 230 bytes per
    // pixel of the crops worked on (their pyramids, guidance, search and vote state, the
    // outline's solve) and 64 per pixel of the image (the result, the source map, the
    // caller's converted and encoded copies), which scale with the channels.
    const double channels = double(in.nchannels());
    const double crop_bytes = 12.0 * (4.0 * channels + 8.0) * double(work);
    const double image_bytes = (20.0 * channels + 4.0) * double(w) * double(h);
    if (!detail::check_memory(
            size_t(std::min(crop_bytes + image_bytes, 1e18)), "the fill's crops and result", error))
        return fail(error);

    // The result starts as the image itself: pixels outside the mask stay bit-identical.
    if (!OIIO::ImageBufAlgo::copy(dst, image, OIIO::TypeDesc::FLOAT))
        return fail("image: " + dst.geterror());
    detail::throw_if_stopped(opt.stop);
    std::vector<std::vector<Plane>> pyramid;
    if (sample) {
        std::vector<Plane> planes = from.channels;
        if (opt.guidance > 0.0f)
            detail::add_guidance(
                planes, from.ncolor(), nullptr, opt.guidance, opt.nthreads, opt.stop);
        pyramid = gaussian_pyramid(planes, most_levels, Boundary::Reflect, opt.nthreads);
    }
    double total = 0.0, done = 0.0;
    for (Region& r : regions) {
        r.levels[0] = detail::crop_level(in.channels, hole, exclude ? &excluded : nullptr, r.crop);
        detail::throw_if_stopped(opt.stop);
        if (opt.guidance > 0.0f)
            detail::add_guidance(r.levels[0].planes, in.ncolor(), &r.levels[0].known, opt.guidance,
                opt.nthreads, opt.stop);
        for (size_t l = 1; l < r.levels.size(); ++l) {
            detail::throw_if_stopped(opt.stop);
            r.levels[l] = detail::reduce_crop(r.levels[l - 1], opt.nthreads);
        }
        // The automatic choice also keeps only levels with a whole patch of the image's own
        // pixels to copy (a wide band in a small image has none at its coarsest levels).
        while (opt.levels == 0 && !sample && r.levels.size() > 1
            && !detail::has_source_patch(r.levels.back(), opt.patch.front()))
            r.levels.pop_back();
        total += detail::fill_work(r.levels, opt);
    }
    const OIIO::ImageBuf& copied_from = sample ? *sample : image;
    const int nc = in.nchannels();
    // The source map: every pixel its own source until a region's copies say otherwise.
    std::vector<uint32_t> sources(size_t(w) * size_t(h));
    if (source_map)
        for (size_t i = 0; i < sources.size(); ++i)
            sources[i] = uint32_t(i);
    // The plate's finest detail sets how softly the copies fade in at the outline.
    const FeatureScale plate = estimate_feature_scale(in, opt.nthreads);
    const int rim = std::min(kMaxRim, int(plate.finest_size / 2.0));
    for (size_t k = 0; k < regions.size(); ++k) {
        Region& r = regions[k];
        std::vector<std::vector<Plane>> levels_of_sample;
        if (sample)
            levels_of_sample.assign(
                pyramid.begin(), pyramid.begin() + std::ptrdiff_t(r.levels.size()));
        detail::RegionFill result;
        if (!detail::fill_region(r.levels, levels_of_sample, opt, k, done, total, result, error))
            return fail(error);
        const int cw = r.crop.width();
        const int source_width = sample ? from.width() : cw;
        const int sw = copied_from.spec().width, sh = copied_from.spec().height;
        detail::RegionCopies copies;
        copies.crop = r.crop;
        copies.channels = nc;
        copies.kept = [&](int x, int y, float* out) {
            image.getpixel(x + image.xbegin(), y + image.ybegin(), out);
        };
        copies.copied = [&](size_t q, int dx, int dy, float* out) {
            const uint32_t s = result.copied[q];
            int sx = int(s % uint32_t(source_width)), sy = int(s / uint32_t(source_width));
            if (!sample) {
                sx += r.crop.x0;
                sy += r.crop.y0;
            }
            sx = std::clamp(sx + dx, 0, sw - 1);
            sy = std::clamp(sy + dy, 0, sh - 1);
            copied_from.getpixel(sx + copied_from.xbegin(), sy + copied_from.ybegin(), out);
        };
        if (source_map)
            for (int y = r.crop.y0; y < r.crop.y1; ++y)
                for (int x = r.crop.x0; x < r.crop.x1; ++x)
                    if (mask_plane(x, y) > 0.0f) {
                        const uint32_t s = result.copied[size_t(y - r.crop.y0) * size_t(cw)
                            + size_t(x - r.crop.x0)];
                        sources[size_t(y) * size_t(w) + size_t(x)]
                            = uint32_t(int(s / uint32_t(cw)) + r.crop.y0) * uint32_t(w)
                            + uint32_t(int(s % uint32_t(cw)) + r.crop.x0);
                    }
        detail::compose_region(
            copies, mask_plane, opt.outline, rim, opt.nthreads, [&](int x, int y, const float* v) {
                dst.setpixel(x + dst.xbegin(), y + dst.ybegin(), v);
            });
    }
    detail::report_progress(opt.progress, opt.stop, 1.0f);
    if (report) {
        report->holes = int(regions.size());
        report->filled = filled;
        report->levels = most_levels;
        report->work_pixels = work;
    }
    const std::string options = FillOptions::table().format(opt);
    detail::tag_synthesis(dst.specmod(), "fill", opt.seed, options);
    dst.specmod().erase_attribute("wrapmodes");
    if (source_map) {
        detail::write_source_map(*source_map, sources, w, h, w, w, h, nullptr, &mask_plane);
        detail::tag_synthesis(source_map->specmod(), "fill", opt.seed, options);
    }
    return true;
}

} // namespace

bool texture_fill(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask,
    const FillOptions& opt, const OIIO::ImageBuf* sample, const OIIO::ImageBuf* exclude,
    FillReport* report, OIIO::ImageBuf* source_map)
{
    return detail::guarded(dst, "texture_fill",
        [&] { return fill(dst, image, mask, opt, sample, exclude, report, source_map); });
}

OIIO::ImageBuf texture_fill(const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask,
    const FillOptions& opt, const OIIO::ImageBuf* sample, const OIIO::ImageBuf* exclude,
    FillReport* report, OIIO::ImageBuf* source_map)
{
    return detail::value_form("texture_fill", [&](OIIO::ImageBuf& dst) {
        return texture_fill(dst, image, mask, opt, sample, exclude, report, source_map);
    });
}

} // namespace texsyn
