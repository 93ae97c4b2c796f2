// SPDX-License-Identifier: Apache-2.0
// Histogram matching (Heeger & Bergen 1995 §3.2): quantile properties, determinism, and
// the fast paths (radix ranking, binned LUT) against slow obvious oracles.
#include <texsyn/histogram.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

using namespace texsyn;

namespace {

Plane random_plane(int w, int h, unsigned seed, float mean = 0.0f, float sigma = 1.0f)
{
    std::mt19937 rng(seed);
    std::normal_distribution<float> dist(mean, sigma);
    Plane p(w, h);
    for (size_t i = 0; i < p.size(); ++i)
        p.data()[i] = dist(rng);
    return p;
}

std::vector<float> values_of(const Plane& p)
{
    return std::vector<float>(p.data(), p.data() + p.size());
}

// The target 0, 1, ..., n-1: exact matching then writes each source value's rank.
QuantileTable rank_table(size_t n)
{
    std::vector<float> v(n);
    std::iota(v.begin(), v.end(), 0.0f);
    return QuantileTable::from_sorted(std::move(v));
}

void expect_hits_target_quantiles(int n, int m)
{
    Plane src = random_plane(n, 1, 1u, 2.0f, 3.0f);
    Plane tgt = random_plane(m, 1, 2u, -1.0f, 0.5f);
    QuantileTable table(tgt);
    match_histogram(src, table, HistogramMode::Exact);
    std::vector<float> out = values_of(src);
    std::sort(out.begin(), out.end());
    // Exact equality: the output is built from the same quantile function.
    for (int i = 0; i < n; ++i)
        ASSERT_EQ(out[size_t(i)], table.quantile((i + 0.5) / n)) << "i=" << i;
}

// The paper's algorithm written the obvious way (pyrtools histoMatch): 256-bin cdfs,
// inverse target cdf by interp1, then pointOp's linear interpolation in the table.
std::vector<float> bins256_oracle(const std::vector<float>& src, const std::vector<float>& tgt)
{
    auto cdf = [](const std::vector<float>& v, double lo, double hi) {
        std::vector<double> count(256, 0.0);
        for (float x : v) {
            int b = int((double(x) - lo) / ((hi - lo) / 256));
            count[size_t(std::min(b, 255))] += 1;
        }
        std::vector<double> c(257, 0.0);
        for (int k = 0; k < 256; ++k)
            c[size_t(k + 1)] = c[size_t(k)] + count[size_t(k)] / double(v.size());
        c[256] = 1.0;
        return c;
    };
    double smin = *std::min_element(src.begin(), src.end());
    double smax = *std::max_element(src.begin(), src.end());
    double tmin = *std::min_element(tgt.begin(), tgt.end());
    double tmax = *std::max_element(tgt.begin(), tgt.end());
    std::vector<double> sc = cdf(src, smin, smax), tc = cdf(tgt, tmin, tmax);
    double tw = (tmax - tmin) / 256, sw = (smax - smin) / 256;
    std::vector<double> lut(257);
    for (int k = 0; k <= 256; ++k) {
        double p = sc[size_t(k)];
        if (p <= 0) {
            lut[size_t(k)] = tmin;
            continue;
        }
        if (p >= 1) {
            lut[size_t(k)] = tmax;
            continue;
        }
        for (int j = 0; j < 256; ++j) // linear scan for the segment holding p
            if (tc[size_t(j)] < p && p <= tc[size_t(j + 1)]) {
                lut[size_t(k)]
                    = tmin + tw * (j + (p - tc[size_t(j)]) / (tc[size_t(j + 1)] - tc[size_t(j)]));
                break;
            }
    }
    std::vector<float> out(src.size());
    for (size_t i = 0; i < src.size(); ++i) {
        double x = (double(src[i]) - smin) / sw;
        int k = std::min(255, int(x));
        out[i] = float(lut[size_t(k)] + (x - k) * (lut[size_t(k + 1)] - lut[size_t(k)]));
    }
    return out;
}

} // namespace

TEST(Histogram, ModeNames)
{
    EXPECT_STREQ(histogram_mode_name(HistogramMode::Exact), "exact");
    EXPECT_STREQ(histogram_mode_name(HistogramMode::Bins256), "bins256");
}

TEST(Histogram, QuantileInterpolatesAndClamps)
{
    QuantileTable t = QuantileTable::from_sorted({ 0.0f, 10.0f, 20.0f, 30.0f });
    EXPECT_EQ(t.quantile(0.0), 0.0f);
    EXPECT_EQ(t.quantile(1.0), 30.0f);
    EXPECT_EQ(t.quantile(0.125), 0.0f);  // position 0
    EXPECT_EQ(t.quantile(0.375), 10.0f); // position 1
    EXPECT_EQ(t.quantile(0.5), 15.0f);   // position 1.5
    EXPECT_EQ(t.quantile(0.875), 30.0f); // position 3
    QuantileTable u(std::vector<float> { 3.0f, 1.0f, 2.0f }.data(), 3);
    EXPECT_EQ(u.sorted(), (std::vector<float> { 1.0f, 2.0f, 3.0f }));
}

TEST(Histogram, ExactHitsTargetQuantilesEqualSizes)
{
    expect_hits_target_quantiles(1000, 1000);
}

TEST(Histogram, ExactHitsTargetQuantilesDifferentSizes)
{
    expect_hits_target_quantiles(777, 2000);
    expect_hits_target_quantiles(3000, 100);
}

TEST(Histogram, ExactEqualSizesReproducesTargetValues)
{
    Plane src = random_plane(50, 40, 3u);
    Plane tgt = random_plane(40, 50, 4u, 5.0f);
    QuantileTable table(tgt);
    match_histogram(src, table, HistogramMode::Exact);
    std::vector<float> out = values_of(src);
    std::sort(out.begin(), out.end());
    EXPECT_EQ(out, table.sorted());
}

TEST(Histogram, ExactAndBinsPreserveOrder)
{
    for (HistogramMode mode : { HistogramMode::Exact, HistogramMode::Bins256 }) {
        Plane src = random_plane(64, 64, 5u);
        const std::vector<float> before = values_of(src);
        QuantileTable table(random_plane(100, 30, 6u, 0.0f, 4.0f));
        match_histogram(src, table, mode);
        std::vector<size_t> idx(before.size());
        std::iota(idx.begin(), idx.end(), size_t(0));
        std::stable_sort(
            idx.begin(), idx.end(), [&](size_t a, size_t b) { return before[a] < before[b]; });
        for (size_t i = 1; i < idx.size(); ++i)
            ASSERT_LE(src.data()[idx[i - 1]], src.data()[idx[i]]) << histogram_mode_name(mode);
        EXPECT_GE(*std::min_element(src.data(), src.data() + src.size()), table.sorted().front());
        EXPECT_LE(*std::max_element(src.data(), src.data() + src.size()), table.sorted().back());
    }
}

TEST(Histogram, ExactTiesRankedByIndex)
{
    Plane src(6, 1);
    const float v[6] = { 2.0f, 1.0f, 2.0f, 1.0f, 0.0f, 2.0f };
    std::copy(v, v + 6, src.data());
    match_histogram(src, rank_table(6), HistogramMode::Exact);
    const std::vector<float> expected = { 3.0f, 1.0f, 4.0f, 2.0f, 0.0f, 5.0f };
    EXPECT_EQ(values_of(src), expected);
}

TEST(Histogram, ConstantSourceAndTarget)
{
    // Constant source: all values tie, so the ranks are the indices.
    Plane src(5, 3, 7.0f);
    match_histogram(src, rank_table(15), HistogramMode::Exact);
    for (size_t i = 0; i < src.size(); ++i)
        EXPECT_EQ(src.data()[i], float(i));

    // Constant target: every output is that constant, in both modes.
    for (HistogramMode mode : { HistogramMode::Exact, HistogramMode::Bins256 }) {
        Plane p = random_plane(20, 20, 7u);
        std::vector<float> c(50, -2.5f);
        match_histogram(p, QuantileTable(c.data(), c.size()), mode);
        for (size_t i = 0; i < p.size(); ++i)
            ASSERT_EQ(p.data()[i], -2.5f);
    }

    // Constant source in Bins256: one cdf step, mapped to the target's median.
    Plane q(4, 4, 1.0f);
    match_histogram(q, rank_table(101), HistogramMode::Bins256);
    for (size_t i = 0; i < q.size(); ++i) {
        ASSERT_TRUE(std::isfinite(q.data()[i]));
        EXPECT_NEAR(q.data()[i], 50.0f, 0.5f); // within one target bin of the median
    }
}

TEST(Histogram, SingleValue)
{
    const float t[3] = { 1.0f, 2.0f, 3.0f };
    Plane one(1, 1, 42.0f);
    match_histogram(one, QuantileTable(t, 3), HistogramMode::Exact);
    EXPECT_EQ(one.data()[0], 2.0f); // Q(0.5): the median
    Plane binned(1, 1, 42.0f);
    match_histogram(binned, QuantileTable(t, 3), HistogramMode::Bins256);
    EXPECT_NEAR(binned.data()[0], 2.0f, 2.0f / 256); // the binned median: within one bin
    Plane p = random_plane(8, 8, 8u);
    const float t1 = 0.25f;
    match_histogram(p, QuantileTable(&t1, 1), HistogramMode::Exact);
    for (size_t i = 0; i < p.size(); ++i)
        EXPECT_EQ(p.data()[i], 0.25f);
}

TEST(Histogram, Bins256MatchesSlowPaperAlgorithm)
{
    for (unsigned seed : { 10u, 11u, 12u }) {
        Plane src = random_plane(97, 53, seed, 1.0f, 2.0f);
        Plane tgt = random_plane(61, 89, seed + 100, -3.0f, 0.3f);
        // A skewed target too, with empty bins in its tail.
        for (size_t i = 0; i < tgt.size(); i += 7)
            tgt.data()[i] = std::exp(tgt.data()[i] + 3.0f);
        const std::vector<float> expected = bins256_oracle(values_of(src), values_of(tgt));
        QuantileTable table(tgt);
        match_histogram(src, table, HistogramMode::Bins256);
        const double range = double(table.sorted().back()) - double(table.sorted().front());
        for (size_t i = 0; i < src.size(); ++i)
            // Both compute in double; only the final float rounding differs.
            ASSERT_NEAR(src.data()[i], expected[i], 1e-6 * range) << "i=" << i;
    }
}

TEST(Histogram, RadixRankingMatchesStableSort)
{
    std::mt19937 rng(99u);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, 9);
    const int n = 300000; // large enough to exercise every radix pass and many chunks
    Plane p(n, 1);
    for (int i = 0; i < n; ++i) {
        float v;
        switch (pick(rng)) {
        case 0:
            v = 0.0f;
            break;
        case 1:
            v = -0.0f;
            break;
        case 2:
            v = float(int(normal(rng) * 4.0f));
            break; // many exact ties
        case 3:
            v = normal(rng) * 1e-40f;
            break; // denormals
        case 4:
            v = normal(rng) * 1e30f;
            break; // huge magnitudes
        default:
            v = normal(rng) * 100.0f;
            break;
        }
        p.data()[i] = v;
    }
    const std::vector<float> before = values_of(p);
    std::vector<size_t> idx(static_cast<size_t>(n));
    std::iota(idx.begin(), idx.end(), size_t(0));
    std::stable_sort(
        idx.begin(), idx.end(), [&](size_t a, size_t b) { return before[a] < before[b]; });
    match_histogram(p, rank_table(size_t(n)), HistogramMode::Exact);
    for (size_t r = 0; r < idx.size(); ++r)
        ASSERT_EQ(p.data()[idx[r]], float(r)) << "rank " << r << " value " << before[idx[r]];
}

TEST(Histogram, DeterministicAcrossThreads)
{
    const Plane src = random_plane(512, 400, 20u);
    const QuantileTable table(random_plane(300, 300, 21u, 1.0f, 0.1f));
    for (HistogramMode mode : { HistogramMode::Exact, HistogramMode::Bins256 }) {
        Plane ref = src;
        match_histogram(ref, table, mode, 1);
        for (int nthreads : { 2, 3, 0 }) {
            Plane p = src;
            match_histogram(p, table, mode, nthreads);
            EXPECT_EQ(0, std::memcmp(p.data(), ref.data(), p.size() * sizeof(float)))
                << histogram_mode_name(mode) << " nthreads=" << nthreads;
        }
    }
}

TEST(Histogram, Wasserstein1)
{
    const Plane a = random_plane(100, 37, 30u);
    const QuantileTable ta(a);
    EXPECT_EQ(wasserstein1(ta, ta), 0.0);

    Plane shifted = a;
    for (size_t i = 0; i < shifted.size(); ++i)
        shifted.data()[i] += 0.25f;
    // Adding 0.25 in float rounds each value by at most half an ulp of ~4.
    EXPECT_NEAR(wasserstein1(ta, QuantileTable(shifted)), 0.25, 1e-6);
    EXPECT_NEAR(wasserstein1(QuantileTable(shifted), ta), 0.25, 1e-6);

    // Different sizes, by hand: Q_a = 0 on [0, 1/4], 1 on [3/4, 1], linear in between;
    // against the constant 0.5, |Q_a - 0.5| integrates to 1/8 + 1/8 + 1/8.
    const float two[2] = { 0.0f, 1.0f };
    const float half = 0.5f;
    EXPECT_NEAR(wasserstein1(QuantileTable(two, 2), QuantileTable(&half, 1)), 0.375, 1e-12);
}

// The barycentre averages quantile functions: of U[0,1] and U[2,4] with weights 1/4, 3/4 it
// is U[1.5, 3.25]; tables of different sizes are evaluated at the larger one's knots.
TEST(Barycenter, OfUniformsIsTheUniformOfAveragedEnds)
{
    const size_t n0 = 1000, n1 = 4000;
    std::vector<float> a(n0), b(n1);
    for (size_t i = 0; i < n0; ++i)
        a[i] = float((i + 0.5) / n0);
    for (size_t i = 0; i < n1; ++i)
        b[i] = float(2.0 + 2.0 * (i + 0.5) / n1);
    const QuantileTable ta = QuantileTable::from_sorted(a), tb = QuantileTable::from_sorted(b);
    const QuantileTable bary = wasserstein_barycenter({ &ta, &tb }, { 1.0, 3.0 });
    ASSERT_EQ(bary.sorted().size(), n1);
    EXPECT_TRUE(std::is_sorted(bary.sorted().begin(), bary.sorted().end()));
    for (double u : { 0.01, 0.25, 0.5, 0.8, 0.99 }) // the interpolation of a: float rounding
        EXPECT_NEAR(bary.quantile(u), 0.25 * u + 0.75 * (2.0 + 2.0 * u), 1e-5) << u;
}

// Of N(0, 1) and N(3, 2^2) with weights 0.6, 0.4 it is N(1.2, 1.4^2): quantiles, mean and
// standard deviation are the weighted ones (a bin-count average would be two-peaked, with
// a larger spread).
TEST(Barycenter, OfGaussiansIsTheGaussianOfAveragedMeansAndDeviations)
{
    auto gaussian = [](double mean, double sigma, size_t n) {
        std::vector<float> v(n);
        for (size_t i = 0; i < n; ++i) // exact quantiles: inverse normal cdf by bisection
        {
            double lo = -10, hi = 10, p = (i + 0.5) / n;
            for (int it = 0; it < 60; ++it) {
                const double mid = 0.5 * (lo + hi);
                (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
            }
            v[i] = float(mean + sigma * 0.5 * (lo + hi));
        }
        return QuantileTable::from_sorted(v);
    };
    const QuantileTable a = gaussian(0.0, 1.0, 5000), b = gaussian(3.0, 2.0, 5000);
    const QuantileTable want = gaussian(1.2, 1.4, 5000);
    const QuantileTable bary = wasserstein_barycenter({ &a, &b }, { 0.6, 0.4 });
    EXPECT_EQ(bary.sorted().size(), 5000u);
    for (double u : { 0.001, 0.1, 0.5, 0.9, 0.999 })
        EXPECT_NEAR(bary.quantile(u), want.quantile(u), 1e-5) << u;
    EXPECT_LT(wasserstein1(bary, want), 1e-6);
    double m = 0.0, s = 0.0;
    for (float v : bary.sorted())
        m += v;
    m /= 5000.0;
    for (float v : bary.sorted())
        s += (v - m) * (v - m);
    EXPECT_NEAR(m, 1.2, 1e-4);
    EXPECT_NEAR(std::sqrt(s / 5000.0), 1.4, 5e-3); // the sampled tails fall short of sigma
}

TEST(Barycenter, WeightOneReturnsTheTableExactlyAndBadInputGivesEmpty)
{
    const QuantileTable a(random_plane(37, 11, 3u)), b(random_plane(64, 64, 4u));
    const QuantileTable same = wasserstein_barycenter({ &a, &b }, { 2.0, 0.0 });
    EXPECT_EQ(same.sorted(), a.sorted()); // sizes differ, yet no resampling
    EXPECT_TRUE(wasserstein_barycenter({ &a, &b }, { 0.0, 0.0 }).empty());
    EXPECT_TRUE(wasserstein_barycenter({ &a, &b }, { 1.0, -1.0 }).empty());
    EXPECT_TRUE(wasserstein_barycenter({ &a }, { 1.0, 1.0 }).empty());
    const QuantileTable none;
    EXPECT_TRUE(wasserstein_barycenter({ &a, &none }, { 1.0, 1.0 }).empty());
}
