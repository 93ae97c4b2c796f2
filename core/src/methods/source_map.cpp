// SPDX-License-Identifier: Apache-2.0
// apply_source_map: one synthesis drives every map of a material.
#include <texsyn/image.h>
#include <texsyn/source_map.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include <OpenImageIO/imagebufalgo.h>

#include "method_helpers_pvt.h"
#include "source_map_pvt.h"

namespace texsyn {

namespace {

// Offset (x, y) inside a k x k block, turned by transform t (source_map.h's M_t, as
// variant_source turns a whole sample).
void turned_offset(int t, int k, int& x, int& y)
{
    const int u = t & 4 ? y : x, v = t & 4 ? x : y;
    x = t & 1 ? k - 1 - u : u;
    y = t & 2 ? k - 1 - v : v;
}

// A normal map's first two channels (encoded 0.5 + 0.5 n) turned by transform t: the copied
// surface's gradient g = M_t^T g_sample (mirror, then swap), with n.y = -g.y for OpenGL.
// Negation is 1 - e on encoded values, so values turn exactly.
void turn_normal(float* pixel, int t, NormalMap convention)
{
    float gx = pixel[0], gy = convention == NormalMap::OpenGL ? 1.0f - pixel[1] : pixel[1];
    if (t & 1)
        gx = 1.0f - gx;
    if (t & 2)
        gy = 1.0f - gy;
    if (t & 4)
        std::swap(gx, gy);
    pixel[0] = gx;
    pixel[1] = convention == NormalMap::OpenGL ? 1.0f - gy : gy;
}

// How the image relates to the sample the map was made from: the same size, k times it
// (up) or 1/k of it (down).
struct Scale {
    int k = 1;
    bool up = true;
};

bool image_scale(int iw, int ih, int rw, int rh, Scale& scale)
{
    if (iw % rw == 0 && ih % rh == 0 && iw / rw == ih / rh) {
        scale = { iw / rw, true };
        return true;
    }
    if (rw % iw == 0 && rh % ih == 0 && rw / iw == rh / ih) {
        scale = { rw / iw, false };
        return true;
    }
    return false;
}

bool apply(OIIO::ImageBuf& dst, const OIIO::ImageBuf& map, const OIIO::ImageBuf& image,
    const ApplyMapOptions& opt)
{
    if (map.has_error() || image.has_error()) {
        dst.errorfmt("{}", map.has_error() ? map.geterror() : image.geterror());
        return false;
    }
    const OIIO::ImageSpec& ms = map.spec();
    const bool turned = ms.nchannels == 3 && ms.channel_name(2) == "t";
    if ((ms.nchannels != 2 && !turned) || ms.depth > 1) {
        dst.errorfmt("the source map has {}; expected the channels x, y (and t) that "
                     "--neighborhood:map=, --choosy:map= and --patch:map= write",
            ms.depth > 1            ? "depth " + std::to_string(ms.depth)
                : ms.nchannels == 3 ? "the channels " + std::string(ms.channel_name(0)) + ", "
                    + std::string(ms.channel_name(1)) + ", " + std::string(ms.channel_name(2))
                                    : detail::count_text(ms.nchannels, "channel"));
        return false;
    }
    const OIIO::ImageSpec& is = image.spec();
    const int iw = is.width, ih = is.height, nc = is.nchannels;
    if (opt.normal != NormalMap::None && nc < 3) {
        dst.errorfmt("a normal map needs 3 channels (x, y, z); the image has {}", nc);
        return false;
    }
    int rw = iw, rh = ih; // the sample's size
    const std::string recorded = ms.get_string_attribute("synth:sample_size");
    if (!recorded.empty()
        && (std::sscanf(recorded.c_str(), "%dx%d", &rw, &rh) != 2 || rw < 1 || rh < 1)) {
        dst.errorfmt("the source map's synth:sample_size '{}' is not WxH", recorded);
        return false;
    }
    Scale scale;
    if (!image_scale(iw, ih, rw, rh, scale)) {
        dst.errorfmt("the image is {}x{} but the source map was made from a {}x{} sample (the "
                     "image must be aligned with the sample: its size, or a whole multiple or "
                     "fraction of it)",
            iw, ih, rw, rh);
        return false;
    }
    const int w = ms.width, h = ms.height, mc = ms.nchannels;
    std::vector<float> coords(size_t(w) * size_t(h) * size_t(mc));
    if (!map.get_pixels(OIIO::ROI(ms.x, ms.x + w, ms.y, ms.y + h, 0, 1, 0, mc), OIIO::TypeFloat,
            coords.data())) {
        dst.errorfmt("source map: {}", map.geterror());
        return false;
    }
    for (size_t i = 0; i < coords.size(); i += size_t(mc)) {
        const float x = coords[i], y = coords[i + 1], t = turned ? coords[i + 2] : 0.0f;
        if (!(x >= 0.0f && x < float(rw) && y >= 0.0f && y < float(rh)) || x != std::floor(x)
            || y != std::floor(y) || !(t >= 0.0f && t <= 7.0f) || t != std::floor(t)) {
            const size_t p = i / size_t(mc);
            dst.errorfmt("the source map's pixel ({}, {}) holds ({}, {}{}): not an integer "
                         "position inside the {}x{} sample{}",
                p % size_t(w), p / size_t(w), x, y, turned ? ", " + std::to_string(t) : "", rw, rh,
                turned ? " with a transform 0..7" : "");
            return false;
        }
    }
    std::vector<float> pixels(size_t(iw) * size_t(ih) * size_t(nc));
    if (!image.get_pixels(OIIO::ROI(is.x, is.x + iw, is.y, is.y + ih, 0, 1, 0, nc), OIIO::TypeFloat,
            pixels.data())) {
        dst.errorfmt("{}", image.geterror());
        return false;
    }
    const int k = scale.k;
    const int ow = scale.up ? w * k : (w + k - 1) / k, oh = scale.up ? h * k : (h + k - 1) / k;
    OIIO::ImageSpec spec(ow, oh, nc, OIIO::TypeFloat);
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
    std::vector<float> out(size_t(ow) * size_t(oh) * size_t(nc));
    for (int y = 0; y < oh; ++y)
        for (int x = 0; x < ow; ++x) {
            // The map's pixel this output pixel belongs to, and its offset in the k x k block.
            const int mx = scale.up ? x / k : x * k, my = scale.up ? y / k : y * k;
            const float* c = coords.data() + (size_t(my) * size_t(w) + size_t(mx)) * size_t(mc);
            const int t = turned ? int(c[2]) : 0;
            int ix = int(c[0]), iy = int(c[1]);
            if (scale.up) {
                int bx = x % k, by = y % k;
                turned_offset(t, k, bx, by);
                ix = ix * k + bx;
                iy = iy * k + by;
            } else {
                ix /= k;
                iy /= k;
            }
            float* o = out.data() + (size_t(y) * size_t(ow) + size_t(x)) * size_t(nc);
            std::copy_n(pixels.data() + (size_t(iy) * size_t(iw) + size_t(ix)) * size_t(nc), nc, o);
            if (opt.normal != NormalMap::None && t != 0)
                turn_normal(o, t, opt.normal);
        }
    dst.set_pixels(OIIO::ROI(0, ow, 0, oh, 0, 1, 0, nc), OIIO::TypeFloat, out.data());
    return true;
}

} // namespace

namespace detail {

void write_source_map(OIIO::ImageBuf& map, const std::vector<uint32_t>& source, int width,
    int height, int source_width, int sample_width, int sample_height,
    const std::vector<uint8_t>* transforms)
{
    PlanarImage m;
    m.channels = { Plane(width, height), Plane(width, height) };
    m.channel_names = { "x", "y" };
    for (size_t i = 0; i < source.size(); ++i) {
        m.channels[0].data()[i] = float(source[i] % uint32_t(source_width));
        m.channels[1].data()[i] = float(source[i] / uint32_t(source_width));
    }
    if (transforms) {
        m.channels.emplace_back(width, height);
        m.channel_names.push_back("t");
        std::transform(transforms->begin(), transforms->end(), m.channels[2].data(),
            [](uint8_t t) { return float(t); });
    }
    imagebuf_from_planes(m, map, false);
    map.specmod().erase_attribute("oiio:UnassociatedAlpha");
    map.specmod().attribute(
        "synth:sample_size", std::to_string(sample_width) + "x" + std::to_string(sample_height));
}

} // namespace detail

bool apply_source_map(OIIO::ImageBuf& dst, const OIIO::ImageBuf& map, const OIIO::ImageBuf& image,
    const ApplyMapOptions& opt)
{
    return detail::guarded(dst, "apply_source_map", [&] { return apply(dst, map, image, opt); });
}

OIIO::ImageBuf apply_source_map(
    const OIIO::ImageBuf& map, const OIIO::ImageBuf& image, const ApplyMapOptions& opt)
{
    return detail::value_form("apply_source_map",
        [&](OIIO::ImageBuf& dst) { return apply_source_map(dst, map, image, opt); });
}

} // namespace texsyn
