// SPDX-License-Identifier: Apache-2.0
// The parts of the feature-scale estimate: the luminance it measures, the periods of its
// autocorrelation and the octave energies of its power spectrum.
#pragma once

#include <vector>

#include <texsyn/feature_scale.h>
#include <texsyn/image.h>

namespace texsyn::detail {

/// The plane the estimate measures (feature_scale.h's rules): the luminance of `sample`,
/// reduced by 2 until its shorter side is at most 1024 (`factor` receives 2^reductions),
/// its illumination divided out, encoded with a 1/2.2 power. Empty if the sample has no
/// colour channel.
Plane measured_luminance(const PlanarImage& sample, int nthreads, int& factor);

/// The normalised autocorrelation of `plane` along each axis (linear, not circular: each
/// shift's products divided by their count): `along_x[d]` at shift (d, 0) and `along_y[d]`
/// at (0, d), for d = 0 .. half the side, each the mean of the rows (columns) at offsets
/// -1, 0, 1 across the axis. Both start at 1; a constant plane gives zeros after it.
void axis_autocorrelation(
    const Plane& plane, int nthreads, std::vector<double>& along_x, std::vector<double>& along_y);

/// The normalised linear autocorrelation of `plane` at every shift (dx, dy) with |dx|, |dy|
/// at most `radius` (and less than the plane's sides), row by row from (-r, -r): 1 at the
/// centre; all zeros for a constant plane.
std::vector<double> autocorrelation_window(const Plane& plane, int radius, int nthreads);

/// The largest normalised linear autocorrelation of `plane` at a shift whose length is
/// between `inner` and `outer` pixels and whose components are at most half the plane's
/// sides; 0 if there is none or the plane is constant.
double autocorrelation_ring_max(const Plane& plane, double inner, double outer, int nthreads);

/// The repeat of a profile from axis_autocorrelation (FeatureScale::period_x's rule), with
/// sub-pixel precision; 0 with `strength` 0 if there is none.
double profile_period(const std::vector<double>& profile, double& strength);

/// FeatureScale::spectral_size (`largest`) and finest_size (`finest`) of `plane`, in its
/// pixels.
struct SpectralSizes {
    double largest = 1.0, finest = 1.0;
};
SpectralSizes spectral_sizes(const Plane& plane, int nthreads);

} // namespace texsyn::detail
