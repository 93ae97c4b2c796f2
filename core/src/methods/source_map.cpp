// SPDX-License-Identifier: Apache-2.0
// apply_source_map: one synthesis drives every map of a material.
#include <texsyn/image.h>
#include <texsyn/methods.h>
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

// `image` resampled as a scale= synthesis resampled its sample (scale_sample), a normal
// map's vectors made unit again; into `out`. False with a message.
bool rescaled(const OIIO::ImageBuf& image, float k, const ApplyMapOptions& opt, OIIO::ImageBuf& out,
    std::string& error)
{
    PlanarImage planes;
    if (!planes_from_imagebuf(image, planes, error))
        return false;
    detail::scale_sample(planes, k, 0);
    if (opt.normal != NormalMap::None && planes.nchannels() >= 3)
        for (size_t i = 0; i < planes.channels[0].size(); ++i) {
            double n[3], len = 0.0;
            for (int c = 0; c < 3; ++c) {
                n[c] = 2.0 * planes.channels[size_t(c)].data()[i] - 1.0;
                len += n[c] * n[c];
            }
            len = std::sqrt(len);
            for (int c = 0; c < 3 && len > 0.0; ++c)
                planes.channels[size_t(c)].data()[i] = float(0.5 + 0.5 * n[c] / len);
        }
    imagebuf_from_planes(planes, out, false);
    for (const OIIO::ParamValue& p : image.spec().extra_attribs)
        if (p.name() == "oiio:UnassociatedAlpha" || p.name() == "oiio:ColorSpace")
            out.specmod().attribute(p.name(), p.type(), p.data());
    return true;
}

bool apply(OIIO::ImageBuf& dst, const OIIO::ImageBuf& map, const OIIO::ImageBuf& given,
    const ApplyMapOptions& opt)
{
    const OIIO::ImageBuf* source = &given;
    OIIO::ImageBuf resampled;
    if (map.has_error() || given.has_error()) {
        dst.errorfmt("{}", map.has_error() ? map.geterror() : given.geterror());
        return false;
    }
    const OIIO::ImageSpec& ms = map.spec();
    // x, y, then t (a turned copy) and m (a fill's mask) if present, in that order.
    const bool turned = ms.nchannels >= 3 && ms.channel_name(2) == "t";
    const int blend_channel
        = ms.nchannels == 3 + int(turned) && ms.channel_name(2 + int(turned)) == "m"
        ? 2 + int(turned)
        : -1;
    if (ms.nchannels != 2 + int(turned) + int(blend_channel >= 0) || ms.depth > 1) {
        dst.errorfmt("the source map has {}; expected the channels x, y (and t, m) that {} write",
            ms.depth > 1            ? "depth " + std::to_string(ms.depth)
                : ms.nchannels == 3 ? "the channels " + std::string(ms.channel_name(0)) + ", "
                    + std::string(ms.channel_name(1)) + ", " + std::string(ms.channel_name(2))
                                    : detail::count_text(ms.nchannels, "channel"),
            command_list(&Method::copies_pixels, ":map="));
        return false;
    }
    // A map of a scale= synthesis: an image of the sample's own size is resampled as the
    // synthesis resampled its sample.
    const float sample_scale = ms.get_float_attribute("synth:sample_scale", 1.0f);
    if (sample_scale != 1.0f) {
        int rw0 = 0, rh0 = 0;
        std::sscanf(ms.get_string_attribute("synth:sample_size").c_str(), "%dx%d", &rw0, &rh0);
        const int gw = given.spec().width, gh = given.spec().height;
        if (std::lround(gw * double(sample_scale)) == rw0
            && std::lround(gh * double(sample_scale)) == rh0) {
            std::string error;
            if (!rescaled(given, sample_scale, opt, resampled, error)) {
                dst.errorfmt("{}", error);
                return false;
            }
            source = &resampled;
        }
    }
    const OIIO::ImageBuf& image = *source;
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
        const float m = blend_channel >= 0 ? coords[i + size_t(blend_channel)] : 1.0f;
        if (!(m >= 0.0f && m <= 1.0f)) {
            const size_t p = i / size_t(mc);
            dst.errorfmt("the source map's pixel ({}, {}) holds the blend m = {}: not in 0..1",
                p % size_t(w), p / size_t(w), m);
            return false;
        }
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
            // A fill's blend: the copy over the image's own pixel (a fill's map is the
            // image's size, and the result is the image's).
            const float m = blend_channel >= 0 ? c[blend_channel] : 1.0f;
            if (m < 1.0f && x < iw && y < ih) {
                const float* own
                    = pixels.data() + (size_t(y) * size_t(iw) + size_t(x)) * size_t(nc);
                for (int ch = 0; ch < nc; ++ch)
                    o[ch] = (1.0f - m) * own[ch] + m * o[ch];
                if (opt.normal != NormalMap::None) { // a blend of unit vectors, made unit
                    double n[3], len = 0.0;
                    for (int i = 0; i < 3; ++i) {
                        n[i] = 2.0 * o[i] - 1.0;
                        len += n[i] * n[i];
                    }
                    len = std::sqrt(len);
                    if (len > 0.0)
                        for (int i = 0; i < 3; ++i)
                            o[i] = float(0.5 + 0.5 * n[i] / len);
                }
            }
        }
    dst.set_pixels(OIIO::ROI(0, ow, 0, oh, 0, 1, 0, nc), OIIO::TypeFloat, out.data());
    return true;
}

} // namespace

namespace detail {

void write_source_map(OIIO::ImageBuf& map, const std::vector<uint32_t>& source, int width,
    int height, int source_width, int sample_width, int sample_height,
    const std::vector<uint8_t>* transforms, const Plane* blend)
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
    if (blend) {
        m.channels.push_back(*blend);
        m.channel_names.push_back("m");
        for (size_t i = 0; i < m.channels.back().size(); ++i)
            m.channels.back().data()[i] = std::clamp(m.channels.back().data()[i], 0.0f, 1.0f);
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
