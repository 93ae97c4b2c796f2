// SPDX-License-Identifier: Apache-2.0
// estimate_feature_scale(): the periods and the spectral size, combined.
#include "feature_scale_pvt.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace texsyn {

FeatureScale estimate_feature_scale(const PlanarImage& sample, int nthreads)
{
    FeatureScale scale;
    int factor = 1;
    const Plane l = detail::measured_luminance(sample, nthreads, factor);
    if (std::min(l.width(), l.height()) < 4)
        return scale;
    std::vector<double> along_x, along_y;
    detail::axis_autocorrelation(l, nthreads, along_x, along_y);
    double strength_x = 0.0, strength_y = 0.0;
    scale.period_x = factor * detail::profile_period(along_x, strength_x);
    scale.period_y = factor * detail::profile_period(along_y, strength_y);
    scale.period_strength = std::max(strength_x, strength_y);
    const detail::SpectralSizes spectral = detail::spectral_sizes(l, nthreads);
    scale.spectral_size = factor * spectral.largest;
    scale.finest_size = factor * spectral.finest;
    const double largest = 0.5 * std::min(sample.width(), sample.height());
    // A repeating pattern's feature is its repeat (its spectrum's lines say less: an
    // octave-wide band holds a line half an octave either side of it).
    const double size
        = scale.periodic() ? std::max(scale.period_x, scale.period_y) : scale.spectral_size;
    scale.size = std::clamp(size, 1.0, std::max(1.0, largest));
    return scale;
}

std::string describe_feature_scale(const FeatureScale& scale)
{
    char text[160];
    if (scale.periodic())
        std::snprintf(text, sizeof(text), "feature size %.0f px (repeats every %s x %s px)",
            scale.size,
            scale.period_x > 0.0 ? std::to_string(int(std::lround(scale.period_x))).c_str() : "-",
            scale.period_y > 0.0 ? std::to_string(int(std::lround(scale.period_y))).c_str() : "-");
    else
        std::snprintf(text, sizeof(text), "feature size %.0f px", scale.size);
    return text;
}

} // namespace texsyn
