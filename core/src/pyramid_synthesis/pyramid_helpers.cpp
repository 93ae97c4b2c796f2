// SPDX-License-Identifier: Apache-2.0
#include "pyramid_synthesis_pvt.h"

#include <algorithm>

namespace texsyn::detail {

std::unique_ptr<Pyramid> make_pyramid(const PyramidOptions& opt, int width, int height, int scales,
    Boundary boundary, std::string& error)
{
    if (opt.pyramid == PyramidKind::Laplacian)
        return make_laplacian_pyramid(width, height, scales, boundary, error);
    return make_steerable_pyramid(width, height, scales, opt.orientations, opt.fft, error);
}

bool is_constant(const Plane& p)
{
    auto [lo, hi] = std::minmax_element(p.data(), p.data() + p.size());
    return *lo == *hi;
}

float plane_mean(const Plane& p)
{
    double sum = 0.0;
    for (size_t i = 0; i < p.size(); ++i)
        sum += p.data()[i];
    return float(sum / double(p.size()));
}

void append_subbands(const std::string& prefix, const std::vector<std::string>& band_names,
    const std::vector<std::vector<Plane>>& per_component,
    const std::vector<std::string>& component_names, std::vector<NamedImage>& out)
{
    for (size_t b = 0; b < band_names.size(); ++b) {
        NamedImage ni;
        ni.name = prefix + "." + band_names[b];
        for (size_t c = 0; c < per_component.size(); ++c) {
            ni.image.channels.push_back(per_component[c][b]);
            ni.image.channel_names.push_back(component_names[c]);
        }
        ni.image.alpha_channel = -1; // "A" is a band here: never multiplied into colour
        out.push_back(std::move(ni));
    }
}

} // namespace texsyn::detail
