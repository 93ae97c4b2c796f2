// SPDX-License-Identifier: Apache-2.0
// The structure distance (autocorrelation windows compared) and the repetition excess.
#include "structure_distance_pvt.h"

#include <algorithm>
#include <cmath>

#include "feature_scale_pvt.h"

namespace texsyn::detail {

namespace {

// The shifts compared: enough to see a feature's shape, few enough to stay cheap.
constexpr int kMinRadius = 4, kMaxRadius = 32;

} // namespace

double structure_distance(
    const PlanarImage& image, const PlanarImage& sample, double feature, int nthreads)
{
    int image_factor = 1, sample_factor = 1;
    const Plane a = measured_luminance(image, nthreads, image_factor);
    const Plane b = measured_luminance(sample, nthreads, sample_factor);
    const int most
        = std::min({ kMaxRadius, a.width() / 2, a.height() / 2, b.width() / 2, b.height() / 2 });
    const int radius
        = std::min(most, std::max(kMinRadius, int(std::lround(feature / sample_factor))));
    const std::vector<double> wa = autocorrelation_window(a, radius, nthreads);
    const std::vector<double> wb = autocorrelation_window(b, radius, nthreads);
    double sum = 0.0;
    for (size_t i = 0; i < wa.size(); ++i)
        sum += (wa[i] - wb[i]) * (wa[i] - wb[i]);
    return std::sqrt(sum / double(wa.size()));
}

double repetition_excess(const PlanarImage& image, const PlanarImage& sample, int nthreads)
{
    int image_factor = 1, sample_factor = 1;
    const Plane a = measured_luminance(image, nthreads, image_factor);
    const Plane b = measured_luminance(sample, nthreads, sample_factor);
    const double side = std::min(b.width(), b.height());
    const double own = autocorrelation_ring_max(b, 0.25 * side, 0.5 * side, nthreads);
    const double scaled = side * sample_factor / image_factor;
    const double repeat = autocorrelation_ring_max(a, 0.5 * scaled, 1.5 * scaled, nthreads);
    return std::max(0.0, repeat - own);
}

} // namespace texsyn::detail
