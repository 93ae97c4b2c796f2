// SPDX-License-Identifier: Apache-2.0
// A volume as a multi-part OpenEXR of z slices, for tools without OpenVDB.
#include <texsyn/volume.h>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/io.h>

namespace texsyn {

namespace {

// Slice z as a PlanarImage (colour un-associated, as in the volume).
PlanarImage z_slice(const PlanarVolume& v, int z)
{
    PlanarImage img;
    img.channel_names = v.channel_names;
    img.alpha_channel = v.alpha_channel;
    for (const Volume& channel : v.channels)
        extract_slice(channel, SliceAxis::Z, z, img.channels.emplace_back());
    return img;
}

} // namespace

bool write_volume_exr(
    const std::string& filename, const PlanarVolume& v, OIIO::TypeDesc format, std::string& error)
{
    std::vector<OIIO::ImageSpec> specs;
    for (int z = 0; z < v.depth(); ++z) {
        // Every part has the same size, so the shared display window OpenEXR requires of a
        // multi-part file is each part's own.
        OIIO::ImageSpec spec(v.width(), v.height(), v.nchannels(), format);
        spec.channelnames = v.channel_names;
        spec.alpha_channel = v.alpha_channel;
        spec.extra_attribs = v.attributes;
        spec.attribute("oiio:subimagename", volume_exr_part_name(z, v.depth()));
        spec.attribute("compression", "zip");
        specs.push_back(std::move(spec));
    }
    return write_multipart_exr(
        filename, specs,
        [&](size_t z, OIIO::ImageBuf& part) {
            imagebuf_from_planes(z_slice(v, int(z)), part, true);
        },
        error);
}

} // namespace texsyn
