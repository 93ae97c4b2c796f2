// SPDX-License-Identifier: Apache-2.0
// Planes to interleaved pixels, plain or with a circular margin; a sample level.
#include "patch_pvt.h"

#include <OpenImageIO/parallel.h>

namespace texsyn::detail {

PixelImage interleave_padded(const std::vector<Plane>& planes, int pad, int nthreads)
{
    PixelImage out;
    const int w = planes.at(0).width(), h = planes.at(0).height(), c = int(planes.size());
    out.width = w + 2 * pad;
    out.height = h + 2 * pad;
    out.channels = c;
    out.data.resize(size_t(out.width) * size_t(out.height) * size_t(c));
    OIIO::parallel_for(
        0, out.height,
        [&](int64_t y) {
            const int sy = wrap(int(y) - pad, h);
            float* row = out.pixel(0, int(y));
            for (int x = 0; x < out.width; ++x) {
                const int sx = wrap(x - pad, w);
                for (int k = 0; k < c; ++k)
                    row[size_t(x) * size_t(c) + size_t(k)] = planes[size_t(k)](sx, sy);
            }
        },
        OIIO::paropt(nthreads));
    return out;
}

PixelImage interleave(const std::vector<Plane>& planes, int nthreads)
{
    return interleave_padded(planes, 0, nthreads);
}

SampleLevel sample_level(const std::vector<Plane>& planes, int cell_width, int nthreads)
{
    SampleLevel level;
    level.cell_width = cell_width;
    level.pixels = detail::interleave(planes, nthreads);
    for (const Plane& p : planes) {
        level.histograms.emplace_back(p);
        double mean = 0.0, var = 0.0;
        plane_moments(p, mean, var);
        level.variance += var;
    }
    return level;
}

int variant_count(int width, int height, bool isotropic)
{
    return !isotropic ? 1 : width == height ? 8 : 4;
}

uint32_t variant_source(int t, int width, int height, int x, int y)
{
    // t's bits: 1 mirror in x, 2 mirror in y, 4 transpose (first; square samples only).
    const int u = t & 4 ? y : x, v = t & 4 ? x : y;
    const int sx = t & 1 ? width - 1 - u : u, sy = t & 2 ? height - 1 - v : v;
    return uint32_t(sy) * uint32_t(width) + uint32_t(sx);
}

Plane variant_plane(const Plane& plane, int t)
{
    Plane out(plane.width(), plane.height());
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x)
            out(x, y) = plane.data()[variant_source(t, plane.width(), plane.height(), x, y)];
    return out;
}

} // namespace texsyn::detail
