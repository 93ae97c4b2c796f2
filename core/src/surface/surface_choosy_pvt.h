// SPDX-License-Identifier: Apache-2.0
// Choosy sampling on a surface (§3.8, §3.10–3.12): the sample's pyramids on the two
// triangular grids as AnalysisPoints, and a level of the synthesis mesh as a ChoosyTarget.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "choosy/choosy_pvt.h"
#include "face_filter_pvt.h"
#include "face_stencil_pvt.h"

namespace texsyn::detail {

using FaceStencils = std::vector<std::array<uint32_t, kStencilSlots>>;

/// The sample mapped on the 0° and 90° grids (§3.8) and their Gaussian and Laplacian
/// pyramids (levels[0] coarsest), with the faces whose whole stencil lies in the grid.
struct SurfaceAnalysis {
    std::array<FacePyramid, 2> grids;
    std::array<std::vector<FaceValues>, 2> gaussian;   ///< [grid][level]
    std::array<std::vector<FaceValues>, 2> laplacian;  ///< [grid][level]; empty at level 0
    std::array<std::vector<FaceStencils>, 2> stencils; ///< [grid][level]
    /// [level]: the sites of choosy sampling, as grid << 31 | face.
    std::vector<std::vector<uint32_t>> sites;
};

/// Maps `sample` (channels of equal size, sides multiples of 2^(levels-1)) on both grids and
/// builds their pyramids with `kernels[level]` (the fine level's kernel of each reduce and
/// project; scale 1: the grids are in the sample's units).
SurfaceAnalysis analyze_surface_sample(const std::vector<Plane>& sample, int levels,
    const std::vector<FaceKernel>& kernels, int nthreads);

/// §3.12's weights beta (eq. 7) of the stencil slots at a level whose mean edge length is
/// `edge` and kernel `sigma`, both in the sample's units.
std::array<float, kStencilSlots> stencil_weights(double edge, double sigma);

/// The sites of `analysis` at `level`, each in the three rotations of its frame (point p:
/// site p / 3, rotation p % 3), as weighted neighbourhoods.
AnalysisPoints surface_points(
    const SurfaceAnalysis& analysis, int level, const std::array<float, kStencilSlots>& weights);

/// One level of the synthesis mesh being synthesized: its Gaussian values and, below the
/// finest, the Laplacian values of the next level that choices fill.
struct SurfaceLevel {
    const FaceLevel* geometry = nullptr;
    const FaceStencils* stencils = nullptr;
    FaceValues gaussian;          ///< [channel][face]
    FaceValues children;          ///< [channel][face of the next level]; empty at the finest
    std::vector<uint32_t> source; ///< the analysis site each face copied
};

/// `out` as a ChoosyTarget over `analysis` at `level`. A slot with no face takes the face's
/// own value; with `wildcards`, one past a boundary is a wildcard instead (§3.12): its
/// difference to every point is zero (ChoosyTarget::wildcards). Its slots count as past a
/// boundary when a corner of the face, or of a face of its stencil, is on a boundary. An
/// empty slot elsewhere is an irregular vertex, where the surface closes up: it always
/// takes the face's own value, so a closed mesh has no wildcards.
std::unique_ptr<ChoosyTarget> make_surface_target(SurfaceLevel& out,
    const SurfaceAnalysis& analysis, int level, const std::array<float, kStencilSlots>& weights,
    bool wildcards);

} // namespace texsyn::detail
