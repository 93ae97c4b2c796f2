// SPDX-License-Identifier: Apache-2.0
// make_tileable(): the fill of a band across an image's wrap-around seams, rolled to the
// middle; its options.
#include <texsyn/fill.h>

#include <algorithm>

#include <OpenImageIO/imagebufalgo.h>

#include "methods/method_helpers_pvt.h"

namespace texsyn {

namespace {

// The fill's options but `context` (the band's context is the whole image).
const OptionTable<FillOptions>& band_fill_table()
{
    return declared_table<FillOptions>([](OptionTable<FillOptions>& t) {
        std::vector<std::string> names;
        for (const OptionField& f : FillOptions::table().fields())
            if (f.name != "context")
                names.push_back(f.name);
        t.subset(FillOptions::table(), names);
    });
}

// A one-channel w x h mask: 1 on the columns and rows within band / 2 of the middle (where
// the seams lie once the image is rolled by half its size).
OIIO::ImageBuf cross_mask(int w, int h, int band)
{
    OIIO::ImageBuf mask(OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::FLOAT));
    const float one = 1.0f;
    const int x0 = w / 2 - band / 2, y0 = h / 2 - band / 2;
    OIIO::ImageBufAlgo::fill(mask, &one, OIIO::ROI(x0, x0 + band, 0, h));
    OIIO::ImageBufAlgo::fill(mask, &one, OIIO::ROI(0, w, y0, y0 + band));
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
    const int patch = opt.options.patch.front();
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
    const OIIO::ImageBuf rolled = OIIO::ImageBufAlgo::circular_shift(image, w / 2, h / 2);
    detail::throw_if_stopped(opt.options.stop);
    OIIO::ImageBuf filled;
    if (!texture_fill(filled, rolled, cross_mask(w, h, band), opt.options)) {
        dst.errorfmt("{}", filled.geterror());
        return false;
    }
    if (!OIIO::ImageBufAlgo::circular_shift(dst, filled, w - w / 2, h - h / 2)) {
        dst.errorfmt("{}", dst.geterror());
        return false;
    }
    detail::tag_synthesis(
        dst.specmod(), "tileable", opt.options.seed, TileableOptions::table().format(opt));
    dst.specmod().attribute("wrapmodes", "periodic,periodic");
    if (report) {
        report->band = band;
        report->changed_fraction = changed_fraction(dst, image);
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
