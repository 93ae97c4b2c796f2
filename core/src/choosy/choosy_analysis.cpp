// SPDX-License-Identifier: Apache-2.0
// The sample's Gaussian and Laplacian pyramids and the incremental inversion
// (choosy_pvt.h; Castellanos & Williams §3.2–3.3, eq. 1–2).
#include "choosy_pvt.h"

#include <texsyn/pyramid.h>

namespace texsyn::detail {

ChoosyAnalysis analyze_choosy(const std::vector<Plane>& channels, int levels, int nthreads)
{
    ChoosyAnalysis a;
    a.gaussian = gaussian_pyramid(channels, levels, Boundary::Reflect, nthreads);
    a.laplacian.resize(a.gaussian.size());
    for (size_t l = 0; l + 1 < a.gaussian.size(); ++l)
        for (const Plane& g : a.gaussian[l]) {
            const size_t ch = a.laplacian[l].size();
            Plane band = expand_plane(
                a.gaussian[l + 1][ch], g.width(), g.height(), Boundary::Reflect, nthreads);
            float* b = band.data();
            const float* gd = g.data();
            for (size_t i = 0; i < band.size(); ++i)
                b[i] = gd[i] - b[i];
            a.laplacian[l].push_back(std::move(band));
        }
    return a;
}

std::vector<Plane> invert_level(const std::vector<Plane>& laplacian,
    const std::vector<Plane>& coarse, Boundary boundary, int nthreads)
{
    std::vector<Plane> level;
    for (size_t ch = 0; ch < laplacian.size(); ++ch) {
        const Plane& band = laplacian[ch];
        Plane g = expand_plane(coarse[ch], band.width(), band.height(), boundary, nthreads);
        float* gd = g.data();
        const float* b = band.data();
        for (size_t i = 0; i < g.size(); ++i)
            gd[i] += b[i];
        level.push_back(std::move(g));
    }
    return level;
}

} // namespace texsyn::detail
