// SPDX-License-Identifier: Apache-2.0
// make_tileable(): the fill of a band across an image's wrap-around seams, rolled to the
// middle; its options.
#include <texsyn/fill.h>

#include <algorithm>

#include <OpenImageIO/imagebufalgo.h>

#include "methods/common_options_pvt.h"
#include "methods/method_helpers_pvt.h"
#include "patch/patch_schedule_pvt.h"

namespace texsyn {

namespace {

// The fill's options but `context` (the band's context is the whole image) and `flatten`
// (make_tileable flattens the whole image).
const OptionTable<FillOptions>& band_fill_table()
{
    return declared_table<FillOptions>([](OptionTable<FillOptions>& t) {
        std::vector<std::string> names;
        for (const OptionField& f : FillOptions::table().fields())
            if (f.name != "context" && f.name != "flatten")
                names.push_back(f.name);
        t.subset(FillOptions::table(), names);
    });
}

// The mask's value `d` pixels inside the band's edge: ramps from 0 to 1 over `feather`
// pixels, so that the band blends into the kept pixels instead of meeting them at a
// straight cut.
float band_weight(int d, int feather)
{
    return d >= feather ? 1.0f : float(d + 1) / float(feather + 1);
}

// A one-channel w x h mask: above 0 on the columns (with `along_x`) and rows (with
// `along_y`) within band / 2 of the middle (where the seams lie once the image is rolled
// by half its size), 1 but for a ramp of `feather` pixels along the band's edges.
OIIO::ImageBuf band_mask(int w, int h, int band, int feather, bool along_x, bool along_y)
{
    OIIO::ImageBuf mask(OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::FLOAT));
    const int x0 = w / 2 - band / 2, y0 = h / 2 - band / 2;
    auto across = [&](bool on, int i, int i0) {
        return !on || i < i0 || i >= i0 + band
            ? 0.0f
            : band_weight(std::min(i - i0, i0 + band - 1 - i), feather);
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float m = std::max(across(along_x, x, x0), across(along_y, y, y0));
            mask.setpixel(x, y, &m);
        }
    return mask;
}

// The fraction of pixels where a and b differ in some channel.
double changed_fraction(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b)
{
    const OIIO::ImageBuf diff = OIIO::ImageBufAlgo::maxchan(OIIO::ImageBufAlgo::absdiff(a, b));
    size_t changed = 0;
    for (OIIO::ImageBuf::ConstIterator<float> it(diff); !it.done(); ++it)
        changed += it[0] > 0.0f;
    return double(changed) / double(a.spec().image_pixels());
}

bool tileable(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const TileableOptions& opt,
    TileableReport* report)
{
    std::string error;
    if (!opt.validate(error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    const int w = image.spec().width, h = image.spec().height, side = std::min(w, h);
    // 3/16 of the side: narrower bands leave courses of bricks and rows of tiles too little
    // room to change phase, and come out smudged.
    const int patch = opt.options.patch.empty() ? detail::automatic_patch_sizes(side).front()
                                                : opt.options.patch.front();
    const int band = opt.band > 0 ? opt.band : std::max(2 * patch, 3 * side / 16);
    if (opt.band == 0 && 3 * band > side) {
        dst.errorfmt("a {}x{} image is too small for a band two {}-pixel patches wide (at most "
                     "a third of its shorter side, {}): give a smaller patch= or band=",
            w, h, patch, side / 3);
        return false;
    }
    if (3 * band > side) {
        dst.errorfmt("{}",
            option_error("band", std::to_string(band),
                "too wide for a " + std::to_string(w) + "x" + std::to_string(h)
                    + " image (at most a third of its shorter side, " + std::to_string(side / 3)
                    + ")"));
        return false;
    }
    PlanarImage planes;
    if (!planes_from_imagebuf(image, planes, error, opt.options.nthreads)) {
        dst.errorfmt("{}", error);
        return false;
    }
    detail::throw_if_stopped(opt.options.stop);
    OIIO::ImageBuf flattened;
    if (opt.flatten) {
        flatten_illumination(planes, opt.options.nthreads);
        imagebuf_from_planes(planes, flattened, true, opt.options.nthreads);
        flattened.specmod().extra_attribs = image.spec().extra_attribs;
    }
    const OIIO::ImageBuf& source = opt.flatten ? flattened : image;
    detail::throw_if_stopped(opt.options.stop);
    const FeatureScale scale = estimate_feature_scale(planes, opt.options.nthreads);
    const bool along_x = opt.axis != TileAxes::Y, along_y = opt.axis != TileAxes::X;
    const int dx = along_x ? w / 2 : 0, dy = along_y ? h / 2 : 0;
    const OIIO::ImageBuf rolled = OIIO::ImageBufAlgo::circular_shift(source, dx, dy);
    detail::throw_if_stopped(opt.options.stop);
    OIIO::ImageBuf filled;
    if (!texture_fill(
            filled, rolled, band_mask(w, h, band, band / 4, along_x, along_y), opt.options)) {
        dst.errorfmt("{}", filled.geterror());
        return false;
    }
    if (!OIIO::ImageBufAlgo::circular_shift(dst, filled, (w - dx) % w, (h - dy) % h)) {
        dst.errorfmt("{}", dst.geterror());
        return false;
    }
    detail::tag_synthesis(
        dst.specmod(), "tileable", opt.options.seed, TileableOptions::table().format(opt));
    dst.specmod().attribute("wrapmodes",
        std::string(along_x ? "periodic" : "black") + "," + (along_y ? "periodic" : "black"));
    if (report) {
        report->band = band;
        report->changed_fraction = changed_fraction(dst, source);
        report->scale = scale;
        report->band_too_narrow = scale.size > 2.0 * band;
    }
    return true;
}

} // namespace

const OptionTable<TileableOptions>& TileableOptions::table()
{
    return declared_table<TileableOptions>([](OptionTable<TileableOptions>& t) {
        using O = TileableOptions;
        t.integer("band", &O::band, 0, 1 << 16,
            "width in pixels of the band across each wrap-around seam that is re-synthesized; "
            "0 = 3/16 of the image's shorter side (at least two of the largest patches)");
        t.choice("axis", &O::axis,
            { { "both", TileAxes::Both }, { "x", TileAxes::X }, { "y", TileAxes::Y } },
            "the axes the result tiles along: both, x (left and right edges meet: a strip "
            "that repeats sideways, as in a trim sheet) or y");
        detail::add_flatten(t,
            "first (a lit scan cannot tile: pixels outside the band are then the flattened "
            "image's)");
        t.include(&O::options, band_fill_table());
    });
}

bool TileableOptions::validate(std::string& error) const
{
    return table().check(*this, error) && options.validate(error);
}

bool make_tileable(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const TileableOptions& opt,
    TileableReport* report)
{
    return detail::guarded(dst, "make_tileable", [&] { return tileable(dst, image, opt, report); });
}

OIIO::ImageBuf make_tileable(
    const OIIO::ImageBuf& image, const TileableOptions& opt, TileableReport* report)
{
    return detail::value_form("make_tileable",
        [&](OIIO::ImageBuf& dst) { return make_tileable(dst, image, opt, report); });
}

} // namespace texsyn
