// SPDX-License-Identifier: Apache-2.0
// The Laplacian pyramid's operations on face levels (§3.5–3.7).
#pragma once

#include <vector>

#include "face_level_pvt.h"

namespace texsyn::detail {

/// Values on the faces of a level: [channel][face].
using FaceValues = std::vector<std::vector<float>>;

/// The Gaussian of a level (eq. 3): w_ij = exp(-1/2 (d(i,j) / sigma)^2) a_j, d the distance
/// between centroids times `scale` (§3.10: synthesis distances in the sample's units).
struct FaceKernel {
    double sigma = 1.0;
    double scale = 1.0;
};

/// Eq. 4: each face's weighted mean over Ω(i), the faces reached from it through shared
/// edges without leaving 3 sigma; with `only`, over the faces it flags (eq. 6's Γ).
/// Deterministic whatever nthreads.
FaceValues filter_faces(const FaceLevel& level, const FaceValues& values, const FaceKernel& kernel,
    const std::vector<uint8_t>* only, int nthreads);

/// reduce: convolution on `fine`, then each face of `coarse` takes its centre child's value.
FaceValues reduce_faces(const FaceLevel& coarse, const FaceLevel& fine, const FaceValues& values,
    const FaceKernel& kernel, int nthreads);

/// project: the white children of each face of `coarse` take its value, the black ones
/// none, then convolution on `fine` normalised over the white faces (eq. 5–6), so a
/// constant stays that constant.
FaceValues project_faces(const FaceLevel& coarse, const FaceLevel& fine, const FaceValues& values,
    const FaceKernel& kernel, int nthreads);

} // namespace texsyn::detail
