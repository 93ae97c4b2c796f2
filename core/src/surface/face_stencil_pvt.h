// SPDX-License-Identifier: Apache-2.0
// §3.12: the 2-distant neighbourhood of a face (12 one-distant and 24 two-distant faces),
// ordered in the face's own frame, and its three rotations.
#pragma once

#include <array>
#include <vector>

#include "face_level_pvt.h"

namespace texsyn::detail {

/// Faces in the 2-distant neighbourhood of a face of a regular triangulation.
constexpr int kStencilSlots = 36;

/// The stencil of a regular grid of unit equilateral triangles, seen from a face in its
/// frame: origin at its centroid, x along its edge from corner 0 to corner 1, y into the
/// face. Slots are ordered by ring (12 one-distant, then 24 two-distant), then by angle.
struct StencilShape {
    std::array<Imath::V2f, kStencilSlots> position; ///< centroid of each slot's face
    std::array<int, kStencilSlots> ring;            ///< 1 or 2
    /// permutation[r][s]: the slot that slot s of the frame of corner 0 is in the frame of
    /// corner r (x along corner r to corner r + 1): the stencil turned by -120° r.
    std::array<std::array<int, kStencilSlots>, 3> permutation;
};
const StencilShape& stencil_shape();

/// Each face's neighbours by slot in its corner-0 frame ([face][slot], kNoFace where the
/// slot has no face: beyond a boundary, or a vertex of valence other than 6 left it
/// empty). Each face of the two rings is put in the slot nearest its centroid, projected
/// on the face's plane in units of the face's mean edge length; a slot holds the nearest.
std::vector<std::array<uint32_t, kStencilSlots>> face_stencils(
    const FaceLevel& level, int nthreads);

/// Whether every slot of `slots` holds a face.
bool complete(const std::array<uint32_t, kStencilSlots>& slots);

} // namespace texsyn::detail
