// SPDX-License-Identifier: Apache-2.0
// Volumes as 3-D ImageBufs: what solid_synthesize returns and the OIIO plugin slices.
#include <texsyn/volume.h>

#include <climits>
#include <cmath>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/color.h>

namespace texsyn {

void imagebuf_from_volume(const PlanarVolume& v, OIIO::ImageBuf& dst)
{
    const int w = v.width(), h = v.height(), d = v.depth(), nc = v.nchannels();
    OIIO::ImageSpec spec(w, h, nc, OIIO::TypeFloat);
    spec.depth = spec.full_depth = d;
    spec.channelnames = v.channel_names;
    spec.alpha_channel = v.alpha_channel;
    spec.extra_attribs = v.attributes;
    spec.attribute("oiio:UnassociatedAlpha", 1);
    dst.reset(spec);
    float* out = static_cast<float*>(dst.localpixels());
    const size_t n = size_t(w) * size_t(h) * size_t(d);
    for (int c = 0; c < nc; ++c) {
        const float* in = v.channels[size_t(c)].data();
        for (size_t i = 0; i < n; ++i)
            out[i * size_t(nc) + size_t(c)] = in[i];
    }
}

bool volume_from_imagebuf(const OIIO::ImageBuf& src, PlanarVolume& dst, std::string& error)
{
    if (src.has_error()) {
        error = src.geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = src.spec();
    const int w = spec.width, h = spec.height, d = std::max(1, spec.depth), nc = spec.nchannels;
    if (w < 1 || h < 1 || nc < 1) {
        error = "the volume is empty";
        return false;
    }
    if (int64_t(h) * int64_t(d) > INT_MAX) {
        error = "the volume is too large (height x depth must be under 2^31)";
        return false;
    }
    const size_t n = size_t(w) * size_t(h) * size_t(d);
    // A local float buffer (what solid_synthesize makes) is read in place; anything else
    // through a float copy.
    std::vector<float> copy;
    const float* voxels = spec.format == OIIO::TypeFloat && src.localpixels()
            && src.pixel_stride() == OIIO::stride_t(nc * sizeof(float))
        ? static_cast<const float*>(src.localpixels())
        : nullptr;
    if (!voxels) {
        copy.resize(n * size_t(nc));
        if (!src.get_pixels(src.roi(), OIIO::TypeFloat, copy.data())) {
            error = src.geterror();
            return false;
        }
        voxels = copy.data();
    }
    const int alpha = spec.alpha_channel > 0 ? spec.alpha_channel : -1;
    const bool divide = alpha >= 0 && !spec.get_int_attribute("oiio:UnassociatedAlpha", 0);
    PlanarVolume v;
    v.channel_names = spec.channelnames;
    v.alpha_channel = alpha;
    for (int c = 0; c < nc; ++c)
        v.channels.emplace_back(w, h, d);
    for (size_t i = 0; i < n; ++i) {
        const float* px = voxels + i * size_t(nc);
        const float a = alpha >= 0 ? px[alpha] : 1.0f;
        for (int c = 0; c < nc; ++c) {
            const float x = px[c];
            if (!std::isfinite(x)) {
                error = "voxel " + std::to_string(i) + " channel "
                    + std::string(spec.channel_name(c))
                    + " is not finite; texsyn needs finite values";
                return false;
            }
            v.channels[size_t(c)].data()[i] = divide && c < alpha && a > 0.0f ? x / a : x;
        }
    }
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        if (OIIO::Strutil::starts_with(p.name(), "synth:") || p.name() == "wrapmodes")
            v.attributes.add_or_replace(p);
    dst = std::move(v);
    return true;
}

OIIO::ImageBuf volume_slice(const OIIO::ImageBuf& volume, int z)
{
    const OIIO::ImageSpec& vs = volume.spec();
    OIIO::ImageSpec spec(vs.width, vs.height, vs.nchannels, OIIO::TypeFloat);
    spec.channelnames = vs.channelnames;
    spec.alpha_channel = vs.alpha_channel;
    spec.extra_attribs = vs.extra_attribs;
    OIIO::ImageBuf slice(spec);
    std::vector<float> px(size_t(vs.width) * size_t(vs.height) * size_t(vs.nchannels));
    volume.get_pixels(OIIO::ROI(vs.x, vs.x + vs.width, vs.y, vs.y + vs.height, vs.z + z,
                          vs.z + z + 1, 0, vs.nchannels),
        OIIO::TypeFloat, px.data());
    // Associated with alpha, OIIO's convention and what the slice EXR stores.
    const int alpha = vs.alpha_channel;
    if (alpha > 0 && vs.get_int_attribute("oiio:UnassociatedAlpha", 0))
        for (size_t i = 0; i < px.size(); i += size_t(vs.nchannels))
            for (int c = 0; c < alpha; ++c)
                px[i + size_t(c)] *= px[i + size_t(alpha)];
    slice.specmod().erase_attribute("oiio:UnassociatedAlpha");
    slice.set_pixels(slice.roi(), OIIO::TypeFloat, px.data());
    return slice;
}

bool convert_volume_colours(const ColorConfig& colors, const OIIO::ImageBuf& volume,
    const std::string& from, const std::string& to, OIIO::ImageBuf& dst, std::string& error)
{
    PlanarVolume v;
    if (!volume_from_imagebuf(volume, v, error))
        return false;
    PlanarImage planes;
    swap_voxel_planes(v, planes);
    const bool ok = colors.convert(planes, from, to, error);
    swap_voxel_planes(v, planes);
    if (ok)
        imagebuf_from_volume(v, dst);
    return ok;
}

} // namespace texsyn
