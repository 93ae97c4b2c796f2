// SPDX-License-Identifier: Apache-2.0
// How far a synthesis's arrangement is from its sample's: what the copying methods use to
// choose between schedules they cannot tell apart from the sample alone.
#pragma once

#include <texsyn/image.h>

namespace texsyn::detail {

/// The RMS difference of the normalised autocorrelations of `image` and `sample` over the
/// shifts up to `feature` pixels each way (at least 4, at most 32), both measured as the
/// feature-scale estimate measures a sample (feature_scale.h: luminance, illumination
/// divided out, 1/2.2 power). 0 for the same arrangement; a shuffle of the sample's pixels
/// gives about 0.1–0.3. Both must have colour channels and the same reduction (shorter
/// sides at most 1024); deterministic whatever `nthreads`.
double structure_distance(
    const PlanarImage& image, const PlanarImage& sample, double feature, int nthreads);

} // namespace texsyn::detail
