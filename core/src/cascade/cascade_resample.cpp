// SPDX-License-Identifier: Apache-2.0
// The cascade's circular resampling of a lattice to the output's size (cascade_pvt.h).
#include "cascade_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {

namespace {

// Catmull-Rom: interpolating (1 at 0, 0 at the other integers), support [-2, 2].
double catmull_rom(double t)
{
    t = std::abs(t);
    if (t < 1.0)
        return (1.5 * t - 2.5) * t * t + 1.0;
    if (t < 2.0)
        return ((-0.5 * t + 2.5) * t - 4.0) * t + 2.0;
    return 0.0;
}

// The taps of one axis, `from` samples to `to`: output i reads `count` wrapped source
// indices with normalised weights. Minifying widens the filter by from/to so that it
// averages instead of aliasing.
struct AxisTaps {
    int count = 0;
    std::vector<int> index;
    std::vector<float> weight;
};

AxisTaps axis_taps(int from, int to)
{
    const double ratio = double(from) / double(to), stretch = std::max(1.0, ratio);
    const int radius = int(std::ceil(2.0 * stretch));
    AxisTaps taps;
    taps.count = 2 * radius;
    for (int o = 0; o < to; ++o) {
        // Pixel centres line up: output o covers source [o, o + 1) * ratio.
        const double centre = (o + 0.5) * ratio - 0.5;
        const int first = int(std::floor(centre)) - radius + 1;
        double sum = 0.0;
        std::vector<double> w(size_t(taps.count));
        for (int k = 0; k < taps.count; ++k)
            sum += w[size_t(k)] = catmull_rom((first + k - centre) / stretch);
        for (int k = 0; k < taps.count; ++k) {
            taps.index.push_back(wrap_coordinate(first + k, from, Boundary::Circular));
            taps.weight.push_back(float(w[size_t(k)] / sum));
        }
    }
    return taps;
}

} // namespace

Plane resample_circular(const Plane& in, int width, int height, int nthreads)
{
    const AxisTaps tx = axis_taps(in.width(), width), ty = axis_taps(in.height(), height);
    Plane rows(width, in.height()), out(width, height);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(in.height()),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y) {
                const float* src = in.row(int(y));
                float* dst = rows.row(int(y));
                for (int x = 0; x < width; ++x) {
                    const size_t t = size_t(x) * size_t(tx.count);
                    float v = 0.0f;
                    for (int k = 0; k < tx.count; ++k)
                        v += tx.weight[t + size_t(k)] * src[tx.index[t + size_t(k)]];
                    dst[x] = v;
                }
            }
        },
        detail::split_every_item(nthreads));
    OIIO::parallel_for_range(
        int64_t(0), int64_t(height),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y) {
                float* dst = out.row(int(y));
                std::fill(dst, dst + width, 0.0f);
                const size_t t = size_t(y) * size_t(ty.count);
                for (int k = 0; k < ty.count; ++k) {
                    const float wt = ty.weight[t + size_t(k)];
                    const float* src = rows.row(ty.index[t + size_t(k)]);
                    for (int x = 0; x < width; ++x)
                        dst[x] += wt * src[x];
                }
            }
        },
        detail::split_every_item(nthreads));
    return out;
}

} // namespace texsyn::detail
