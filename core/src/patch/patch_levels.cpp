// SPDX-License-Identifier: Apache-2.0
// Planes to interleaved pixels, plain or with a circular margin; a sample level and its
// variants; a field carried to the next finer level.
#include "patch_pvt.h"

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {

PixelImage interleave_padded(const std::vector<Plane>& planes, int pad, int nthreads, Wrap wrap)
{
    const Boundary bx = wrap.x ? Boundary::Circular : Boundary::Reflect;
    const Boundary by = wrap.y ? Boundary::Circular : Boundary::Reflect;
    PixelImage out;
    const int w = planes.at(0).width(), h = planes.at(0).height(), c = int(planes.size());
    out.width = w + 2 * pad;
    out.height = h + 2 * pad;
    out.channels = c;
    out.data.resize(size_t(out.width) * size_t(out.height) * size_t(c));
    OIIO::parallel_for(
        0, out.height,
        [&](int64_t y) {
            const int sy = wrap_coordinate(int(y) - pad, h, by);
            float* row = out.pixel(0, int(y));
            for (int x = 0; x < out.width; ++x) {
                const int sx = wrap_coordinate(x - pad, w, bx);
                for (int k = 0; k < c; ++k)
                    row[size_t(x) * size_t(c) + size_t(k)] = planes[size_t(k)](sx, sy);
            }
        },
        detail::split_every_item(nthreads));
    return out;
}

PixelImage interleave(const std::vector<Plane>& planes, int nthreads)
{
    return interleave_padded(planes, 0, nthreads);
}

SampleLevel sample_level(
    const std::vector<Plane>& planes, int cell_width, int nthreads, bool histograms)
{
    SampleLevel level;
    level.cell_width = cell_width;
    level.pixels = detail::interleave(planes, nthreads);
    for (const Plane& p : planes) {
        if (histograms)
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

PatchField upsample_field(const PatchField& coarse, const detail::CentreRange& coarse_range, int w,
    int h, const detail::CentreRange& range)
{
    const int coarse_sample_width = coarse_range.width, coarse_cell = coarse_range.cell();
    PatchField field { w, h, std::vector<uint32_t>(size_t(w) * size_t(h)),
        std::vector<float>(size_t(w) * size_t(h), 0.0f) };
    for (int y = 0; y < h; ++y) {
        const int yc = std::min(coarse.height - 1, int(int64_t(y) * coarse.height / h));
        for (int x = 0; x < w; ++x) {
            const int xc = std::min(coarse.width - 1, int(int64_t(x) * coarse.width / w));
            const uint32_t s = coarse.source[size_t(yc) * size_t(coarse.width) + size_t(xc)];
            const int sx = int(s % uint32_t(coarse_sample_width));
            const int sy = int(s / uint32_t(coarse_sample_width));
            const int cell = sx / coarse_cell, local = sx - cell * coarse_cell;
            field.source[size_t(y) * size_t(w) + size_t(x)] = range.clamp(
                cell * range.cell() + 2 * local + (x - 2 * xc), 2 * sy + (y - 2 * yc));
        }
    }
    return field;
}

} // namespace texsyn::detail
