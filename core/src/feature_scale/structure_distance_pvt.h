// SPDX-License-Identifier: Apache-2.0
// How far a synthesis's arrangement is from its sample's, and how much it repeats itself:
// what the copying methods use to choose between schedules they cannot tell apart from the
// sample alone.
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

/// How much more `image` repeats itself at the scale of `sample` than the sample does: the
/// image's largest normalised autocorrelation at shifts of 0.5 to 1.5 times the sample's
/// shorter side (at most half the image's), less the sample's own largest at 0.25 to 0.5
/// times it, measured as structure_distance measures; at least 0. About 0 for a new
/// arrangement of the sample's features; copies of the sample side by side give 0.5 or
/// more.
double repetition_excess(const PlanarImage& image, const PlanarImage& sample, int nthreads);

} // namespace texsyn::detail
