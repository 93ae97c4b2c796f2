// SPDX-License-Identifier: Apache-2.0
// The surface a texture grows on (issue #17, Castellanos & Williams §3.4-3.10), as plain
// arrays: reading and checking OBJ and PLY meshes, isotropic remeshing (§3.9), closest
// points on a surface (for baking remeshed geometry back to the input's UVs), and the
// face-coloured PLY output. OpenMesh stays inside the .cpp files.
//
// For every function here: failures return false with one line in `error` that names the
// file (or the parameter), what was found and what was expected; nothing throws
// (std::bad_alloc included) but SurfaceProjector's constructor; an output argument is
// left empty on failure. Vertices in messages are numbered from 1, in file order (as OBJ
// numbers them). Everything is serial and deterministic: the same input gives the same
// output, bit for bit.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
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

/// Reads a Wavefront OBJ or a PLY (ASCII or binary) file with texsyn's own readers,
/// chosen by the extension (.obj, .ply, any case). Polygons become triangle fans from their
/// first corner. UVs: OBJ's per-corner `f v/vt` or PLY's per-face texcoord lists (a vertex
/// on a UV seam keeps one UV per side; equal values become one UV), or PLY's per-vertex
/// u,v (face_uvs are then the faces); none if the file has none. No other file is opened
/// (an OBJ's mtllib is not read). Fails, naming the file, if it is missing or not a regular
/// file, has another extension, is truncated, has more than kMaxMeshElements vertices,
/// faces or UVs, a face with fewer than 3 vertices, an index that is not a number, out of
/// range or repeated in one face, texture coordinates on some faces only, a token that is
/// not a number of its type (with its line), or fails check_surface_mesh(). Nothing is
/// repaired: a face another reader would drop or re-attach is refused.
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

/// Remeshing backends: OpenMesh (texsyn's own remesher, BSD-3, always built) and
/// CGAL's isotropic_remeshing (GPL-3.0-or-later; only in -DTEXSYN_WITH_CGAL=ON builds, for
/// comparison: the same algorithm, its own details; CGAL projects onto the mesh it is
/// given, so each of 3 runs restarts from the input with L corrected by the last, which
/// follows the face count less closely).
enum class RemeshBackend { OpenMesh, Cgal };

/// Whether this build of texsyn contains `backend`.
bool remesh_backend_available(RemeshBackend backend);

/// Isotropic remeshing (Botsch & Kobbelt 2004, the remesher §3.9 asks for: faces of nearly
/// equal area, nearly equilateral, valences near 6) with OpenMesh's topological operators.
/// `iterations` rounds of: split edges longer than 4/3 L, collapse edges shorter than 4/5 L
/// where OpenMesh's link condition allows it and no edge longer than 4/3 L or turned-over
/// face results, flip edges towards valence 6 (4 on the boundary), tangential (uniform
/// Laplacian) relaxation, and projection of every vertex onto the input (onto the closest
/// input face facing its way; boundary vertices onto the input's boundary, which they
/// never leave). L starts from the input's area and `target_faces` (equilateral faces:
/// sqrt(3)/4 L^2 each) and follows the face count after each round, so that the result
/// has target_faces within a few percent after about 5 rounds. Keeps the input's topology
/// (genus, boundary loops, one component). Parts thinner than about L (the cow's tail at
/// 4000 faces) come out as a few slivers. `output` has no UVs: map its points to the
/// input's with SurfaceProjector. Fails if `input` fails check_surface_mesh(), if
/// target_faces is outside 8..kMaxMeshElements or iterations outside 1..100, if `backend`
/// is not built in, or if the result fails check_surface_mesh() (a target too coarse for
/// the shape).
bool remesh_isotropic(const SurfaceMesh& input, size_t target_faces, SurfaceMesh& output,
    std::string& error, int iterations = 10, RemeshBackend backend = RemeshBackend::OpenMesh);

/// A point on a mesh: the face it lies in, its barycentric coordinates for that face's
/// corners (in the face's vertex order; non-negative, summing to 1), its position and its
/// distance to the query point.
struct SurfacePoint {
    uint32_t face = 0;
    Imath::V3f barycentric { 1, 0, 0 };
    Imath::V3f position { 0, 0, 0 };
    float distance = 0;
};

/// Exact closest points on a mesh: a kd-tree over face centroids proposes the candidates,
/// closest-point-on-triangle decides (in double precision; among faces at the same distance,
/// the lowest index wins). A query costs more when the mesh has a few faces much larger
/// than the others (every face within the largest face's reach is a candidate).
/// Thread safety: immutable after construction; const methods may be called concurrently.
class SurfaceProjector {
public:
    /// Indexes `mesh`, which must have at least one face, indices in range, and must
    /// outlive the projector unchanged. May throw std::bad_alloc.
    explicit SurfaceProjector(const SurfaceMesh& mesh);
    ~SurfaceProjector();

    /// The point of the mesh closest to `p`.
    SurfacePoint closest_point(const Imath::V3f& p) const;

    /// The point closest to `p` among the faces that face the way `normal` does (face
    /// normal within 90 degrees of it): a point just off a part thinner than its distance
    /// to it then finds its own side. False if no face faces that way.
    bool closest_facing_point(
        const Imath::V3f& p, const Imath::V3f& normal, SurfacePoint& point) const;

    /// The point of the mesh's boundary (edges with one face) closest to `p`, in that
    /// edge's face. False if the mesh is closed.
    bool closest_boundary_point(const Imath::V3f& p, SurfacePoint& point) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

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
