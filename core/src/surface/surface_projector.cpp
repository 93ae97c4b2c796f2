// SPDX-License-Identifier: Apache-2.0
// Exact closest points on a mesh. A kd-tree over face centroids finds the candidates: every
// point of a face lies within `reach` (the largest centroid-to-corner distance) of its
// centroid, so the face closest to p has its centroid within (best distance so far +
// reach) of p. The search's radius shrinks as exact distances come in; a nanoflann result
// set of our own does that inside one tree traversal.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include <nanoflann.hpp>

#include <Imath/ImathBox.h>

#include "closest_point_pvt.h"
#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

using Imath::V3d;

SurfacePoint make_point(uint32_t face, const V3d& bary, const V3d& position, double distance)
{
    SurfacePoint s;
    s.face = face;
    s.barycentric = Imath::V3f(bary);
    s.position = Imath::V3f(position);
    s.distance = float(distance);
    return s;
}

} // namespace

struct SurfaceProjector::Impl {
    // nanoflann's dataset concept over points stored as float, relative to the mesh's centre
    // (float keeps ~7 digits of the offset from the centre, not of a far-away origin).
    struct CentrePoints {
        std::vector<Imath::V3f> points;
        size_t kdtree_get_point_count() const { return points.size(); }
        float kdtree_get_pt(uint32_t i, size_t d) const { return points[i][int(d)]; }
        template <class BoundingBox>
        bool kdtree_get_bbox(BoundingBox&) const
        {
            return false;
        }
    };

    using CentreTree
        = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, CentrePoints>,
            CentrePoints, 3, uint32_t>;

    // A kd-tree over the centres of primitives (faces or boundary edges) and the exact search.
    struct PrimitiveIndex {
        CentrePoints centres;
        double reach = 0;
        std::unique_ptr<CentreTree> tree;

        void build() { tree = std::make_unique<CentreTree>(3, centres); }
    };

    // nanoflann's result-set concept: offered each primitive whose centre lies within
    // worstDist() of the query, keeps the exactly closest one (the lowest index among equals).
    template <class Exact>
    struct ClosestPrimitive {
        ClosestPrimitive(const Exact& e, double r, double s)
            : exact(e)
            , reach(r)
            , slack(s)
        { }

        const Exact& exact; // (index, SurfacePoint&) -> distance
        double reach, slack;
        double best = std::numeric_limits<double>::infinity();
        uint32_t best_index = std::numeric_limits<uint32_t>::max();
        SurfacePoint point;

        bool addPoint(float, uint32_t index)
        {
            SurfacePoint candidate;
            const double d = exact(index, candidate);
            if (d < best || (d == best && index < best_index)) {
                best = d;
                best_index = index;
                point = candidate;
            }
            return true;
        }
        float worstDist() const
        {
            if (!std::isfinite(best))
                return std::numeric_limits<float>::max();
            const double r = best + reach + slack;
            return float(r * r);
        }
        bool full() const { return true; }
    };

    struct BoundaryEdge {
        uint32_t face;
        int corner; // the edge goes from this corner of the face to the next
    };

    const SurfaceMesh& mesh;
    V3d centre;
    double slack = 0; // covers float rounding of the centres and of the query
    PrimitiveIndex faces, boundary;
    std::vector<BoundaryEdge> boundary_edges;

    explicit Impl(const SurfaceMesh& m)
        : mesh(m)
    {
        Imath::Box3d box;
        for (const Imath::V3f& v : mesh.vertices)
            box.extendBy(V3d(v));
        centre = box.center();
        slack = 1e-5 * (box.max - box.min).length();

        faces.centres.points.reserve(mesh.faces.size());
        for (const auto& f : mesh.faces) {
            const V3d c = (position(f[0]) + position(f[1]) + position(f[2])) / 3.0;
            faces.centres.points.emplace_back(c - centre);
            for (uint32_t v : f)
                faces.reach = std::max(faces.reach, (position(v) - c).length());
        }
        faces.build();

        const std::vector<EdgeUse> uses = sorted_edge_uses(mesh.faces);
        for (size_t i = 0, j; i < uses.size(); i = j) {
            j = edge_end(uses, i);
            if (j - i != 1)
                continue;
            const auto& f = mesh.faces[uses[i].face];
            const uint32_t from = uses[i].forward ? uses[i].a : uses[i].b;
            const int corner = f[0] == from ? 0 : f[1] == from ? 1 : 2;
            boundary_edges.push_back({ uses[i].face, corner });
            const V3d a = position(from), b = position(f[(corner + 1) % 3]);
            boundary.centres.points.emplace_back((a + b) / 2.0 - centre);
            boundary.reach = std::max(boundary.reach, (b - a).length() / 2);
        }
        if (!boundary_edges.empty())
            boundary.build();
    }

    V3d position(uint32_t v) const { return V3d(mesh.vertices[v]); }

    // Over the faces whose normal points within 90 degrees of `facing` (all if null); false
    // if there is none.
    bool closest_face_point(const Imath::V3f& p, const V3d* facing, SurfacePoint& point) const
    {
        const V3d q(p);
        auto exact = [&](uint32_t f, SurfacePoint& s) {
            const V3d a = position(mesh.faces[f][0]), b = position(mesh.faces[f][1]),
                      c = position(mesh.faces[f][2]);
            if (facing && (((b - a) % (c - a)) ^ *facing) <= 0)
                return std::numeric_limits<double>::infinity();
            V3d bary;
            const V3d x = closest_on_triangle(q, a, b, c, bary);
            const double d = (x - q).length();
            s = make_point(f, bary, x, d);
            return d;
        };
        return search(faces, p, exact, point);
    }

    template <class Exact>
    bool search(const PrimitiveIndex& index, const Imath::V3f& p, const Exact& exact,
        SurfacePoint& point) const
    {
        ClosestPrimitive<Exact> result(exact, index.reach, slack);
        const Imath::V3f query(V3d(p) - centre);
        index.tree->findNeighbors(result, &query.x, nanoflann::SearchParams());
        if (!std::isfinite(result.best))
            return false;
        point = result.point;
        return true;
    }
};

SurfaceProjector::SurfaceProjector(const SurfaceMesh& mesh)
    : m_impl(std::make_unique<Impl>(mesh))
{ }

SurfaceProjector::~SurfaceProjector() = default;

SurfacePoint SurfaceProjector::closest_point(const Imath::V3f& p) const
{
    SurfacePoint point;
    m_impl->closest_face_point(p, nullptr, point);
    return point;
}

bool SurfaceProjector::closest_facing_point(
    const Imath::V3f& p, const Imath::V3f& normal, SurfacePoint& point) const
{
    const V3d n(normal);
    return m_impl->closest_face_point(p, &n, point);
}

bool SurfaceProjector::closest_boundary_point(const Imath::V3f& p, SurfacePoint& point) const
{
    const Impl& m = *m_impl;
    if (m.boundary_edges.empty())
        return false;
    const V3d q(p);
    auto exact = [&](uint32_t e, SurfacePoint& s) {
        const Impl::BoundaryEdge& edge = m.boundary_edges[e];
        const auto& face = m.mesh.faces[edge.face];
        const V3d a = m.position(face[edge.corner]), b = m.position(face[(edge.corner + 1) % 3]);
        const V3d ab = b - a;
        const double t = std::clamp(((q - a) ^ ab) / (ab ^ ab), 0.0, 1.0);
        const V3d c = a + t * ab;
        V3d bary(0, 0, 0);
        bary[edge.corner] = 1 - t;
        bary[(edge.corner + 1) % 3] = t;
        const double d = (c - q).length();
        s = make_point(edge.face, bary, c, d);
        return d;
    };
    return m.search(m.boundary, p, exact, point);
}

} // namespace texsyn::detail
