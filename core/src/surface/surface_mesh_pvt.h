// SPDX-License-Identifier: Apache-2.0
// The surface a texture grows on (issue #17, Castellanos & Williams §3.4-3.10), as plain
// arrays: reading and checking OBJ and PLY meshes, isotropic remeshing (§3.9), closest
// points on a surface (for baking remeshed geometry back to the input's UVs), and the
// face-coloured PLY output. OpenMesh stays inside the .cpp files.
//
// For every function here: failures return false with one line in `error` that names the
// file (or the parameter), what was found and what was expected; nothing throws
// (std::bad_alloc included); an output argument is left empty on failure. Vertices in
// messages are numbered from 1, in file order (as OBJ numbers them). Everything is serial
// and deterministic: the same input gives the same output, bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <OpenImageIO/Imath.h>

namespace texsyn::detail {

/// A triangle mesh. A mesh that passed check_surface_mesh() is one connected, edge- and
/// vertex-manifold surface (closed or with boundary loops) whose faces all have non-zero
/// area, turn counter-clockwise seen from outside, and use every vertex.
struct SurfaceMesh {
    std::vector<Imath::V3f> vertices;
    std::vector<std::array<uint32_t, 3>> faces;    // counter-clockwise seen from outside
    std::vector<Imath::V2f> uvs;                   // empty if the file has none
    std::vector<std::array<uint32_t, 3>> face_uvs; // per face corner, into uvs; empty if none
};

/// Most vertices, faces (after triangulation) or UVs a mesh may have: larger counts are
/// refused from the file's header or line counts, before anything is allocated for them.
constexpr size_t kMaxMeshElements = 50'000'000;

/// Reads a Wavefront OBJ or a PLY (ASCII or binary) file through OpenMesh's readers, chosen
/// by the extension (.obj, .ply, any case). Polygons become triangle fans from their first
/// corner. UVs: OBJ's per-corner `f v/vt` (a vertex on a UV seam keeps one UV per side;
/// `vt` lines with equal values become one UV), or PLY's per-vertex u,v (face_uvs are then
/// the faces); none if the file has none. Fails, naming the file, if it is missing or not
/// a regular file, has another extension, is truncated, has more than kMaxMeshElements
/// vertices, faces or UVs, a face line with fewer than 3 vertices, an index that is not a
/// number, out of range or repeated in one face, texture coordinates on some faces only,
/// a coordinate that is not a finite number, or fails check_surface_mesh(). OpenMesh's own
/// messages are silenced while it reads (reads are serialised: OpenMesh's readers keep
/// state), and nothing is repaired: a face OpenMesh would drop or re-attach is refused.
bool read_surface_mesh(const std::string& path, SurfaceMesh& mesh, std::string& error);

/// Whether `mesh` is a surface texsyn can grow a texture on (SurfaceMesh's invariants):
/// at least one face, at most kMaxMeshElements of anything, indices in range (face_uvs
/// empty or one per face), finite coordinates and UVs, every vertex used, no face of area
/// below 1e-12 x the squared bounding-box diagonal, no edge shared by more than two faces,
/// neighbouring faces turning the same way, every vertex's faces forming one fan, one
/// connected component, and, when closed, a positive enclosed volume (faces facing out).
/// `name` starts the message ("NAME: has 3 separate components; ...").
bool check_surface_mesh(const SurfaceMesh& mesh, const std::string& name, std::string& error);

/// Counts that describe a checked mesh's topology.
struct SurfaceTopology {
    size_t vertices = 0, edges = 0, faces = 0;
    size_t boundary_edges = 0, boundary_loops = 0, components = 0;
    /// V - E + F: 2 - 2 genus - boundary loops for one component.
    long euler_characteristic() const { return long(vertices) - long(edges) + long(faces); }
};

/// The topology of a mesh that passed check_surface_mesh() (any mesh with indices in range
/// for the counts; boundary loops are only meaningful on a vertex-manifold mesh).
SurfaceTopology surface_topology(const SurfaceMesh& mesh);

/// Shape measures of a mesh with indices in range: the total area, the smallest angle of
/// any face (degrees), the share of faces with an angle below 30 degrees, and the mean and
/// relative spread (standard deviation / mean) of its edge lengths (each edge counted
/// once), in double precision.
struct MeshQuality {
    double area = 0, min_angle_degrees = 0, small_angle_share = 0;
    double mean_edge = 0, edge_spread = 0;
};
MeshQuality mesh_quality(const SurfaceMesh& mesh);

/// The length of the diagonal of the box bounding all vertices (0 if there are none).
double bounding_box_diagonal(const std::vector<Imath::V3f>& vertices);

/// Writes a binary little-endian PLY for mesh viewers and bakes: `element vertex` (float x
/// y z), `element face` (list uchar int vertex_indices), one float property per channel,
/// named after channel_names (scene-linear values; e.g. "r", "g", "b"), then, if
/// display_rgb is given, uchar red green blue (8-bit sRGB-encoded: the face colours
/// MeshLab and Blender show), and comment lines naming texsyn and these colour spaces.
/// face_channels is [channel][face]. Written atomically (temporary file in the same
/// folder, synced and read back, then renamed); a failed write leaves no file. Fails if
/// `path` does not end in .ply or its folder does not exist, if there are no faces, a
/// face index is out of range, more than 2^31-1 vertices or faces, a non-finite vertex,
/// a channel without one value per face, a channel name that is empty, repeated, not
/// letters, digits and '_', vertex_indices, or red/green/blue when display_rgb is given,
/// or display_rgb without one colour per face.
bool write_face_colour_ply(const std::string& path, const std::vector<Imath::V3f>& vertices,
    const std::vector<std::array<uint32_t, 3>>& faces,
    const std::vector<std::vector<float>>& face_channels,
    const std::vector<std::string>& channel_names,
    const std::vector<std::array<uint8_t, 3>>* display_rgb, std::string& error);

} // namespace texsyn::detail
