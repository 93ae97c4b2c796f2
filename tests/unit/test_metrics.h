// SPDX-License-Identifier: Apache-2.0
// Measures of synthesized images shared by the unit tests of the copying methods.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include <OpenImageIO/hash.h>

#include <texsyn/histogram.h>

#include "test_samples.h"

namespace texsyn::test {

/// A hash of an image's float pixels (equal hashes: bit-identical pixels).
inline std::string pixel_hash(const OIIO::ImageBuf& buf)
{
    std::vector<float> px(size_t(buf.spec().image_pixels()) * size_t(buf.nchannels()));
    buf.get_pixels(buf.roi(), OIIO::TypeFloat, px.data());
    return OIIO::Strutil::fmt::format("{:016x}",
        OIIO::Strutil::strhash(
            std::string_view(reinterpret_cast<const char*>(px.data()), px.size() * sizeof(float))));
}

// The largest per-channel 1-D Wasserstein distance between the pixel histograms of a and b.
inline double worst_w1(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b)
{
    const PlanarImage pa = planes_of(a), pb = planes_of(b);
    double worst = 0;
    for (size_t c = 0; c < pa.channels.size(); ++c)
        worst = std::max(
            worst, wasserstein1(QuantileTable(pa.channels[c]), QuantileTable(pb.channels[c])));
    return worst;
}

// Mean absolute difference across the wrap-around seam (last column to first, last row to
// first) over the mean difference between interior neighbours: ~1 for a seamless tile.
inline double seam_ratio(const OIIO::ImageBuf& buf)
{
    const PlanarImage p = planes_of(buf);
    const int w = p.width(), h = p.height();
    double seam = 0, inner = 0;
    size_t nseam = 0, ninner = 0;
    for (const Plane& c : p.channels)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const double dx = std::abs(c((x + 1) % w, y) - c(x, y));
                const double dy = std::abs(c(x, (y + 1) % h) - c(x, y));
                (x == w - 1 ? seam : inner) += dx;
                (y == h - 1 ? seam : inner) += dy;
                (x == w - 1 ? nseam : ninner) += 1;
                (y == h - 1 ? nseam : ninner) += 1;
            }
    return (seam / double(nseam)) / (inner / double(ninner));
}

/// Area-weighted Wasserstein-1 distance between the values of a channel on mesh faces
/// (each face weighing its area) and the pixel values of a plane, both as distributions:
/// each face is compared with the pixel at its mid-area quantile.
inline double area_weighted_w1(
    const std::vector<float>& faces, const std::vector<float>& areas, const Plane& p)
{
    std::vector<size_t> order(faces.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return faces[a] < faces[b]; });
    std::vector<float> pixels(p.data(), p.data() + p.size());
    std::sort(pixels.begin(), pixels.end());
    const double total = std::accumulate(areas.begin(), areas.end(), 0.0);
    double w1 = 0.0, mass = 0.0;
    for (size_t i : order) {
        const double q = (mass + 0.5 * areas[i]) / total; // this face's quantile
        mass += areas[i];
        const float sample = pixels[std::min(pixels.size() - 1, size_t(q * double(pixels.size())))];
        w1 += double(areas[i]) / total * std::abs(double(faces[i]) - double(sample));
    }
    return w1;
}

/// Prints "[doc] key value" (value with `digits` decimals): a number a page of docs/ quotes,
/// which docs/numbers.py collects from the test's output and writes into the page's
/// <!--n:key-->…<!--/n--> span, so that no quoted measurement is typed by hand.
inline void doc_number(const std::string& key, double value, int digits)
{
    std::printf("[doc] %s %.*f\n", key.c_str(), digits, value);
}

} // namespace texsyn::test
