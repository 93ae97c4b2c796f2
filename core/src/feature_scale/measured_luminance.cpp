// SPDX-License-Identifier: Apache-2.0
// The luminance the feature-scale estimate measures: reduced to a bounded size, its
// lighting divided out, perceptually encoded.
#include "feature_scale_pvt.h"

#include <algorithm>
#include <cmath>

#include <texsyn/homogeneity.h>
#include <texsyn/pyramid.h>

#include "homogeneity/homogeneity_pvt.h"
#include "image/parallel_pvt.h"

namespace texsyn::detail {

namespace {

// Above this shorter side the sample is measured reduced: features larger than a quarter
// of it are not features a patch method can place anyway.
constexpr int kMaxMeasuredSide = 1024;

} // namespace

Plane measured_luminance(const PlanarImage& sample, int nthreads, int& factor)
{
    factor = 1;
    if (!homogeneity::has_luminance(sample))
        return Plane();
    const int w = sample.width(), h = sample.height();
    PlanarImage luminance;
    luminance.channels.emplace_back(w, h);
    OIIO::parallel_for(
        0, h,
        [&](int64_t y) {
            homogeneity::luminance_row(sample, int(y), luminance.channels[0].row(int(y)));
        },
        split_every_item(nthreads));
    while (std::min(luminance.width(), luminance.height()) > kMaxMeasuredSide) {
        luminance.channels[0] = reduce_plane(luminance.channels[0], Boundary::Reflect, nthreads);
        factor *= 2;
    }
    flatten_illumination(luminance, nthreads);
    Plane& l = luminance.channels[0];
    for (size_t i = 0; i < l.size(); ++i)
        l.data()[i] = std::pow(std::max(l.data()[i], 0.0f), 1.0f / 2.2f);
    return std::move(l);
}

} // namespace texsyn::detail
