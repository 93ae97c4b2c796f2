// SPDX-License-Identifier: Apache-2.0
// The fitted illumination in numbers a user can read: amplitude, direction, shape.
#include "homogeneity_pvt.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace texsyn::homogeneity {

namespace {

// Below this amplitude the fit is called flat and given no direction.
constexpr double kFlatAmplitude = 0.01;

std::string direction_word(double degrees)
{
    static const char* words[8] = { "right", "top right", "top", "top left", "left", "bottom left",
        "bottom", "bottom right" };
    return words[int(std::floor((degrees + 22.5) / 45.0)) % 8];
}

} // namespace

void describe_illumination(HomogeneityReport& report, int nthreads)
{
    const int w = report.width, h = report.height;
    const IlluminationFit& fit = report.illumination;
    const size_t nblocks = size_t((h + rows_per_block - 1) / rows_per_block);
    std::vector<double> lo(nblocks, INFINITY), hi(nblocks, -INFINITY), sum(nblocks, 0.0);
    for_each_row_block(h, nthreads, [&](int b, int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const double g = fit.at(x, y, w, h);
                lo[size_t(b)] = std::min(lo[size_t(b)], g);
                hi[size_t(b)] = std::max(hi[size_t(b)], g);
                sum[size_t(b)] += g;
            }
    });
    double gmin = INFINITY, gmax = -INFINITY, total = 0.0;
    for (size_t b = 0; b < nblocks; ++b) { // block order: same sum at any thread count
        gmin = std::min(gmin, lo[b]);
        gmax = std::max(gmax, hi[b]);
        total += sum[b];
    }
    report.illumination_amplitude = (gmax - gmin) / (total / (double(w) * h));

    const auto& c = fit.coefficients;
    // The mean gradient of a quadratic over the symmetric domain is its linear part; in
    // pixel units (u spans 2/w per pixel), with y turned up for the angle.
    const double gx = c[1] / w, gy_up = -c[2] / h;
    double deg = std::atan2(gy_up, gx) * 180.0 / M_PI;
    report.illumination_direction = deg < 0.0 ? deg + 360.0 : deg;
    // The planar part's range over the pixel centres, against the whole range.
    const double planar = std::abs(c[1]) * (2.0 - 2.0 / w) + std::abs(c[2]) * (2.0 - 2.0 / h);
    const double range = gmax - gmin;
    report.illumination_planar_fraction = range > 0.0 ? std::min(1.0, planar / range) : 0.0;

    char text[96];
    if (report.illumination_amplitude < kFlatAmplitude)
        std::snprintf(text, sizeof(text), "flat");
    else if (report.illumination_planar_fraction >= 0.5)
        std::snprintf(text, sizeof(text), "brighter towards the %s (%.0f deg)",
            direction_word(report.illumination_direction).c_str(),
            std::fmod(std::round(report.illumination_direction), 360.0));
    else // mostly curved: a vignette if the middle is a maximum
        std::snprintf(text, sizeof(text), "%s",
            c[3] + c[5] < 0.0 ? "darker towards the edges (vignette)" : "darker in the middle");
    report.illumination_description = text;
}

} // namespace texsyn::homogeneity
