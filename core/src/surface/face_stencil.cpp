// SPDX-License-Identifier: Apache-2.0
// §3.12's 2-distant stencil: its shape on the regular grid, and each face's neighbours put
// in its slots.
#include "face_stencil_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {

namespace {

// A triangle of the unit lattice: corners as lattice coordinates (i, j) -> i e1 + j e2.
struct LatticeTriangle {
    std::array<std::pair<int, int>, 3> corners;
    Imath::V2f centroid() const
    {
        Imath::V2f c(0.0f);
        for (const auto& [i, j] : corners)
            c += Imath::V2f(float(i + 0.5 * j), float(j * std::sqrt(3.0) / 2.0));
        return c / 3.0f;
    }
    bool touches(const LatticeTriangle& o) const
    {
        for (const auto& a : corners)
            for (const auto& b : o.corners)
                if (a == b)
                    return true;
        return false;
    }
};

StencilShape make_shape()
{
    std::vector<LatticeTriangle> all;
    for (int j = -4; j <= 4; ++j)
        for (int i = -4; i <= 4; ++i) {
            all.push_back({ { { { i, j }, { i + 1, j }, { i, j + 1 } } } });
            all.push_back({ { { { i + 1, j }, { i + 1, j + 1 }, { i, j + 1 } } } });
        }
    const LatticeTriangle reference { { { { 0, 0 }, { 1, 0 }, { 0, 1 } } } };
    const Imath::V2f origin = reference.centroid();
    std::vector<int> ring(all.size(), 0);
    for (size_t t = 0; t < all.size(); ++t)
        if (all[t].centroid() != origin && all[t].touches(reference))
            ring[t] = 1;
    for (size_t t = 0; t < all.size(); ++t) {
        if (ring[t] != 0 || all[t].centroid() == origin)
            continue;
        for (size_t u = 0; u < all.size(); ++u)
            if (ring[u] == 1 && all[t].touches(all[u]))
                ring[t] = 2;
    }
    struct Slot {
        int ring;
        double angle, distance;
        Imath::V2f position;
    };
    std::vector<Slot> slots;
    for (size_t t = 0; t < all.size(); ++t)
        if (ring[t] > 0) {
            const Imath::V2f p = all[t].centroid() - origin;
            double angle = std::atan2(double(p.y), double(p.x));
            if (angle < -1e-9)
                angle += 2.0 * M_PI;
            slots.push_back({ ring[t], angle, double(p.length()), p });
        }
    std::sort(slots.begin(), slots.end(), [](const Slot& a, const Slot& b) {
        if (a.ring != b.ring)
            return a.ring < b.ring;
        if (std::abs(a.angle - b.angle) > 1e-6)
            return a.angle < b.angle;
        return a.distance < b.distance;
    });
    StencilShape shape;
    for (int s = 0; s < kStencilSlots; ++s) {
        shape.position[size_t(s)] = slots[size_t(s)].position;
        shape.ring[size_t(s)] = slots[size_t(s)].ring;
    }
    for (int r = 0; r < 3; ++r) {
        const double a = -2.0 * M_PI / 3.0 * r, ca = std::cos(a), sa = std::sin(a);
        for (int s = 0; s < kStencilSlots; ++s) {
            const Imath::V2f& p = shape.position[size_t(s)];
            const Imath::V2f q(float(ca * p.x - sa * p.y), float(sa * p.x + ca * p.y));
            int best = 0;
            for (int t = 1; t < kStencilSlots; ++t)
                if ((shape.position[size_t(t)] - q).length2()
                    < (shape.position[size_t(best)] - q).length2())
                    best = t;
            shape.permutation[size_t(r)][size_t(s)] = best;
        }
    }
    return shape;
}

// A face of the two rings further than this (in edge lengths) from every slot stays out.
constexpr float kReach = 0.3f;

// The slots that may be within kReach of a point, by square cells of the plane around the
// stencil: a face is placed only in a slot within kReach, so only those are compared.
class SlotCells {
public:
    explicit SlotCells(const StencilShape& shape)
    {
        for (int cy = 0; cy < kCells; ++cy)
            for (int cx = 0; cx < kCells; ++cx) {
                const float x0 = -kExtent + float(cx) * kCell, y0 = -kExtent + float(cy) * kCell;
                auto& cell = m_slots[size_t(cy * kCells + cx)];
                for (int s = 0; s < kStencilSlots; ++s) {
                    const Imath::V2f& q = shape.position[size_t(s)];
                    // Distance from the slot to the cell, with a margin for rounding.
                    const float dx = std::max({ x0 - q.x, q.x - (x0 + kCell), 0.0f });
                    const float dy = std::max({ y0 - q.y, q.y - (y0 + kCell), 0.0f });
                    if (dx * dx + dy * dy < (kReach + 0.01f) * (kReach + 0.01f))
                        cell.push_back(uint8_t(s));
                }
            }
    }
    // The candidate slots of `p`, in increasing order (none outside the cells).
    const std::vector<uint8_t>& at(const Imath::V2f& p) const
    {
        static const std::vector<uint8_t> none;
        const float fx = (p.x + kExtent) / kCell, fy = (p.y + kExtent) / kCell;
        if (!(fx >= 0.0f && fy >= 0.0f && fx < float(kCells) && fy < float(kCells)))
            return none;
        return m_slots[size_t(int(fy) * kCells + int(fx))];
    }

private:
    // Every slot is within 2.2 edge lengths of the centre, so cells over +-2.5 hold every
    // point within kReach of one.
    static constexpr float kExtent = 2.5f, kCell = 0.25f;
    static constexpr int kCells = 20;
    std::array<std::vector<uint8_t>, size_t(kCells* kCells)> m_slots;
};

} // namespace

const StencilShape& stencil_shape()
{
    static const StencilShape shape = make_shape();
    return shape;
}

bool complete(const std::array<uint32_t, kStencilSlots>& slots)
{
    return std::find(slots.begin(), slots.end(), kNoFace) == slots.end();
}

std::vector<std::array<uint32_t, kStencilSlots>> face_stencils(const FaceLevel& level, int nthreads)
{
    const StencilShape& shape = stencil_shape();
    static const SlotCells cells(shape);
    std::vector<std::array<uint32_t, kStencilSlots>> out(level.size());
    constexpr float kReach2 = kReach * kReach;
    // Few chunks: each holds a mark per face of the level.
    const int64_t chunk = std::max<int64_t>(1, int64_t(level.size()) / 8);
    OIIO::parallel_for_chunked(
        0, int64_t(level.size()), chunk,
        [&](int64_t begin, int64_t end) {
            // The two rings, each face once: `seen` holds the face it was last gathered for.
            std::vector<uint32_t> seen(level.size(), kNoFace), ring1, rings;
            auto gather = [&](uint32_t around, uint32_t f, std::vector<uint32_t>& into) {
                for (uint32_t v : level.faces[around])
                    for (uint32_t i = level.vertex_face_start[v];
                         i < level.vertex_face_start[v + 1]; ++i) {
                        const uint32_t g = level.vertex_faces[i];
                        if (seen[g] != f) {
                            seen[g] = f;
                            into.push_back(g);
                        }
                    }
            };
            std::array<float, kStencilSlots> best {};
            for (int64_t fi = begin; fi < end; ++fi) {
                const uint32_t f = uint32_t(fi);
                const auto& corner = level.faces[f];
                const Imath::V3f& a = level.vertices[corner[0]];
                const Imath::V3f& b = level.vertices[corner[1]];
                const Imath::V3f& c = level.vertices[corner[2]];
                const float unit = ((b - a).length() + (c - b).length() + (a - c).length()) / 3.0f;
                const Imath::V3f x = (b - a).normalized();
                const Imath::V3f y = level.normal[f].cross(x);
                ring1.clear();
                seen[f] = f;
                gather(f, f, ring1);
                rings = ring1;
                for (uint32_t g : ring1)
                    gather(g, f, rings);
                out[f].fill(kNoFace);
                best.fill(kReach2);
                for (uint32_t g : rings) {
                    if (g == f)
                        continue;
                    const Imath::V3f d = level.centroid[g] - level.centroid[f];
                    const Imath::V2f p(d.dot(x) / unit, d.dot(y) / unit);
                    // The nearest slot, if it is within kReach (the first of equals).
                    int nearest = -1;
                    float nearest2 = 0.0f;
                    for (uint8_t s : cells.at(p)) {
                        const float d2 = (shape.position[s] - p).length2();
                        if (nearest < 0 || d2 < nearest2) {
                            nearest = s;
                            nearest2 = d2;
                        }
                    }
                    if (nearest >= 0 && nearest2 < best[size_t(nearest)]) {
                        best[size_t(nearest)] = nearest2;
                        out[f][size_t(nearest)] = g;
                    }
                }
            }
        },
        detail::split_every_item(nthreads));
    return out;
}

} // namespace texsyn::detail
