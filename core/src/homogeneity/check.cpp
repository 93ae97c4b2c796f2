// SPDX-License-Identifier: Apache-2.0
// check_homogeneity: the three measures, the score and the warnings.
#include "homogeneity_pvt.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace texsyn {

namespace {

std::string percent(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.0f%%", 100.0 * x);
    return buf;
}

void score_and_warn(HomogeneityReport& r)
{
    const double b = std::max({ r.illumination_amplitude / homogeneity_max_illumination_amplitude,
        r.local_mean_variation / homogeneity_max_local_mean_variation,
        r.local_contrast_variation / homogeneity_max_local_contrast_variation });
    r.score = std::exp2(-b * b);
    r.poor = b > 1.0;
    if (r.illumination_amplitude > homogeneity_max_illumination_amplitude)
        r.warnings.push_back("the lighting varies by " + percent(r.illumination_amplitude)
            + " across the sample (limit " + percent(homogeneity_max_illumination_amplitude) + "), "
            + r.illumination_description
            + ": synthesis will be blotchy; flatten=1 (--pyramid:flatten=1) divides it out");
    if (r.local_mean_variation > homogeneity_max_local_mean_variation)
        r.warnings.push_back("the local mean varies by " + percent(r.local_mean_variation)
            + " between tiles (limit " + percent(homogeneity_max_local_mean_variation)
            + "): synthesis will be blotchy; crop to an evenly lit area, or try flatten=1 if "
              "it is lighting");
    r.uneven_for_copying = r.illumination_amplitude > homogeneity_max_lighting_for_copying
        && r.illumination_planar_fraction >= 0.5
        && r.lighting_share >= homogeneity_min_lighting_share
        && r.lit_out_contrast_variation <= homogeneity_max_contrast_variation_of_lighting;
    if (r.uneven_for_copying && r.illumination_amplitude <= homogeneity_max_illumination_amplitude)
        r.warnings.push_back("the lighting varies by " + percent(r.illumination_amplitude) + ", "
            + r.illumination_description
            + ": the copying methods (patch, neighborhood, choosy, "
              "fill, tileable) will re-tile it as light and dark blocks; flatten=1 divides it "
              "out");
    if (r.local_contrast_variation > homogeneity_max_local_contrast_variation)
        r.warnings.push_back("the local contrast varies by " + percent(r.local_contrast_variation)
            + " between tiles (limit " + percent(homogeneity_max_local_contrast_variation)
            + "): the texture itself changes across the sample (perspective, or different "
              "surfaces); crop to a region where it looks the same");
}

} // namespace

HomogeneityReport check_homogeneity(const PlanarImage& sample, int nthreads)
{
    using namespace homogeneity;
    HomogeneityReport r;
    r.width = sample.width();
    r.height = sample.height();
    if (!has_luminance(sample)) {
        r.score = 0.0;
        r.poor = true;
        r.warnings.push_back("the image is empty (or has no colour channels): nothing to measure");
        return r;
    }
    if (fit_illumination(sample, r.illumination, nthreads))
        describe_illumination(r, nthreads);
    else
        r.illumination_description = "flat";
    measure_local_variation(sample, r, nthreads);
    measure_lighting(sample, r, nthreads);
    score_and_warn(r);
    if (r.tiles_x == 0)
        r.warnings.push_back("the sample is " + std::to_string(r.width) + "x"
            + std::to_string(r.height) + ": too small to compare tiles (needs 16x16)");
    return r;
}

} // namespace texsyn
