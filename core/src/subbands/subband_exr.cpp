// SPDX-License-Identifier: Apache-2.0
#include <texsyn/subbands.h>

#include <algorithm>

#include <OpenImageIO/imageio.h>

#include <texsyn/io.h>

namespace texsyn {

namespace {

OIIO::ImageSpec part_spec(int width, int height, const std::vector<std::string>& channels,
    int alpha_channel, const std::string& name, int display_w, int display_h,
    const OIIO::ImageSpec& metadata)
{
    OIIO::ImageSpec spec(width, height, int(channels.size()), OIIO::TypeFloat);
    spec.channelnames = channels;
    spec.alpha_channel = alpha_channel;
    // OpenEXR multi-part files need one display window shared by every part.
    spec.full_x = spec.full_y = 0;
    spec.full_width = display_w;
    spec.full_height = display_h;
    for (const OIIO::ParamValue& p : metadata.extra_attribs)
        if (OIIO::Strutil::starts_with(p.name(), "synth:"))
            spec.attribute(p.name(), p.type(), p.data());
    spec.attribute("oiio:subimagename", name);
    spec.attribute("compression", "zip");
    return spec;
}

} // namespace

bool write_subband_exr(const std::string& filename, const OIIO::ImageBuf& synth,
    const std::vector<NamedImage>& subbands, std::string& error)
{
    int display_w = synth.spec().width, display_h = synth.spec().height;
    for (const NamedImage& s : subbands) {
        display_w = std::max(display_w, s.image.width());
        display_h = std::max(display_h, s.image.height());
    }
    std::vector<OIIO::ImageSpec> specs;
    specs.push_back(part_spec(synth.spec().width, synth.spec().height, synth.spec().channelnames,
        synth.spec().alpha_channel, "synth", display_w, display_h, synth.spec()));
    for (const OIIO::ParamValue& p : synth.spec().extra_attribs)
        if (!OIIO::Strutil::starts_with(p.name(), "synth:")
            && !OIIO::Strutil::starts_with(p.name(), "oiio:"))
            specs[0].attribute(p.name(), p.type(), p.data());
    for (const NamedImage& s : subbands)
        specs.push_back(part_spec(s.image.width(), s.image.height(), s.image.channel_names,
            s.image.alpha_channel, s.name, display_w, display_h, synth.spec()));

    return write_multipart_exr(
        filename, specs,
        [&](size_t i, OIIO::ImageBuf& part) {
            if (i == 0)
                part.copy(synth, OIIO::TypeFloat);
            else
                imagebuf_from_planes(subbands[i - 1].image, part);
        },
        error);
}

} // namespace texsyn
