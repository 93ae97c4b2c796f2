// SPDX-License-Identifier: Apache-2.0
// What the surface mesh sources share besides surface_mesh_pvt.h: the OBJ and PLY readers'
// common record, PLY headers (read by the PLY reader, and to verify a written file) and the
// edges of a face list.
#pragma once

#include <array>
#include <cstdint>
#include <istream>
#include <numeric>
#include <string>
#include <vector>

#include <OpenImageIO/Imath.h>

namespace texsyn::detail {

/// PLY's scalar types (both spellings of each are read).
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// What a PLY scalar type is: its names, bytes, and the values an ASCII token of it may
/// hold (for float and double alike, float's finite range: vertices are stored as float).
struct PlyTypeTraits {
    const char *name, *alias;
    int size;
    bool integer;
    double low, high;
};
const PlyTypeTraits& ply_type_traits(PlyType type);

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32; ///< of the value (of each item for a list)
    PlyType count_type = PlyType::UInt8;
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
    uint64_t lines = 0; ///< the header's lines, "end_header" included
    std::vector<std::string> comments;

    /// The element called `name`, or null.
    const PlyElement* element(const std::string& name) const;
};

/// Parses a PLY header from the start of `in` (leaving `in` at the first data byte): the
/// magic line, one format line, elements with scalar and list properties of PLY's types,
/// comments, obj_info lines and end_header. False with a reason (no file name) otherwise.
bool read_ply_header(std::istream& in, PlyHeader& header, std::string& reason);

/// The longest line a mesh file may have (a polygon of ~1 million corners): a file of one
/// endless line is refused instead of read into memory whole.
constexpr size_t kMaxMeshLineBytes = 16 << 20;

enum class LineRead { Line, Unterminated, End, TooLong };

/// The next line of `in` without its '\n' (a CR stays): Line, Unterminated (the file ends
/// without a line break after it), End (nothing left), or TooLong (more than
/// kMaxMeshLineBytes; `line` then holds the first kMaxMeshLineBytes).
LineRead read_mesh_line(std::istream& in, std::string& line);

/// "line N: 'TEXT...': longer than 16 MiB (not KIND?)" for a line read_mesh_line() found
/// TooLong; `kind` names what the file should hold ("an OBJ file", "PLY data").
std::string line_too_long(uint64_t number, const std::string& line, const char* kind);

/// "cannot be opened (REASON)" from errno, after a failed open of a mesh file.
std::string cannot_open_mesh();

/// "line N: 'TEXT': " with TEXT cut to a readable length (and without a CR line end).
std::string at_line(uint64_t number, std::string line);

/// Whether `count` exceeds kMaxMeshElements; if so `what` says "has more than ... WHAT".
bool too_many_mesh_elements(uint64_t count, const std::string& what_counted, std::string& what);

/// A mesh file's polygons as the file gives them, before any check of their indices:
/// what the OBJ and PLY readers hand to read_surface_mesh().
struct MeshRecord {
    std::vector<Imath::V3f> points;
    std::vector<int64_t> corners; ///< polygon vertex indices from 0, polygon after polygon
    std::vector<size_t> polygon_start { 0 };
    std::vector<Imath::V2f> corner_uvs; ///< one per corner, or empty
    std::vector<Imath::V2f> vertex_uvs; ///< one per point, or empty

    size_t polygons() const { return polygon_start.size() - 1; }
    /// Ends a polygon whose corners were appended to `corners`.
    void end_polygon() { polygon_start.push_back(corners.size()); }
};

/// Reads a Wavefront OBJ file's v, vt and f lines (every other line, mtllib included, is
/// skipped: no file the mesh names is opened) into `record`, validating every token: a
/// vertex line without three finite numbers, a UV line without finite numbers, a face line
/// with fewer than 3 corners, an index that is not a whole number, 0, before the first
/// vertex or naming a vt line the file does not have, a vertex repeated in one face, corners
/// with and without texture coordinates mixed, and more than kMaxMeshElements vertices,
/// UVs or triangles are refused as soon as read, with "line N: 'TEXT': ..." (no file name)
/// in `what`. Indices beyond the vertices are left for the caller to report.
bool read_obj_record(const std::string& path, MeshRecord& record, std::string& what);

/// Reads a PLY file (ASCII, binary little- or big-endian) into `record`: the vertex
/// element's x, y, z and u, v (or s, t, texture_u, texture_v), the face element's
/// vertex_indices (or vertex_index) list, any integer count type, and a per-face texcoord
/// list (two values per corner, as MeshLab writes it); other elements and properties are
/// read past. Refuses, with a reason in `what` (no file name), a header without those,
/// more than kMaxMeshElements of anything, data that stops before the header's counts
/// end, a negative index, and in ASCII files any token that is not a number of its
/// property's type (an integer in range, a finite float), with its line number.
bool read_ply_record(const std::string& path, MeshRecord& record, std::string& what);

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
