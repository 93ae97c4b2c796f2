// SPDX-License-Identifier: Apache-2.0
// Castellanos & Williams' Algorithm 1 on a triangle mesh (§3.2, §3.10, §4).
#pragma once

#include <string>
#include <vector>

#include <texsyn/choosy.h>
#include <texsyn/surface.h>

#include "face_filter_pvt.h"

namespace texsyn::detail {

/// A texture grown on a mesh: the synthesis pyramid (levels[0] the base mesh, two-coloured;
/// each finer level its butterfly subdivision) and the colours of the finest level's faces.
struct SurfaceSynthesis {
    FacePyramid pyramid;
    FaceValues colours; ///< [channel][face of pyramid.levels.back()], scene-linear
};

/// Grows `sample` (scene-linear channels of one size) over the triangle mesh `base` with
/// `opt` (levels, iterations (finest first), penalty, search, dims, eps, seed, nthreads,
/// progress; width, height and isotropic do not apply: a surface has no global
/// orientation, so the sample is seen in six rotations, §3.8). The sample is cropped to a
/// multiple of 2^(levels-1) on each side. Fails (false, `error` naming the option) when
/// the sample is too small for `levels`. Bit-identical for a seed whatever nthreads is.
/// `boundary`: what slots past a mesh boundary hold (make_surface_target).
bool synthesize_on_surface(const std::vector<Plane>& sample, FaceLevel base,
    const ChoosyOptions& opt, SurfaceSynthesis& out, std::string& error,
    BoundarySlots boundary = BoundarySlots::Own);

} // namespace texsyn::detail
