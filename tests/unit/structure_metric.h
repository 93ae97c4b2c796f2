// SPDX-License-Identifier: Apache-2.0
// A structure metric of the tests' own, for every copying method (patch, neighborhood,
// choosy, fill, tileable): does a result arrange its sample's features as the sample does,
// without seams? Two measures, each against the sample:
//  - arrangement: the RMS difference of the luminance autocorrelations at every shift
//    within `radius` (the layout of features: blobs, courses, grain);
//  - seams: the 95th percentile, over the result's 7x7 patches, of the distance to the
//    nearest patch of the sample (RMS per pixel, in units of the sample's luminance
//    standard deviation): a patch that straddles a visible seam exists nowhere in the
//    sample.
// And the two controls a metric must fail: the sample's pixels shuffled (no arrangement)
// and the sample pasted side by side with every other row of copies shifted by half the
// sample (every feature whole, but seams at the joins).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/image.h>
#include <texsyn/search.h>

namespace texsyn::test {

/// The Rec. 709 luminance of an image's first three channels (or its only one).
inline Plane luminance_of(const OIIO::ImageBuf& image)
{
    PlanarImage p;
    std::string error;
    planes_from_imagebuf(image, p, error);
    Plane l(p.width(), p.height());
    const double wts[3] = { 0.2126, 0.7152, 0.0722 };
    for (size_t i = 0; i < l.size(); ++i) {
        double v = 0.0;
        for (int c = 0; c < 3; ++c)
            v += wts[c] * p.channels[size_t(std::min(c, p.nchannels() - 1))].data()[i];
        l.data()[i] = float(v);
    }
    return l;
}

/// The normalised autocorrelation of `l` at every shift within `radius` (row-major,
/// (2 radius + 1)^2 values): over the overlap of the plane with its shifted self.
inline std::vector<double> autocorrelation_within(const Plane& l, int radius)
{
    const int w = l.width(), h = l.height();
    double mean = 0.0;
    for (size_t i = 0; i < l.size(); ++i)
        mean += l.data()[i];
    mean /= double(l.size());
    std::vector<double> r;
    double zero = 0.0;
    for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
            double sum = 0.0;
            size_t n = 0;
            for (int y = std::max(0, -dy); y < std::min(h, h - dy); ++y)
                for (int x = std::max(0, -dx); x < std::min(w, w - dx); ++x) {
                    sum += (l(x, y) - mean) * (l(x + dx, y + dy) - mean);
                    ++n;
                }
            r.push_back(sum / double(std::max<size_t>(n, 1)));
            if (dx == 0 && dy == 0)
                zero = r.back();
        }
    for (double& v : r)
        v = zero > 0.0 ? v / zero : 0.0;
    return r;
}

/// The arrangement measure: RMS difference of the two autocorrelations within `radius`.
inline double arrangement_error(
    const OIIO::ImageBuf& result, const OIIO::ImageBuf& sample, int radius)
{
    const std::vector<double> a = autocorrelation_within(luminance_of(result), radius);
    const std::vector<double> b = autocorrelation_within(luminance_of(sample), radius);
    double sum = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum / double(a.size()));
}

/// The seam measure: per column and per row of the result, the mean distance of the 7x7
/// luminance patches centred on it to their nearest patch of the sample (a kd-tree over
/// every sample patch); the worst line's excess over the mean line, in units of the
/// sample's luminance standard deviation. A line where copies meet with a visible step
/// holds patches that exist nowhere in the sample: small when no line stands out (the
/// seams of a good synthesis wander), large where copies were pasted side by side.
inline double seam_error(const OIIO::ImageBuf& result, const OIIO::ImageBuf& sample)
{
    constexpr int p = 7, half = p / 2, dim = p * p;
    const Plane s = luminance_of(sample), r = luminance_of(result);
    std::vector<float> vectors;
    for (int y = 0; y + p <= s.height(); ++y)
        for (int x = 0; x + p <= s.width(); ++x)
            for (int j = 0; j < p; ++j)
                for (int i = 0; i < p; ++i)
                    vectors.push_back(s(x + i, y + j));
    const VectorSet set { vectors.data(), vectors.size() / dim, dim };
    SearchSettings settings;
    settings.method = SearchMethod::KdTree;
    settings.dims = 10;
    settings.candidates = 4;
    std::string error;
    const auto search = make_search(set, settings, error);
    const int w = r.width(), h = r.height();
    std::vector<double> columns(size_t(w), 0.0), rows(size_t(h), 0.0);
    std::vector<int> in_column(size_t(w), 0), in_row(size_t(h), 0);
    std::vector<float> q(dim);
    for (int y = half; y + half < h; ++y)
        for (int x = half + (y % 2); x + half < w; x += 2) { // every other pixel of a line
            for (int j = 0; j < p; ++j)
                for (int i = 0; i < p; ++i)
                    q[size_t(j * p + i)] = r(x - half + i, y - half + j);
            const uint32_t k = search->nearest(q.data(), nullptr, 0);
            const double d = std::sqrt(squared_distance(q.data(), set.row(k), dim) / dim);
            columns[size_t(x)] += d;
            rows[size_t(y)] += d;
            ++in_column[size_t(x)];
            ++in_row[size_t(y)];
        }
    double mean = 0.0, var = 0.0;
    for (size_t i = 0; i < s.size(); ++i)
        mean += s.data()[i];
    mean /= double(s.size());
    for (size_t i = 0; i < s.size(); ++i)
        var += (s.data()[i] - mean) * (s.data()[i] - mean);
    const double sd = std::max(std::sqrt(var / double(s.size())), 1e-9);
    // The worst line's excess over the mean line, each axis.
    auto excess = [&](const std::vector<double>& sums, const std::vector<int>& n) {
        double worst = 0.0, total = 0.0;
        int lines = 0;
        for (size_t i = 0; i < sums.size(); ++i)
            if (n[i]) {
                worst = std::max(worst, sums[i] / n[i]);
                total += sums[i] / n[i];
                ++lines;
            }
        return (worst - total / std::max(lines, 1)) / sd;
    };
    return std::max(excess(columns, in_column), excess(rows, in_row));
}

/// `image`'s pixels rearranged into w x h: pixel (x, y) takes the image's pixel number
/// `source(x, y)` (row after row).
template <class Source>
OIIO::ImageBuf rearranged(const OIIO::ImageBuf& image, int w, int h, Source source)
{
    PlanarImage p;
    std::string error;
    planes_from_imagebuf(image, p, error);
    PlanarImage out = p;
    for (Plane& c : out.channels)
        c = Plane(w, h);
    for (size_t c = 0; c < p.channels.size(); ++c)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                out.channels[c](x, y) = p.channels[c].data()[source(x, y)];
    OIIO::ImageBuf buf;
    imagebuf_from_planes(out, buf);
    return buf;
}

/// Control: `sample`'s pixels in a seeded random order, tiled to w x h.
inline OIIO::ImageBuf shuffled(const OIIO::ImageBuf& sample, int w, int h)
{
    const int sw = sample.spec().width, sh = sample.spec().height;
    std::vector<size_t> order(size_t(sw) * size_t(sh));
    std::iota(order.begin(), order.end(), size_t(0));
    std::shuffle(order.begin(), order.end(), std::mt19937(7));
    return rearranged(sample, w, h,
        [&](int x, int y) { return order[size_t(y % sh) * size_t(sw) + size_t(x % sw)]; });
}

/// Control: `sample` pasted side by side to w x h, every other row of copies shifted by
/// half the sample's width (a running bond of copies).
inline OIIO::ImageBuf half_shifted_tiling(const OIIO::ImageBuf& sample, int w, int h)
{
    const int sw = sample.spec().width, sh = sample.spec().height;
    return rearranged(sample, w, h, [&](int x, int y) {
        const int shift = (y / sh) % 2 ? sw / 2 : 0;
        return size_t(y % sh) * size_t(sw) + size_t((x + shift) % sw);
    });
}

/// `image` pasted 2 x 2: a tile's wrap-around seams inside the picture.
inline OIIO::ImageBuf tiled_twice(const OIIO::ImageBuf& image)
{
    const int w = image.spec().width, h = image.spec().height;
    return rearranged(image, 2 * w, 2 * h,
        [&](int x, int y) { return size_t(y % h) * size_t(w) + size_t(x % w); });
}

} // namespace texsyn::test
