// SPDX-License-Identifier: Apache-2.0
// Neighbourhood shapes, candidate positions and vector gathering (neighborhood_pvt.h).
#include "neighborhood_pvt.h"

#include <OpenImageIO/parallel.h>

namespace texsyn::detail {

NeighborhoodLayout make_layout(int n, int coarse, bool has_coarser, NeighborhoodShape shape)
{
    NeighborhoodLayout layout;
    layout.half = (n - 1) / 2;
    layout.shape = shape;
    const int h = layout.half;
    const int last_row = shape == NeighborhoodShape::Causal ? 0 : h;
    for (int dy = -h; dy <= last_row; ++dy)
        for (int dx = -h; dx <= h; ++dx) {
            if (dy == 0 && dx == 0)
                continue;
            if (shape == NeighborhoodShape::Causal && dy == 0 && dx > 0)
                break;
            layout.fine.push_back({ dx, dy });
        }
    if (has_coarser) {
        const int c = (coarse - 1) / 2;
        for (int dy = -c; dy <= c; ++dy)
            for (int dx = -c; dx <= c; ++dx)
                layout.coarse.push_back({ dx, dy });
    }
    return layout;
}

CandidateGrid candidate_grid(const NeighborhoodLayout& layout, int width, int height)
{
    const int h = layout.half;
    const int below = layout.shape == NeighborhoodShape::Causal ? 0 : h;
    CandidateGrid g;
    g.x0 = h;
    g.y0 = h;
    g.columns = width - 2 * h > 0 ? width - 2 * h : 0;
    g.rows = height - h - below > 0 ? height - h - below : 0;
    if (g.columns == 0 || g.rows == 0)
        g.columns = g.rows = 0;
    return g;
}

SampleVectors sample_vectors(const NeighborhoodLayout& layout, const CandidateGrid& grid,
    const std::vector<Plane>& level, const std::vector<Plane>& coarser, int nthreads)
{
    const int nc = int(level.size());
    const size_t dim = size_t(layout.npixels()) * size_t(nc);
    const int cw = coarser.empty() ? 0 : coarser[0].width();
    const int ch = coarser.empty() ? 0 : coarser[0].height();
    SampleVectors vectors(grid.count() * dim);
    OIIO::parallel_for(
        int64_t(0), int64_t(grid.rows),
        [&](int64_t row) {
            for (int col = 0; col < grid.columns; ++col) {
                const size_t index = size_t(row) * size_t(grid.columns) + size_t(col);
                const int x = grid.x0 + col, y = grid.y0 + int(row);
                float* v = vectors.data() + index * dim;
                for (const Offset& o : layout.fine)
                    for (int c = 0; c < nc; ++c)
                        *v++ = level[size_t(c)](x + o.dx, y + o.dy);
                for (const Offset& o : layout.coarse) {
                    // Reflection only where the square leaves the coarser level (Plane::at
                    // is a call per value).
                    const int cx = x / 2 + o.dx, cy = y / 2 + o.dy;
                    const bool inside = cx >= 0 && cy >= 0 && cx < cw && cy < ch;
                    for (int c = 0; c < nc; ++c)
                        *v++ = inside ? coarser[size_t(c)](cx, cy)
                                      : coarser[size_t(c)].at(cx, cy, Boundary::Reflect);
                }
            }
        },
        OIIO::paropt(nthreads).minitems(1));
    return vectors;
}

void output_vector(const NeighborhoodLayout& layout, const std::vector<Plane>& level,
    const std::vector<Plane>& coarser, int x, int y, float* out)
{
    const size_t nc = level.size();
    const int w = level[0].width(), h = level[0].height();
    for (const Offset& o : layout.fine) {
        const size_t i = size_t(wrap(y + o.dy, h)) * size_t(w) + size_t(wrap(x + o.dx, w));
        for (size_t c = 0; c < nc; ++c)
            *out++ = level[c].data()[i];
    }
    if (layout.coarse.empty())
        return;
    const int cw = coarser[0].width(), ch = coarser[0].height();
    for (const Offset& o : layout.coarse) {
        const size_t i
            = size_t(wrap(y / 2 + o.dy, ch)) * size_t(cw) + size_t(wrap(x / 2 + o.dx, cw));
        for (size_t c = 0; c < nc; ++c)
            *out++ = coarser[c].data()[i];
    }
}

} // namespace texsyn::detail
