// SPDX-License-Identifier: Apache-2.0
// 1-to-4 subdivision with parent -> children indices (§3.4–3.5), the new vertices at edge
// midpoints or by Zorin, Schröder & Sweldens' modified butterfly ("Interpolating
// subdivision for meshes with arbitrary topology", SIGGRAPH 1996).
#include "face_level_pvt.h"

#include <cmath>

namespace texsyn::detail {

namespace {

// What the butterfly needs of a finished level, per vertex.
class VertexRings {
public:
    explicit VertexRings(const FaceLevel& level)
        : m_level(level)
        , m_boundary(level.vertices.size(), 0)
    {
        for (size_t f = 0; f < level.size(); ++f)
            for (int e = 0; e < 3; ++e)
                if (level.across[f][size_t(e)] == kNoFace) {
                    m_boundary[level.faces[f][size_t(e)]] = 1;
                    m_boundary[level.faces[f][size_t((e + 1) % 3)]] = 1;
                }
    }

    bool boundary(uint32_t v) const { return m_boundary[v] != 0; }
    // Edges at v: the faces around it, plus one on a boundary.
    int valence(uint32_t v) const
    {
        const int faces = int(m_level.vertex_face_start[v + 1] - m_level.vertex_face_start[v]);
        return faces + (boundary(v) ? 1 : 0);
    }

    // x of the face (v, from, x) around v, or kNoFace: the next neighbour of v after
    // `from`, counter-clockwise.
    uint32_t next_around(uint32_t v, uint32_t from) const
    {
        for (uint32_t i = m_level.vertex_face_start[v]; i < m_level.vertex_face_start[v + 1]; ++i) {
            const auto& face = m_level.faces[m_level.vertex_faces[i]];
            for (int k = 0; k < 3; ++k)
                if (face[size_t(k)] == v && face[size_t((k + 1) % 3)] == from)
                    return face[size_t((k + 2) % 3)];
        }
        return kNoFace;
    }

    // The boundary neighbour of boundary vertex v other than w (along the boundary), or
    // kNoFace.
    uint32_t boundary_neighbour(uint32_t v, uint32_t w) const
    {
        for (uint32_t i = m_level.vertex_face_start[v]; i < m_level.vertex_face_start[v + 1]; ++i) {
            const uint32_t f = m_level.vertex_faces[i];
            for (int e = 0; e < 3; ++e) {
                if (m_level.across[f][size_t(e)] != kNoFace)
                    continue;
                const uint32_t a = m_level.faces[f][size_t(e)];
                const uint32_t b = m_level.faces[f][size_t((e + 1) % 3)];
                if (a == v && b != w)
                    return b;
                if (b == v && a != w)
                    return a;
            }
        }
        return kNoFace;
    }

private:
    const FaceLevel& m_level;
    std::vector<uint8_t> m_boundary;
};

// Zorin et al.'s stencil of an interior vertex v of valence k != 6 for its edge to w:
// 3/4 v + sum_j s_j v_j, the neighbours v_j counted around v from v_0 = w. False if the
// ring is open (a boundary vertex).
bool extraordinary_point(
    const FaceLevel& level, const VertexRings& rings, uint32_t v, uint32_t w, Imath::V3d& out)
{
    const int k = rings.valence(v);
    std::vector<uint32_t> ring { w };
    while (int(ring.size()) < k) {
        const uint32_t next = rings.next_around(v, ring.back());
        if (next == kNoFace)
            return false;
        ring.push_back(next);
    }
    out = Imath::V3d(level.vertices[v]) * 0.75;
    for (int j = 0; j < k; ++j) {
        double s;
        if (k == 3)
            s = j == 0 ? 5.0 / 12.0 : -1.0 / 12.0;
        else if (k == 4)
            s = j == 0 ? 3.0 / 8.0 : j == 2 ? -1.0 / 8.0 : 0.0;
        else {
            const double t = 2.0 * M_PI * double(j) / double(k);
            s = (0.25 + std::cos(t) + 0.5 * std::cos(2.0 * t)) / double(k);
        }
        out += Imath::V3d(level.vertices[ring[size_t(j)]]) * s;
    }
    return true;
}

// The vertex of face `g` that is not on its edge shared with the face it is across from
// (a, b), or kNoFace for no face.
uint32_t apex(const FaceLevel& level, uint32_t g, uint32_t a, uint32_t b)
{
    if (g == kNoFace)
        return kNoFace;
    for (uint32_t v : level.faces[g])
        if (v != a && v != b)
            return v;
    return kNoFace;
}

// The butterfly's new vertex on edge e of face f.
Imath::V3f butterfly_point(const FaceLevel& level, const VertexRings& rings, uint32_t f, int e)
{
    const auto& face = level.faces[f];
    const uint32_t a = face[size_t(e)], b = face[size_t((e + 1) % 3)],
                   c = face[size_t((e + 2) % 3)];
    auto p = [&](uint32_t v) { return Imath::V3d(level.vertices[v]); };
    const uint32_t g = level.across[f][size_t(e)];
    if (g == kNoFace) { // the 4-point scheme along the boundary
        const uint32_t x = rings.boundary_neighbour(a, b), y = rings.boundary_neighbour(b, a);
        if (x == kNoFace || y == kNoFace)
            return Imath::V3f((p(a) + p(b)) * 0.5);
        return Imath::V3f(p(a) * (9.0 / 16.0) + p(b) * (9.0 / 16.0) - p(x) / 16.0 - p(y) / 16.0);
    }
    const uint32_t d = apex(level, g, a, b);
    const bool a_odd = !rings.boundary(a) && rings.valence(a) != 6;
    const bool b_odd = !rings.boundary(b) && rings.valence(b) != 6;
    if (a_odd || b_odd) { // the extraordinary stencils, averaged when both are
        Imath::V3d sum(0.0), one;
        int n = 0;
        if (a_odd && extraordinary_point(level, rings, a, b, one)) {
            sum += one;
            ++n;
        }
        if (b_odd && extraordinary_point(level, rings, b, a, one)) {
            sum += one;
            ++n;
        }
        if (n > 0)
            return Imath::V3f(sum / double(n));
    }
    // The regular 8-point stencil; its wings are the apexes across the faces' other edges.
    uint32_t gw[2], n = 0;
    const auto& gf = level.faces[g];
    for (int k = 0; k < 3; ++k) {
        const uint32_t u = gf[size_t(k)], v = gf[size_t((k + 1) % 3)];
        if ((u == b && v == a) || (u == a && v == b))
            continue;
        gw[n++] = apex(level, level.across[g][size_t(k)], u, v);
    }
    const uint32_t w1 = apex(level, level.across[f][size_t((e + 1) % 3)], b, c);
    const uint32_t w2 = apex(level, level.across[f][size_t((e + 2) % 3)], c, a);
    if (w1 == kNoFace || w2 == kNoFace || n != 2 || gw[0] == kNoFace || gw[1] == kNoFace)
        return Imath::V3f((p(a) + p(b)) * 0.375 + (p(c) + p(d)) * 0.125);
    return Imath::V3f((p(a) + p(b)) * 0.5 + (p(c) + p(d)) * 0.125
        - (p(w1) + p(w2) + p(gw[0]) + p(gw[1])) * 0.0625);
}

} // namespace

FaceLevel subdivide(FaceLevel& coarse, EdgePoints rule)
{
    const size_t nf = coarse.size();
    FaceLevel fine;
    fine.vertices = coarse.vertices;
    const VertexRings rings(coarse);
    // The new vertex of every edge, made once: by the face of lower index.
    std::vector<std::array<uint32_t, 3>> edge_vertex(nf, { kNoFace, kNoFace, kNoFace });
    for (uint32_t f = 0; f < nf; ++f)
        for (int e = 0; e < 3; ++e) {
            const uint32_t g = coarse.across[f][size_t(e)];
            const uint32_t a = coarse.faces[f][size_t(e)], b = coarse.faces[f][size_t((e + 1) % 3)];
            if (g != kNoFace && g < f) {
                for (int k = 0; k < 3; ++k)
                    if (coarse.faces[g][size_t(k)] == b
                        && coarse.faces[g][size_t((k + 1) % 3)] == a)
                        edge_vertex[f][size_t(e)] = edge_vertex[g][size_t(k)];
                continue;
            }
            edge_vertex[f][size_t(e)] = uint32_t(fine.vertices.size());
            fine.vertices.push_back(rule == EdgePoints::Midpoint
                    ? (coarse.vertices[a] + coarse.vertices[b]) * 0.5f
                    : butterfly_point(coarse, rings, f, e));
        }
    fine.faces.resize(4 * nf);
    fine.colour.resize(4 * nf);
    coarse.children.resize(nf);
    for (uint32_t f = 0; f < nf; ++f) {
        const auto& v = coarse.faces[f];
        const auto& m = edge_vertex[f]; // m[e] on the edge from corner e to corner e + 1
        const uint32_t first = 4 * f;
        fine.faces[first] = { m[0], m[1], m[2] };
        fine.faces[first + 1] = { v[0], m[0], m[2] };
        fine.faces[first + 2] = { v[1], m[1], m[0] };
        fine.faces[first + 3] = { v[2], m[2], m[1] };
        const uint8_t colour = coarse.colour.empty() ? 0 : coarse.colour[f];
        fine.colour[first] = colour;
        for (uint32_t k = 1; k < 4; ++k)
            fine.colour[first + k] = uint8_t(1 - colour);
        coarse.children[f] = { first, first + 1, first + 2, first + 3 };
    }
    finish_level(fine);
    return fine;
}

} // namespace texsyn::detail
