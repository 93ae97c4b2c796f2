// SPDX-License-Identifier: Apache-2.0
// Choosy sampling on the pixel grid (choosy_pvt.h): the 2-distant ring, its eight
// orientations, the sample's points and the output level as a ChoosyTarget.
#include "choosy_pvt.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace texsyn::detail {

const std::vector<RingSlot>& ring_slots()
{
    static const std::vector<RingSlot> slots = [] {
        // sigma_k is the reduce kernel's standard deviation: (1,4,6,4,1)/16 is the binomial
        // B(4, 1/2), of variance 1, so 1 pixel of the level.
        constexpr double sigma = 1.0;
        std::vector<RingSlot> s;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                if (dx == 0 && dy == 0)
                    continue;
                const double d = std::sqrt(double(dx * dx + dy * dy)) / (1.3 * sigma);
                s.push_back({ dx, dy, float(std::exp(-0.5 * d * d)) });
            }
        return s;
    }();
    return slots;
}

void orient(int t, int& dx, int& dy)
{
    if (t & 4)
        std::swap(dx, dy);
    if (t & 1)
        dx = -dx;
    if (t & 2)
        dy = -dy;
}

AnalysisPoints grid_points(const std::vector<Plane>& gaussian, int orientations)
{
    const std::vector<RingSlot>& slots = ring_slots();
    const int w = gaussian[0].width();
    const GridCandidates candidates { w, gaussian[0].height() };
    // Linear offsets of each slot in each orientation.
    std::vector<std::ptrdiff_t> offsets;
    for (int t = 0; t < orientations; ++t)
        for (const RingSlot& s : slots) {
            int dx = s.dx, dy = s.dy;
            orient(t, dx, dy);
            offsets.push_back(std::ptrdiff_t(dy) * w + dx);
        }
    AnalysisPoints points;
    points.orientations = orientations;
    points.count = candidates.count() * size_t(orientations);
    points.dim = int(slots.size() * gaussian.size());
    points.vector
        = [&gaussian, &slots, candidates, offsets, orientations, w](size_t p, float* out) {
              const size_t c = p / size_t(orientations);
              const std::ptrdiff_t centre = std::ptrdiff_t(candidates.y(c)) * w + candidates.x(c);
              const std::ptrdiff_t* o = offsets.data() + (p % size_t(orientations)) * slots.size();
              const size_t nc = gaussian.size();
              for (size_t s = 0; s < slots.size(); ++s)
                  for (size_t ch = 0; ch < nc; ++ch)
                      out[s * nc + ch] = slots[s].weight * gaussian[ch].data()[centre + o[s]];
          };
    return points;
}

void copy_choice(GridLevel& out, int x, int y, const std::vector<Plane>& gaussian,
    const std::vector<Plane>& laplacian, int sx, int sy, int t)
{
    for (size_t ch = 0; ch < gaussian.size(); ++ch)
        out.gaussian[ch](x, y) = gaussian[ch](sx, sy);
    const size_t site = size_t(y) * size_t(out.width()) + size_t(x);
    out.source[site] = uint32_t(sy) * uint32_t(gaussian[0].width()) + uint32_t(sx);
    out.orientation[site] = uint8_t(t);
    if (laplacian.empty())
        return;
    // Child (cx, cy) of the output's 2x2 block, at (2cx - 1, 2cy - 1) from the block's
    // centre in half pixels, takes the sample's child at the oriented position.
    for (int cy = 0; cy < 2; ++cy)
        for (int cx = 0; cx < 2; ++cx) {
            int a = 2 * cx - 1, b = 2 * cy - 1;
            orient(t, a, b);
            const int lx = 2 * sx + (a + 1) / 2, ly = 2 * sy + (b + 1) / 2;
            for (size_t ch = 0; ch < laplacian.size(); ++ch)
                out.children[ch](2 * x + cx, 2 * y + cy) = laplacian[ch](lx, ly);
        }
}

namespace {

class GridTarget final : public ChoosyTarget {
public:
    GridTarget(GridLevel& out, const std::vector<Plane>& gaussian,
        const std::vector<Plane>& laplacian, int orientations)
        : m_out(out)
        , m_gaussian(gaussian)
        , m_laplacian(laplacian)
        , m_candidates { gaussian[0].width(), gaussian[0].height() }
        , m_orientations(orientations)
    { }

    size_t sites() const override { return m_out.source.size(); }
    int dim() const override { return int(ring_slots().size() * m_out.gaussian.size()); }
    size_t max_neighbors() const override { return ring_slots().size(); }

    void query(size_t site, float* out) const override
    {
        const std::vector<RingSlot>& slots = ring_slots();
        std::array<size_t, 24> at {};
        neighbors(site, at.data());
        const size_t nc = m_out.gaussian.size();
        for (size_t s = 0; s < slots.size(); ++s)
            for (size_t ch = 0; ch < nc; ++ch)
                out[s * nc + ch] = slots[s].weight * m_out.gaussian[ch].data()[at[s]];
    }

    size_t neighbors(size_t site, size_t* out) const override
    {
        const int w = m_out.width(), h = m_out.height();
        const int x = int(site % size_t(w)), y = int(site / size_t(w));
        const std::vector<RingSlot>& slots = ring_slots();
        for (size_t s = 0; s < slots.size(); ++s) {
            const int xx = wrap_coordinate(x + slots[s].dx, w, Boundary::Circular);
            const int yy = wrap_coordinate(y + slots[s].dy, h, Boundary::Circular);
            out[s] = size_t(yy) * size_t(w) + size_t(xx);
        }
        return slots.size();
    }

    size_t hints(size_t site, uint32_t* out) const override
    {
        const std::vector<RingSlot>& slots = ring_slots();
        std::array<size_t, 24> at {};
        neighbors(site, at.data());
        const int sw = m_candidates.width;
        size_t n = 0;
        for (size_t s = 0; s < slots.size(); ++s) {
            const int t = m_out.orientation[at[s]];
            if (t == kNotChosen)
                continue;
            // The neighbour at offset o copied sample pixel q seen in orientation t, so this
            // pixel continues it at q - T_t(o).
            int dx = slots[s].dx, dy = slots[s].dy;
            orient(t, dx, dy);
            const uint32_t q = m_out.source[at[s]];
            const int64_t c
                = m_candidates.index(int(q % uint32_t(sw)) - dx, int(q / uint32_t(sw)) - dy);
            if (c < 0)
                continue;
            const uint32_t point = uint32_t(c) * uint32_t(m_orientations) + uint32_t(t);
            if (std::find(out, out + n, point) == out + n)
                out[n++] = point;
        }
        return n;
    }

    void apply(size_t site, uint32_t point) override
    {
        const size_t c = point / uint32_t(m_orientations);
        const int w = m_out.width();
        copy_choice(m_out, int(site % size_t(w)), int(site / size_t(w)), m_gaussian, m_laplacian,
            m_candidates.x(c), m_candidates.y(c), int(point % uint32_t(m_orientations)));
    }

private:
    GridLevel& m_out;
    const std::vector<Plane>& m_gaussian;
    const std::vector<Plane>& m_laplacian;
    GridCandidates m_candidates;
    int m_orientations;
};

} // namespace

std::unique_ptr<ChoosyTarget> make_grid_target(GridLevel& out, const std::vector<Plane>& gaussian,
    const std::vector<Plane>& laplacian, int orientations)
{
    return std::make_unique<GridTarget>(out, gaussian, laplacian, orientations);
}

} // namespace texsyn::detail
