// SPDX-License-Identifier: Apache-2.0
// Neighbourhood shapes, candidate positions and vector gathering (neighborhood_pvt.h).
#include "neighborhood_pvt.h"

#include <algorithm>
#include <cstdlib>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

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

void sample_vector(const NeighborhoodLayout& layout, const std::vector<Plane>& level,
    const std::vector<Plane>& coarser, int x, int y, float* out)
{
    const size_t nc = level.size();
    for (const Offset& o : layout.fine)
        for (size_t c = 0; c < nc; ++c)
            *out++ = level[c](x + o.dx, y + o.dy);
    if (layout.coarse.empty())
        return;
    const int cw = coarser[0].width(), ch = coarser[0].height();
    for (const Offset& o : layout.coarse) {
        // Reflection only where the square leaves the coarser level (Plane::at is a call
        // per value).
        const int cx = x / 2 + o.dx, cy = y / 2 + o.dy;
        const bool inside = cx >= 0 && cy >= 0 && cx < cw && cy < ch;
        for (size_t c = 0; c < nc; ++c)
            *out++ = inside ? coarser[c](cx, cy) : coarser[c].at(cx, cy, Boundary::Reflect);
    }
}

SampleVectors sample_vectors(const NeighborhoodLayout& layout, const CandidateGrid& grid,
    const std::vector<Plane>& level, const std::vector<Plane>& coarser, int nthreads)
{
    const size_t dim = size_t(layout.npixels()) * level.size();
    SampleVectors vectors(grid.count() * dim);
    OIIO::parallel_for(
        int64_t(0), int64_t(grid.rows),
        [&](int64_t row) {
            for (int col = 0; col < grid.columns; ++col) {
                const size_t index = size_t(row) * size_t(grid.columns) + size_t(col);
                sample_vector(layout, level, coarser, grid.x0 + col, grid.y0 + int(row),
                    vectors.data() + index * dim);
            }
        },
        detail::split_every_item(nthreads));
    return vectors;
}

NeighborAccess::NeighborAccess(const NeighborhoodLayout& layout, const OutputLevel& level,
    const std::vector<Plane>& coarser, NeighborView view)
    : m_layout(layout)
    , m_level(level)
    , m_coarser(coarser)
    , m_view(view)
{
    const std::ptrdiff_t w = level.width();
    for (const Offset& o : layout.fine) {
        m_fine_offsets.push_back(o.dy * w + o.dx);
        m_after.push_back(view == NeighborView::Scanline && (o.dy > 0 || (o.dy == 0 && o.dx > 0)));
        m_reach = std::max({ m_reach, std::abs(o.dx), std::abs(o.dy) });
    }
    if (layout.coarse.empty())
        return;
    const std::ptrdiff_t cw = coarser[0].width();
    for (const Offset& o : layout.coarse) {
        m_coarse_offsets.push_back(o.dy * cw + o.dx);
        m_coarse_reach = std::max({ m_coarse_reach, std::abs(o.dx), std::abs(o.dy) });
    }
}

const OutputLevel::Pixels& NeighborAccess::locate(int x, int y, size_t i, size_t& index) const
{
    const int w = m_level.width(), h = m_level.height();
    const Offset& o = m_layout.fine[i];
    const int nx = x + o.dx, ny = y + o.dy;
    index = size_t(wrap(ny, h)) * size_t(w) + size_t(wrap(nx, w));
    const bool initial = m_after[i] || (m_view == NeighborView::Scanline && (nx < 0 || ny < 0));
    return initial ? m_level.initial : m_level.live;
}

uint32_t NeighborAccess::neighbor_source(int x, int y, size_t i) const
{
    size_t index = 0;
    return locate(x, y, i, index).source[index];
}

void NeighborAccess::gather(int x, int y, float* out) const
{
    const size_t nc = m_level.live.channels.size();
    const int w = m_level.width(), h = m_level.height();
    if (x >= m_reach && y >= m_reach && x + m_reach < w && y + m_reach < h) {
        const std::ptrdiff_t base = std::ptrdiff_t(y) * w + x;
        for (size_t i = 0; i < m_fine_offsets.size(); ++i) {
            const auto& pixels = m_after[i] ? m_level.initial : m_level.live;
            for (size_t c = 0; c < nc; ++c)
                *out++ = pixels.channels[c].data()[base + m_fine_offsets[i]];
        }
    } else {
        for (size_t i = 0; i < m_fine_offsets.size(); ++i) {
            size_t index = 0;
            const auto& pixels = locate(x, y, i, index);
            for (size_t c = 0; c < nc; ++c)
                *out++ = pixels.channels[c].data()[index];
        }
    }
    if (m_layout.coarse.empty())
        return;
    const int cw = m_coarser[0].width(), ch = m_coarser[0].height();
    const int px = x / 2, py = y / 2;
    if (px >= m_coarse_reach && py >= m_coarse_reach && px + m_coarse_reach < cw
        && py + m_coarse_reach < ch) {
        const std::ptrdiff_t base = std::ptrdiff_t(py) * cw + px;
        for (std::ptrdiff_t off : m_coarse_offsets)
            for (size_t c = 0; c < nc; ++c)
                *out++ = m_coarser[c].data()[base + off];
    } else {
        for (const Offset& o : m_layout.coarse) {
            const size_t i = size_t(wrap(py + o.dy, ch)) * size_t(cw) + size_t(wrap(px + o.dx, cw));
            for (size_t c = 0; c < nc; ++c)
                *out++ = m_coarser[c].data()[i];
        }
    }
}

} // namespace texsyn::detail
