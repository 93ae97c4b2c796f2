// SPDX-License-Identifier: Apache-2.0
#include <texsyn/histogram.h>

#include <algorithm>
#include <array>
#include <vector>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "histogram_pvt.h"

namespace texsyn {

const char* histogram_mode_name(HistogramMode mode)
{
    switch (mode) {
    case HistogramMode::Exact:
        return "exact";
    case HistogramMode::Bins256:
        return "bins256";
    }
    return "unknown";
}

namespace {

// Work is split into fixed chunks (never by thread count), so results are identical at
// any nthreads.
constexpr int64_t kChunk = int64_t(1) << 16;

void match_exact(Plane& plane, const QuantileTable& target, int nthreads)
{
    histogram_pvt::assign_quantiles_by_rank(
        plane.data(), plane.size(), target.sorted().data(), target.sorted().size(), nthreads);
}

constexpr int kBins = 256;
using Cdf = std::array<double, kBins + 1>; // cdf at the kBins+1 bin edges

inline int bin_of(double v, double lo, double width)
{
    return std::min(kBins - 1, int((v - lo) / width));
}

// Cumulative 256-bin histogram of values in [lo, lo + kBins*width], at the bin edges.
Cdf cdf_at_edges(const float* v, size_t n, double lo, double width, int nthreads)
{
    const size_t nchunks = (n + size_t(kChunk) - 1) / size_t(kChunk);
    std::vector<std::array<size_t, kBins>> counts(nchunks);
    OIIO::parallel_for_chunked(
        0, int64_t(n), kChunk,
        [&](int64_t begin, int64_t end) {
            std::array<size_t, kBins>& c = counts[size_t(begin / kChunk)];
            c.fill(0);
            for (int64_t i = begin; i < end; ++i)
                ++c[bin_of(v[i], lo, width)];
        },
        detail::split_every_item(nthreads));
    Cdf cdf;
    cdf[0] = 0.0;
    size_t cum = 0;
    for (int k = 0; k < kBins; ++k) {
        for (const auto& c : counts)
            cum += c[k];
        cdf[k + 1] = double(cum) / double(n);
    }
    return cdf;
}

// Heeger & Bergen §3.2: source cdf (256 bins over [min, max]) composed with the target's
// inverse cdf (256 bins, inverted by linear interpolation), applied as a lookup table
// with linear interpolation within a bin.
void match_bins256(Plane& plane, const QuantileTable& target, int nthreads)
{
    float* v = plane.data();
    const size_t n = plane.size();
    const auto [smin_it, smax_it] = std::minmax_element(v, v + n);
    const double smin = *smin_it, smax = *smax_it;

    const std::vector<float>& t = target.sorted();
    const double tmin = t.front(), tmax = t.back();
    const double twidth = (tmax - tmin) / kBins;
    Cdf tcdf {};
    if (tmax > tmin)
        tcdf = cdf_at_edges(t.data(), t.size(), tmin, twidth, nthreads);
    // Inverse of the piecewise-linear target cdf; empty bins (flat cdf) are skipped.
    auto inverse_cdf = [&](double p) {
        if (!(tmax > tmin) || p <= 0.0)
            return tmin;
        if (p >= 1.0)
            return tmax;
        const int k = int(std::lower_bound(tcdf.begin() + 1, tcdf.end(), p) - tcdf.begin()) - 1;
        return tmin + twidth * (k + (p - tcdf[k]) / (tcdf[k + 1] - tcdf[k]));
    };

    if (!(smax > smin)) {
        // A constant source is one cdf step from 0 to 1: map it to the step's midpoint.
        std::fill(v, v + n, float(inverse_cdf(0.5)));
        return;
    }
    const double swidth = (smax - smin) / kBins;
    const Cdf scdf = cdf_at_edges(v, n, smin, swidth, nthreads);
    std::array<double, kBins + 1> lut;
    for (int k = 0; k <= kBins; ++k)
        lut[k] = inverse_cdf(scdf[k]);

    OIIO::parallel_for_chunked(
        0, int64_t(n), kChunk,
        [&](int64_t begin, int64_t end) {
            for (int64_t i = begin; i < end; ++i) {
                const double x = (double(v[i]) - smin) / swidth;
                const int k = std::min(kBins - 1, int(x));
                const double f = std::min(1.0, x - k); // x may round to just above 256
                v[i] = float(lut[k] + f * (lut[k + 1] - lut[k]));
            }
        },
        detail::split_every_item(nthreads));
}

} // namespace

void match_histogram(Plane& plane, const QuantileTable& target, HistogramMode mode, int nthreads)
{
    // Nothing to match to (or nothing to change): leave the plane as it is.
    if (plane.empty() || target.empty())
        return;
    if (mode == HistogramMode::Bins256)
        match_bins256(plane, target, nthreads);
    else
        match_exact(plane, target, nthreads);
}

} // namespace texsyn
