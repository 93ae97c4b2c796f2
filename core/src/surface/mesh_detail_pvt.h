// SPDX-License-Identifier: Apache-2.0
// What the surface mesh sources share besides surface_mesh_pvt.h: PLY headers (read to
// check a file before OpenMesh reads it, and to verify a written one) and the edges of a
// face list.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <numeric>
#include <string>
#include <vector>

namespace texsyn::detail {

struct PlyProperty {
    std::string name;
    int size = 0;       ///< bytes of one value (of each list item for a list)
    int count_size = 0; ///< 0 for a scalar; bytes of the item count for a list
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    enum class Format { Ascii, BinaryLittleEndian, BinaryBigEndian };
    Format format = Format::Ascii;
    std::vector<PlyElement> elements;
    uint64_t bytes = 0; ///< the header's length, up to and including "end_header\n"
    std::vector<std::string> comments;

    /// The element called `name`, or null.
    const PlyElement* element(const std::string& name) const;
};

/// Parses a PLY header from the start of `in` (leaving `in` at the first data byte): the
/// magic line, one format line, elements with scalar and list properties of PLY's types,
/// comments, obj_info lines and end_header. False with a reason (no file name) otherwise.
bool read_ply_header(std::istream& in, PlyHeader& header, std::string& reason);

/// What a mesh file announces, from a pass over it that allocates nothing per element:
/// OBJ's v, vt and f lines (and the triangles its faces fan into), or a PLY header's vertex
/// and face counts (triangles unknown: 0).
struct MeshFileCounts {
    uint64_t vertices = 0, texcoords = 0, faces = 0, triangles = 0;
    bool face_texcoords = false; ///< OBJ faces give `v/vt` corners
};

/// Checks an OBJ file line by line before OpenMesh reads it, for what OpenMesh's reader
/// would drop or guess silently: a vertex line without three finite numbers, a face line
/// with fewer than 3 corners, an index that is not a number, 0 or before the first vertex,
/// a vertex repeated in one face, corners with and without texture coordinates mixed, and
/// more than kMaxMeshElements vertices, UVs or triangles (refused as soon as counted).
/// False with "line N: ..." (no file name) otherwise.
bool prescan_obj(const std::string& path, MeshFileCounts& counts, std::string& what);

/// Checks a PLY file's header before OpenMesh reads it: a vertex element with x, y, z, a
/// face element with a vertex_indices (or vertex_index) list, at most kMaxMeshElements
/// of each, and enough data for them (binary: the bytes the smallest faces take; ASCII:
/// one line per element, the last one ended). False with a reason (no file name) otherwise.
bool prescan_ply(const std::string& path, MeshFileCounts& counts, std::string& what);

/// One face's use of an edge: the edge's vertices (a < b), the face, and whether the face
/// goes from a to b (forward) or from b to a.
struct EdgeUse {
    uint32_t a = 0, b = 0, face = 0;
    bool forward = false;
};

/// Every (face, edge) pair of `faces`, sorted by (a, b, face): the uses of one edge are
/// consecutive, and the order depends on nothing but the faces.
std::vector<EdgeUse> sorted_edge_uses(const std::vector<std::array<uint32_t, 3>>& faces);

/// The index past the last use of the edge whose uses start at `i` in sorted uses: an edge
/// has (edge_end(uses, i) - i) faces, 1 on the boundary.
inline size_t edge_end(const std::vector<EdgeUse>& uses, size_t i)
{
    size_t j = i + 1;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b)
        ++j;
    return j;
}

#if TEXSYN_HAVE_CGAL
/// CGAL's isotropic_remeshing of `input` (checked) at target edge length `length`, for
/// `iterations` rounds (remesh_cgal.cpp, GPL). May throw what CGAL throws.
struct SurfaceMesh;
void remesh_with_cgal(const SurfaceMesh& input, double length, int iterations, SurfaceMesh& output);
#endif

/// Union-find over 0..n-1 with path halving; a set's representative is its lowest member.
class DisjointSets {
public:
    explicit DisjointSets(size_t n = 0) { reset(n); }

    /// n singletons again (reusing the storage).
    void reset(size_t n)
    {
        m_parent.resize(n);
        std::iota(m_parent.begin(), m_parent.end(), uint32_t(0));
    }
    uint32_t find(uint32_t x)
    {
        while (m_parent[x] != x) {
            m_parent[x] = m_parent[m_parent[x]];
            x = m_parent[x];
        }
        return x;
    }
    void unite(uint32_t a, uint32_t b)
    {
        a = find(a);
        b = find(b);
        if (a < b)
            m_parent[b] = a;
        else if (b < a)
            m_parent[a] = b;
    }

private:
    std::vector<uint32_t> m_parent;
};

} // namespace texsyn::detail
