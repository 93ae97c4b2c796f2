// SPDX-License-Identifier: Apache-2.0
// The automatic guidance channel of Kaspar et al. 2015 §4.2 (the distance transform of a
// feature mask), here the distance to the sample's strong edges.
#include "patch_pvt.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <OpenImageIO/parallel.h>

#include <texsyn/pyramid.h>

#include "image/parallel_pvt.h"
#include "methods/method_helpers_pvt.h"

namespace texsyn::detail {

namespace {

// The mean of the colour planes.
Plane luminance(const std::vector<Plane>& colour)
{
    Plane l(colour[0].width(), colour[0].height());
    for (const Plane& p : colour)
        for (size_t i = 0; i < l.size(); ++i)
            l.data()[i] += p.data()[i] / float(colour.size());
    return l;
}

// Squared Euclidean distance transform along one line (Felzenszwalb & Huttenlocher 2012):
// d[i] = min_j (i - j)^2 + f[j], f infinite off the mask.
void distance_line(const float* f, float* d, int n, std::vector<int>& v, std::vector<float>& z)
{
    const float inf = std::numeric_limits<float>::infinity();
    int k = -1;
    for (int q = 0; q < n; ++q) {
        if (f[q] == inf)
            continue;
        while (k >= 0) {
            const float s = ((f[q] + float(q) * float(q)) - (f[v[k]] + float(v[k]) * float(v[k])))
                / (2.0f * float(q - v[k]));
            if (s > z[k])
                break;
            --k;
        }
        ++k;
        v[k] = q;
        z[k] = k == 0
            ? -inf
            : ((f[q] + float(q) * float(q)) - (f[v[k - 1]] + float(v[k - 1]) * float(v[k - 1])))
                / (2.0f * float(q - v[k - 1]));
    }
    if (k < 0) {
        std::fill(d, d + n, inf);
        return;
    }
    int j = 0;
    for (int q = 0; q < n; ++q) {
        while (j < k && z[j + 1] < float(q))
            ++j;
        d[q] = float(q - v[j]) * float(q - v[j]) + f[v[j]];
    }
}

} // namespace

void plane_moments(const Plane& plane, double& mean, double& variance)
{
    mean = 0.0;
    for (size_t i = 0; i < plane.size(); ++i)
        mean += plane.data()[i];
    mean /= double(plane.size());
    variance = 0.0;
    for (size_t i = 0; i < plane.size(); ++i)
        variance += (plane.data()[i] - mean) * (plane.data()[i] - mean);
    variance /= double(plane.size());
}

void scale_like_colour(Plane& plane, const std::vector<Plane>& colour)
{
    double mean = 0.0, var = 0.0, colour_sd = 0.0;
    for (const Plane& p : colour) {
        plane_moments(p, mean, var);
        colour_sd += std::sqrt(var) / double(colour.size());
    }
    plane_moments(plane, mean, var);
    const double scale = var > 0.0 ? colour_sd / std::sqrt(var) : 0.0;
    for (size_t i = 0; i < plane.size(); ++i)
        plane.data()[i] = float((plane.data()[i] - mean) * scale);
}

Plane guidance_channel(
    const std::vector<Plane>& colour, int feature_size, int nthreads, const StopFlag* stop)
{
    const Plane l = luminance(colour);
    const int w = l.width(), h = l.height();
    // Gradient magnitude (central differences, clamped at the edges); the mask is its top
    // fifth.
    Plane grad(w, h);
    OIIO::parallel_for(
        0, h,
        [&](int64_t row) {
            const int y = int(row);
            for (int x = 0; x < w; ++x) {
                const float gx = l(std::min(x + 1, w - 1), y) - l(std::max(x - 1, 0), y);
                const float gy = l(x, std::min(y + 1, h - 1)) - l(x, std::max(y - 1, 0));
                grad(x, y) = gx * gx + gy * gy;
            }
        },
        split_every_item(nthreads));
    throw_if_stopped(stop);
    std::vector<float> sorted(grad.data(), grad.data() + grad.size());
    const size_t cut = sorted.size() * 4 / 5;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(cut), sorted.end());
    const float threshold = sorted[cut];
    const float inf = std::numeric_limits<float>::infinity();
    Plane dist(w, h);
    for (size_t i = 0; i < grad.size(); ++i)
        dist.data()[i] = grad.data()[i] > threshold || (threshold == 0.0f && grad.data()[i] > 0.0f)
            ? 0.0f
            : inf;
    throw_if_stopped(stop);
    // Two passes of the 1-D transform: columns, then rows; each line on its own.
    auto lines = [&](int count, int length, auto&& load, auto&& store) {
        OIIO::parallel_for_range(
            0, count,
            [&](int64_t begin, int64_t end) {
                std::vector<float> f(size_t(length) + 1), d(size_t(length) + 1),
                    z(size_t(length) + 1);
                std::vector<int> v(size_t(length) + 1);
                for (int64_t i = begin; i < end && !stop_requested(stop); ++i) {
                    load(int(i), f.data());
                    distance_line(f.data(), d.data(), length, v, z);
                    store(int(i), d.data());
                }
            },
            split_every_item(nthreads));
        throw_if_stopped(stop);
    };
    lines(
        w, h,
        [&](int x, float* f) {
            for (int y = 0; y < h; ++y)
                f[y] = dist(x, y);
        },
        [&](int x, const float* d) {
            for (int y = 0; y < h; ++y)
                dist(x, y) = d[y];
        });
    lines(
        h, w, [&](int y, float* f) { std::copy_n(dist.row(y), w, f); },
        [&](int y, const float* d) { std::copy_n(d, w, dist.row(y)); });
    // Clip, then scale like the colours.
    const float clip = float(std::max(1, feature_size));
    for (size_t i = 0; i < dist.size(); ++i) {
        const float v2 = dist.data()[i];
        dist.data()[i] = std::isfinite(v2) ? std::min(std::sqrt(v2), clip) : clip;
    }
    scale_like_colour(dist, colour);
    return dist;
}

} // namespace texsyn::detail
