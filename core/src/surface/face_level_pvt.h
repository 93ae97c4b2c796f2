// SPDX-License-Identifier: Apache-2.0
// The geometry of Castellanos & Williams' surface pyramids (§3.4–3.8): a triangle mesh
// whose faces play the part of pixels, its 1-to-4 subdivisions with parent -> children
// indices, the two-colouring that down- and upsampling follow, and the flat triangular
// grids the sample is mapped onto.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <OpenImageIO/Imath.h>

#include <texsyn/image.h>

namespace texsyn::detail {

/// No face (across a boundary edge, an empty stencil slot).
constexpr uint32_t kNoFace = UINT32_MAX;

/// One level of a face pyramid.
struct FaceLevel {
    std::vector<Imath::V3f> vertices;
    /// Corners, counter-clockwise seen from outside.
    std::vector<std::array<uint32_t, 3>> faces;
    /// §3.5's type of each face: 0 black, 1 white. Below the base, inherited: the centre
    /// child keeps its parent's, the corner children take the other.
    std::vector<uint8_t> colour;
    /// Children at the next finer level: [0] the centre child, [1 + e] the child at corner
    /// e. Empty at the finest level.
    std::vector<std::array<uint32_t, 4>> children;

    // Derived from vertices and faces by finish_level():
    /// The face across edge e (corner e to corner e + 1), kNoFace on a boundary.
    std::vector<std::array<uint32_t, 3>> across;
    std::vector<Imath::V3f> centroid;
    std::vector<Imath::V3f> normal; ///< unit
    std::vector<float> area;
    /// Faces around vertex v: vertex_faces[vertex_face_start[v] .. vertex_face_start[v+1]).
    std::vector<uint32_t> vertex_face_start, vertex_faces;
    /// Over edge-adjacent face pairs: the mean and largest centroid distance (§3.6, §3.10).
    double mean_adjacent_distance = 0.0;
    double max_adjacent_distance = 0.0;
    double mean_edge_length = 0.0;

    size_t size() const { return faces.size(); }
};

/// Fills the derived members of `level` from its vertices and faces. The mesh must be an
/// edge-manifold, consistently oriented triangle mesh (surface_mesh_pvt.h checks inputs).
void finish_level(FaceLevel& level);

/// Where subdivision puts the vertex it adds on an edge.
enum class EdgePoints {
    Midpoint,  ///< the edge's midpoint (flat grids: the same as the butterfly there)
    Butterfly, ///< Zorin, Schröder & Sweldens' modified butterfly (§3.4)
};

/// One 1-to-4 subdivision of `coarse`: a vertex on every edge, each face split into its
/// centre child and three corner children; fills coarse.children and returns the finer
/// level, finished, with colours inherited. Existing vertices keep their positions and
/// indices (the scheme interpolates).
FaceLevel subdivide(FaceLevel& coarse, EdgePoints rule);

/// §3.5: colours the faces of `level` black and white so that as few edge-adjacent pairs
/// as possible share a colour (none where the face graph allows it: every interior vertex
/// of even valence). Deterministic. Returns the number of edge-adjacent same-colour pairs.
size_t two_colour(FaceLevel& level);

/// A base mesh and its subdivisions: levels[0] the coarsest (G0 of the paper), levels.back()
/// the finest.
struct FacePyramid {
    std::vector<FaceLevel> levels;
    size_t colour_conflicts = 0; ///< same-colour edge-adjacent pairs of the base
};

/// Two-colours `base` and subdivides it `levels - 1` times with `rule`.
FacePyramid build_face_pyramid(FaceLevel base, int levels, EdgePoints rule);

/// §3.8: the flat grid of equilateral triangles a `width` x `height` image is mapped onto
/// for `levels` levels: its finest level has one row of triangles per image row (height
/// a multiple of 2^(levels-1)) and is no wider than the image, and it is `levels - 1`
/// midpoint subdivisions of a coarse grid of congruent triangles. In image units: one
/// row of triangles is one pixel high, x to the right, y down, z = 0.
FacePyramid triangular_grid(int width, int height, int levels);

/// Bilinear samples of `image` (every channel) at the centroids of `level` (in image
/// units, pixel centres at half integers, clamped at the edges): [channel][face].
std::vector<std::vector<float>> sample_at_centroids(
    const std::vector<Plane>& image, const FaceLevel& level);

} // namespace texsyn::detail
