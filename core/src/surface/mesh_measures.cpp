// SPDX-License-Identifier: Apache-2.0
// Topology counts and shape measures of triangle meshes (in double precision).
#include <algorithm>
#include <cmath>
#include <limits>

#include <Imath/ImathBox.h>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

Imath::V3d corner(const SurfaceMesh& mesh, uint32_t v)
{
    return Imath::V3d(mesh.vertices[v]);
}

} // namespace

double bounding_box_diagonal(const std::vector<Imath::V3f>& vertices)
{
    if (vertices.empty())
        return 0;
    Imath::Box3d box;
    for (const Imath::V3f& v : vertices)
        box.extendBy(Imath::V3d(v));
    return (box.max - box.min).length();
}

SurfaceTopology surface_topology(const SurfaceMesh& mesh)
{
    SurfaceTopology t;
    t.vertices = mesh.vertices.size();
    t.faces = mesh.faces.size();

    // The face-side half-edge of each boundary edge, by the vertex it leaves: one per
    // boundary vertex of a vertex-manifold mesh, so that following them walks the loops.
    constexpr uint32_t none = std::numeric_limits<uint32_t>::max();
    std::vector<uint32_t> boundary_next(mesh.vertices.size(), none);
    const std::vector<EdgeUse> uses = sorted_edge_uses(mesh.faces);
    for (size_t i = 0, j; i < uses.size(); i = j) {
        j = edge_end(uses, i);
        ++t.edges;
        if (j - i == 1) {
            ++t.boundary_edges;
            const EdgeUse& u = uses[i];
            boundary_next[u.forward ? u.a : u.b] = u.forward ? u.b : u.a;
        }
    }
    for (uint32_t start = 0; start < boundary_next.size(); ++start) {
        if (boundary_next[start] == none)
            continue;
        ++t.boundary_loops;
        for (uint32_t v = start; boundary_next[v] != none;) {
            const uint32_t next = boundary_next[v];
            boundary_next[v] = none;
            v = next;
        }
    }

    DisjointSets sets(mesh.vertices.size());
    std::vector<char> used(mesh.vertices.size(), 0);
    for (const auto& f : mesh.faces) {
        sets.unite(f[0], f[1]);
        sets.unite(f[0], f[2]);
        used[f[0]] = used[f[1]] = used[f[2]] = 1;
    }
    for (uint32_t v = 0; v < used.size(); ++v)
        t.components += used[v] && sets.find(v) == v;
    return t;
}

MeshQuality mesh_quality(const SurfaceMesh& mesh)
{
    MeshQuality q;
    double min_angle = M_PI;
    size_t small = 0;
    for (const auto& f : mesh.faces) {
        const Imath::V3d p[3] = { corner(mesh, f[0]), corner(mesh, f[1]), corner(mesh, f[2]) };
        q.area += 0.5 * ((p[1] - p[0]) % (p[2] - p[0])).length();
        double face_min = M_PI;
        for (int k = 0; k < 3; ++k) {
            const Imath::V3d a = p[(k + 1) % 3] - p[k], b = p[(k + 2) % 3] - p[k];
            face_min = std::min(face_min, std::atan2((a % b).length(), a ^ b));
        }
        min_angle = std::min(min_angle, face_min);
        small += face_min < M_PI / 6;
    }
    if (!mesh.faces.empty()) {
        q.min_angle_degrees = min_angle * 180 / M_PI;
        q.small_angle_share = double(small) / double(mesh.faces.size());
    }

    const std::vector<EdgeUse> uses = sorted_edge_uses(mesh.faces);
    double sum = 0, sum2 = 0;
    size_t edges = 0;
    for (size_t i = 0; i < uses.size(); i = edge_end(uses, i)) {
        const double length = (corner(mesh, uses[i].a) - corner(mesh, uses[i].b)).length();
        sum += length;
        sum2 += length * length;
        ++edges;
    }
    if (edges > 0) {
        q.mean_edge = sum / double(edges);
        const double variance = std::max(0.0, sum2 / double(edges) - q.mean_edge * q.mean_edge);
        q.edge_spread = q.mean_edge > 0 ? std::sqrt(variance) / q.mean_edge : 0;
    }
    return q;
}

} // namespace texsyn::detail
