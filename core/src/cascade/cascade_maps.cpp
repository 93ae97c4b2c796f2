// SPDX-License-Identifier: Apache-2.0
// The cascade's pointwise maps (cascade_pvt.h).
#include "cascade_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {

namespace {

// The piecewise-linear curve through (x0, y0), (x1, y1), … (x increasing), flat outside.
float curve_value(const std::vector<float>& curve, float x)
{
    const size_t n = curve.size() / 2;
    if (n == 0)
        return x;
    if (x <= curve[0])
        return curve[1];
    for (size_t k = 1; k < n; ++k) {
        const float x0 = curve[2 * k - 2], y0 = curve[2 * k - 1];
        const float x1 = curve[2 * k], y1 = curve[2 * k + 1];
        if (x <= x1)
            return x1 > x0 ? y0 + (y1 - y0) * (x - x0) / (x1 - x0) : y1;
    }
    return curve[2 * n - 1];
}

} // namespace

float cascade_map_value(CascadeMap map, float r, const std::vector<float>& curve, float x)
{
    constexpr float pi = 3.14159265358979f;
    x = std::clamp(x, 0.0f, 1.0f);
    float y = x;
    switch (map) {
    case CascadeMap::Logistic:
        y = r * x * (1.0f - x);
        break;
    case CascadeMap::Sine:
        y = 0.25f * r * std::sin(pi * x);
        break;
    case CascadeMap::Tent:
        y = 0.25f * r * (1.0f - std::abs(2.0f * x - 1.0f));
        break;
    case CascadeMap::Cubic:
        y = r * 0.649519053f * x * (1.0f - x * x);
        break; // 3 sqrt(3) / 8
    case CascadeMap::Curve:
        y = curve_value(curve, x);
        break;
    }
    return std::clamp(y, 0.0f, 1.0f);
}

void apply_cascade_map(
    Plane& plane, CascadeMap map, float r, const std::vector<float>& curve, int nthreads)
{
    OIIO::parallel_for_range(
        int64_t(0), int64_t(plane.height()),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y) {
                float* row = plane.row(int(y));
                for (int x = 0; x < plane.width(); ++x)
                    row[x] = cascade_map_value(map, r, curve, row[x]);
            }
        },
        detail::split_every_item(nthreads));
}

} // namespace texsyn::detail
