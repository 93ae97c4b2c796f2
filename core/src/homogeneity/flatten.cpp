// SPDX-License-Identifier: Apache-2.0
#include "homogeneity_pvt.h"

#include <algorithm>

namespace texsyn {

namespace {

// The fitted illumination is clamped to at least this fraction of its mean before
// dividing: a strong fit can extrapolate to zero or below in a corner, and dividing by it
// would blow those pixels up (or flip their sign). 1/16 caps the gain at 16x the average.
constexpr double kMinIllumination = 1.0 / 16.0;

} // namespace

void flatten_illumination(PlanarImage& image, int nthreads)
{
    using namespace homogeneity;
    IlluminationFit fit;
    if (!fit_illumination(image, fit, nthreads))
        return;
    const int w = image.width(), h = image.height();
    // c0 is the mean of the fit (= the mean luminance): the clamp's reference.
    const double floor = kMinIllumination * fit.coefficients[0];
    auto gain = [&](int x, int y) { return 1.0 / std::max(floor, fit.at(x, y, w, h)); };

    // The sums of Y and Y/I over the image fix the overall scale.
    std::vector<double> sum_y(size_t((h + rows_per_block - 1) / rows_per_block));
    std::vector<double> sum_flat(sum_y.size());
    for_each_row_block(h, nthreads, [&](int b, int y0, int y1) {
        std::vector<float> luma(static_cast<size_t>(w));
        double sy = 0.0, sf = 0.0;
        for (int y = y0; y < y1; ++y) {
            luminance_row(image, y, luma.data());
            for (int x = 0; x < w; ++x) {
                sy += luma[size_t(x)];
                sf += luma[size_t(x)] * gain(x, y);
            }
        }
        sum_y[size_t(b)] = sy;
        sum_flat[size_t(b)] = sf;
    });
    double total_y = 0.0, total_flat = 0.0;
    for (size_t b = 0; b < sum_y.size(); ++b) { // block order: same at any thread count
        total_y += sum_y[b];
        total_flat += sum_flat[b];
    }
    // Mean luminance preserved: the luminance is linear in the colour channels, so
    // scaling them all by gain * scale scales it likewise.
    if (!(total_flat > 0.0))
        return;
    const double scale = total_y / total_flat;
    for_each_row_block(h, nthreads, [&](int, int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const double g = gain(x, y) * scale;
                for (int c = 0; c < image.ncolor(); ++c) {
                    float& v = image.channels[size_t(c)](x, y);
                    v = float(double(v) * g);
                }
            }
    });
}

} // namespace texsyn
