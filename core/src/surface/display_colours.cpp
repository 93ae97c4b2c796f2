// SPDX-License-Identifier: Apache-2.0
// The colours mesh viewers show for a surface texture's faces.
#include <texsyn/surface.h>

#include <algorithm>
#include <cmath>

#include <texsyn/image.h>

namespace texsyn {

bool surface_display_rgb(const SurfaceTexture& texture, const ColorConfig& colors,
    std::vector<std::array<uint8_t, 3>>& rgb, std::string& error, int nthreads)
{
    const size_t nfaces = texture.faces.size();
    PlanarImage planes;
    for (size_t c = 0; c < 3; ++c) {
        const std::vector<float>& from = texture.colours[std::min(c, texture.colours.size() - 1)];
        Plane p(int(nfaces), 1);
        std::copy(from.begin(), from.end(), p.data());
        planes.channels.push_back(std::move(p));
    }
    planes.channel_names = { "R", "G", "B" };
    const std::string srgb
        = colors.guess_colorspace(OIIO::ImageSpec(1, 1, 3, OIIO::TypeUInt8)).space;
    if (!colors.convert(planes, colors.scene_linear(), srgb, error, nthreads))
        return false;
    rgb.assign(nfaces, {});
    for (size_t f = 0; f < nfaces; ++f)
        for (size_t c = 0; c < 3; ++c) {
            const float v = std::clamp(planes.channels[c].data()[f], 0.0f, 1.0f);
            rgb[f][c] = uint8_t(std::lround(v * 255.0f));
        }
    return true;
}

} // namespace texsyn
