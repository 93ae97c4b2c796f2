// SPDX-License-Identifier: Apache-2.0
// SurfaceMesh's invariants, checked in an order where each check may rely on the ones
// before it (indices in range before areas, areas before edges, edges before fans).
#include <algorithm>
#include <cmath>

#include "mesh_detail_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

// Vertices are named as OBJ numbers them, from 1.
std::string vertex_number(uint32_t v)
{
    return std::to_string(uint64_t(v) + 1);
}

bool finite(const Imath::V3f& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

std::string coordinates(const Imath::V3f& p)
{
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z)
        + ")";
}

bool check_indices(const SurfaceMesh& mesh, std::string& what)
{
    const size_t nv = mesh.vertices.size(), nf = mesh.faces.size();
    if (nv > kMaxMeshElements || nf > kMaxMeshElements || mesh.uvs.size() > kMaxMeshElements) {
        what = "has " + std::to_string(nv) + " vertices, " + std::to_string(nf) + " faces and "
            + std::to_string(mesh.uvs.size()) + " UVs (at most " + std::to_string(kMaxMeshElements)
            + " of each)";
        return false;
    }
    for (size_t f = 0; f < nf; ++f)
        for (uint32_t v : mesh.faces[f])
            if (v >= nv) {
                what = "face " + std::to_string(f + 1) + " refers to vertex " + vertex_number(v)
                    + ", but there are " + std::to_string(nv) + " vertices";
                return false;
            }
    if (mesh.face_uvs.empty())
        return true;
    if (mesh.face_uvs.size() != nf) {
        what = "has UVs for " + std::to_string(mesh.face_uvs.size()) + " faces but "
            + std::to_string(nf) + " faces";
        return false;
    }
    for (size_t f = 0; f < nf; ++f)
        for (uint32_t t : mesh.face_uvs[f])
            if (t >= mesh.uvs.size()) {
                what = "face " + std::to_string(f + 1) + " refers to UV " + vertex_number(t)
                    + ", but there are " + std::to_string(mesh.uvs.size()) + " UVs";
                return false;
            }
    return true;
}

bool check_values(const SurfaceMesh& mesh, std::string& what)
{
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        if (!finite(mesh.vertices[v])) {
            what = "vertex " + vertex_number(uint32_t(v)) + " has a coordinate that is not a "
                + "finite number " + coordinates(mesh.vertices[v]);
            return false;
        }
    for (size_t t = 0; t < mesh.uvs.size(); ++t)
        if (!std::isfinite(mesh.uvs[t].x) || !std::isfinite(mesh.uvs[t].y)) {
            what = "UV " + vertex_number(uint32_t(t)) + " is not a finite number";
            return false;
        }
    std::vector<char> used(mesh.vertices.size(), 0);
    for (const auto& f : mesh.faces)
        used[f[0]] = used[f[1]] = used[f[2]] = 1;
    const auto unused = std::find(used.begin(), used.end(), 0);
    if (unused != used.end()) {
        what = "vertex " + vertex_number(uint32_t(unused - used.begin()))
            + " belongs to no face (a surface mesh uses every vertex: remove unused ones)";
        return false;
    }
    return true;
}

bool check_areas(const SurfaceMesh& mesh, std::string& what)
{
    // Relative to the mesh's size, so that the check means the same in millimetres and
    // kilometres; 1e-12 of the squared diagonal is far below any face a texture can show.
    const double diagonal = bounding_box_diagonal(mesh.vertices);
    const double smallest = 1e-12 * diagonal * diagonal;
    for (const auto& f : mesh.faces) {
        const Imath::V3d p0(mesh.vertices[f[0]]), p1(mesh.vertices[f[1]]), p2(mesh.vertices[f[2]]);
        if (0.5 * ((p1 - p0) % (p2 - p0)).length() <= smallest) {
            what = "the face on vertices " + vertex_number(f[0]) + ", " + vertex_number(f[1]) + ", "
                + vertex_number(f[2])
                + " has zero area (below 1e-12 x the squared bounding-box diagonal)";
            return false;
        }
    }
    return true;
}

std::string edge_name(const EdgeUse& e)
{
    return "the edge between vertices " + vertex_number(e.a) + " and " + vertex_number(e.b);
}

bool check_edges(const SurfaceMesh& mesh, std::string& what)
{
    const std::vector<EdgeUse> uses = sorted_edge_uses(mesh.faces);
    for (size_t i = 0, j; i < uses.size(); i = j) {
        j = edge_end(uses, i);
        if (j - i > 2) {
            what = edge_name(uses[i]) + " is shared by " + std::to_string(j - i)
                + " faces (non-manifold: a surface edge borders at most 2)";
            return false;
        }
    }
    for (size_t i = 0, j; i < uses.size(); i = j) {
        j = edge_end(uses, i);
        if (j - i == 2 && uses[i].forward == uses[i + 1].forward) {
            what = "the faces on either side of " + edge_name(uses[i])
                + " turn opposite ways (inconsistent orientation: every face must be "
                  "counter-clockwise seen from the same side)";
            return false;
        }
    }
    return true;
}

// The faces around each vertex must form one fan: faces that share an edge at the vertex
// are joined, and more than one group is a non-manifold vertex (two cones tip to tip).
bool check_fans(const SurfaceMesh& mesh, std::string& what)
{
    const size_t nv = mesh.vertices.size();
    std::vector<uint32_t> first(nv + 1, 0), incident(mesh.faces.size() * 3);
    for (const auto& f : mesh.faces)
        for (uint32_t v : f)
            ++first[v + 1];
    for (size_t v = 0; v < nv; ++v)
        first[v + 1] += first[v];
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for (size_t f = 0; f < mesh.faces.size(); ++f)
        for (uint32_t v : mesh.faces[f])
            incident[fill[v]++] = uint32_t(f);

    DisjointSets sets;
    std::vector<std::pair<uint32_t, uint32_t>> spokes; // (other vertex, local face)
    for (uint32_t v = 0; v < nv; ++v) {
        const uint32_t begin = first[v], count = first[v + 1] - begin;
        spokes.clear();
        for (uint32_t k = 0; k < count; ++k)
            for (uint32_t w : mesh.faces[incident[begin + k]])
                if (w != v)
                    spokes.emplace_back(w, k);
        std::sort(spokes.begin(), spokes.end());
        sets.reset(count);
        for (size_t s = 1; s < spokes.size(); ++s)
            if (spokes[s].first == spokes[s - 1].first)
                sets.unite(spokes[s].second, spokes[s - 1].second);
        uint32_t fans = 0;
        for (uint32_t k = 0; k < count; ++k)
            fans += sets.find(k) == k;
        if (fans > 1) {
            what = "vertex " + vertex_number(v) + " is where " + std::to_string(fans)
                + " separate fans of faces meet (non-manifold vertex: its faces must form one "
                  "fan)";
            return false;
        }
    }
    return true;
}

bool check_whole(const SurfaceMesh& mesh, std::string& what)
{
    const SurfaceTopology topology = surface_topology(mesh);
    if (topology.components > 1) {
        what = "has " + std::to_string(topology.components)
            + " separate components; texsyn grows one surface at a time (split it)";
        return false;
    }
    if (topology.boundary_edges == 0) {
        double volume = 0; // six times the enclosed volume
        for (const auto& f : mesh.faces)
            volume += Imath::V3d(mesh.vertices[f[0]])
                ^ (Imath::V3d(mesh.vertices[f[1]]) % Imath::V3d(mesh.vertices[f[2]]));
        if (volume <= 0) {
            what = "is a closed surface whose faces face inwards (negative enclosed volume); "
                   "faces must be counter-clockwise seen from outside";
            return false;
        }
    }
    return true;
}

} // namespace

bool check_surface_mesh(const SurfaceMesh& mesh, const std::string& name, std::string& error)
{
    std::string what;
    if (mesh.faces.empty())
        what = "has no faces (a surface needs at least one triangle)";
    else if (check_indices(mesh, what) && check_values(mesh, what) && check_areas(mesh, what)
        && check_edges(mesh, what) && check_fans(mesh, what) && check_whole(mesh, what))
        return true;
    error = name + ": " + what;
    return false;
}

} // namespace texsyn::detail
