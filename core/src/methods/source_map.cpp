// SPDX-License-Identifier: Apache-2.0
// apply_source_map: one synthesis drives every map of a material.
#include <texsyn/image.h>
#include <texsyn/source_map.h>

#include <cmath>
#include <cstdio>

#include <OpenImageIO/imagebufalgo.h>

#include "method_helpers_pvt.h"
#include "source_map_pvt.h"

namespace texsyn {

namespace {

bool apply(OIIO::ImageBuf& dst, const OIIO::ImageBuf& map, const OIIO::ImageBuf& image)
{
    if (map.has_error() || image.has_error()) {
        dst.errorfmt("{}", map.has_error() ? map.geterror() : image.geterror());
        return false;
    }
    const OIIO::ImageSpec& ms = map.spec();
    if (ms.nchannels != 2 || ms.depth > 1) {
        dst.errorfmt("the source map has {}; expected 2 (x, y) as --neighborhood:map=, "
                     "--choosy:map= and --patch:map= write",
            ms.depth > 1 ? "depth " + std::to_string(ms.depth)
                         : detail::count_text(ms.nchannels, "channel"));
        return false;
    }
    const OIIO::ImageSpec& is = image.spec();
    const int iw = is.width, ih = is.height;
    const std::string recorded = ms.get_string_attribute("synth:sample_size");
    if (!recorded.empty()) {
        int rw = 0, rh = 0;
        if (std::sscanf(recorded.c_str(), "%dx%d", &rw, &rh) != 2 || rw < 1 || rh < 1) {
            dst.errorfmt("the source map's synth:sample_size '{}' is not WxH", recorded);
            return false;
        }
        if (rw != iw || rh != ih) {
            dst.errorfmt("the image is {}x{} but the source map was made from a {}x{} sample "
                         "(the image must be aligned with the sample)",
                iw, ih, rw, rh);
            return false;
        }
    }
    const int w = ms.width, h = ms.height;
    std::vector<float> coords(size_t(w) * size_t(h) * 2);
    if (!map.get_pixels(OIIO::ROI(ms.x, ms.x + w, ms.y, ms.y + h, 0, 1, 0, 2), OIIO::TypeFloat,
            coords.data())) {
        dst.errorfmt("source map: {}", map.geterror());
        return false;
    }
    for (size_t i = 0; i < coords.size(); i += 2) {
        const float x = coords[i], y = coords[i + 1];
        if (!(x >= 0.0f && x < float(iw) && y >= 0.0f && y < float(ih)) || x != std::floor(x)
            || y != std::floor(y)) {
            const size_t p = i / 2;
            dst.errorfmt("the source map's pixel ({}, {}) holds ({}, {}): not an integer "
                         "position inside the {}x{} image",
                p % size_t(w), p / size_t(w), x, y, iw, ih);
            return false;
        }
    }
    const int nc = is.nchannels;
    std::vector<float> pixels(size_t(iw) * size_t(ih) * size_t(nc));
    if (!image.get_pixels(OIIO::ROI(is.x, is.x + iw, is.y, is.y + ih, 0, 1, 0, nc), OIIO::TypeFloat,
            pixels.data())) {
        dst.errorfmt("{}", image.geterror());
        return false;
    }
    OIIO::ImageSpec spec(w, h, nc, OIIO::TypeFloat);
    spec.channelnames = is.channelnames;
    spec.alpha_channel = is.alpha_channel;
    spec.z_channel = is.z_channel;
    for (const OIIO::ParamValue& p : is.extra_attribs)
        if (p.name() == "oiio:UnassociatedAlpha" || p.name() == "oiio:ColorSpace")
            spec.attribute(p.name(), p.type(), p.data());
    for (const OIIO::ParamValue& p : ms.extra_attribs)
        if (OIIO::Strutil::starts_with(p.name(), "synth:") && p.name() != "synth:sample_size")
            spec.attribute(p.name(), p.type(), p.data());
    dst.reset(spec);
    std::vector<float> out(size_t(w) * size_t(h) * size_t(nc));
    for (size_t p = 0; p < size_t(w) * size_t(h); ++p) {
        const size_t from = size_t(coords[2 * p + 1]) * size_t(iw) + size_t(coords[2 * p]);
        std::copy_n(pixels.data() + from * size_t(nc), nc, out.data() + p * size_t(nc));
    }
    dst.set_pixels(OIIO::ROI(0, w, 0, h, 0, 1, 0, nc), OIIO::TypeFloat, out.data());
    return true;
}

} // namespace

namespace detail {

void write_source_map(OIIO::ImageBuf& map, const std::vector<uint32_t>& source, int width,
    int height, int source_width, int sample_width, int sample_height)
{
    PlanarImage m;
    m.channels = { Plane(width, height), Plane(width, height) };
    m.channel_names = { "x", "y" };
    for (size_t i = 0; i < source.size(); ++i) {
        m.channels[0].data()[i] = float(source[i] % uint32_t(source_width));
        m.channels[1].data()[i] = float(source[i] / uint32_t(source_width));
    }
    imagebuf_from_planes(m, map, false);
    map.specmod().erase_attribute("oiio:UnassociatedAlpha");
    map.specmod().attribute(
        "synth:sample_size", std::to_string(sample_width) + "x" + std::to_string(sample_height));
}

} // namespace detail

bool apply_source_map(OIIO::ImageBuf& dst, const OIIO::ImageBuf& map, const OIIO::ImageBuf& image)
{
    return detail::guarded(dst, "apply_source_map", [&] { return apply(dst, map, image); });
}

OIIO::ImageBuf apply_source_map(const OIIO::ImageBuf& map, const OIIO::ImageBuf& image)
{
    return detail::value_form(
        "apply_source_map", [&](OIIO::ImageBuf& dst) { return apply_source_map(dst, map, image); });
}

} // namespace texsyn
