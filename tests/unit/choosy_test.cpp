// SPDX-License-Identifier: Apache-2.0
// Castellanos & Williams choosy sampling: the neighbourhood, the Laplacian inversion, the
// dynamic kd-tree set against the exact search, determinism, and the paper's claim about
// first-order statistics.
#include <texsyn/choosy.h>
#include <texsyn/histogram.h>
#include <texsyn/random.h>

#include <algorithm>
#include <cmath>
#include <set>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "choosy/choosy_pvt.h"
#include "test_metrics.h"
#include "test_samples.h"

using namespace texsyn;

namespace {

using test::linear_crop;
using test::linear_sample;
using test::pixel_hash;
using test::planes_of;
using test::seam_ratio;

ChoosyOptions options(int w, int h, int levels)
{
    ChoosyOptions opt;
    opt.width = w;
    opt.height = h;
    opt.levels = levels;
    opt.seed = 7;
    opt.isotropic = 1; // the paper's, with which docs/choosy.md's measurements were made
    return opt;
}

// Per-channel W1 between the pixel histograms of a and b.
std::vector<double> channel_w1(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b)
{
    const PlanarImage pa = planes_of(a), pb = planes_of(b);
    std::vector<double> w;
    for (size_t c = 0; c < pa.channels.size(); ++c)
        w.push_back(wasserstein1(QuantileTable(pa.channels[c]), QuantileTable(pb.channels[c])));
    return w;
}

// Mean squared horizontal over mean squared vertical difference of the first channel: far
// from 1 for a texture with a dominant orientation.
double gradient_ratio(const OIIO::ImageBuf& buf)
{
    const PlanarImage image = planes_of(buf);
    const Plane& p = image.channels[0];
    double gx = 0, gy = 0;
    for (int y = 0; y + 1 < p.height(); ++y)
        for (int x = 0; x + 1 < p.width(); ++x) {
            gx += double(p(x + 1, y) - p(x, y)) * double(p(x + 1, y) - p(x, y));
            gy += double(p(x, y + 1) - p(x, y)) * double(p(x, y + 1) - p(x, y));
        }
    return gx / gy;
}

} // namespace

// The grid's 2-distant neighbourhood: 24 pixels, eq. 7 weights, and 8 orientations that
// permute it.
TEST(ChoosyNeighborhood, RingOfTwentyFourWithEquationSevenWeights)
{
    const auto& slots = detail::ring_slots();
    ASSERT_EQ(slots.size(), 24u);
    for (const auto& s : slots) {
        EXPECT_LE(std::max(std::abs(s.dx), std::abs(s.dy)), 2);
        EXPECT_FALSE(s.dx == 0 && s.dy == 0);
        const double d = std::hypot(double(s.dx), double(s.dy));
        EXPECT_NEAR(s.weight, std::exp(-0.5 * (d / 1.3) * (d / 1.3)), 1e-6);
    }
    // Each orientation maps the ring onto itself; the 8 are distinct.
    std::set<std::vector<std::pair<int, int>>> images;
    for (int t = 0; t < 8; ++t) {
        std::vector<std::pair<int, int>> image;
        for (const auto& s : slots) {
            int dx = s.dx, dy = s.dy;
            detail::orient(t, dx, dy);
            EXPECT_LE(std::max(std::abs(dx), std::abs(dy)), 2);
            image.push_back({ dx, dy });
        }
        std::vector<std::pair<int, int>> sorted = image;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end());
        images.insert(image);
    }
    EXPECT_EQ(images.size(), 8u);
}

// With every output pixel choosing its own sample pixel (identity, orientation 0), copying
// Gaussian values and Laplacian children and inverting level by level rebuilds the sample.
TEST(ChoosyPyramid, IdentityChoicesReconstructTheSample)
{
    const PlanarImage sample = planes_of(linear_crop("stucco_yellow.png", 128, 96));
    const int levels = 4;
    const detail::ChoosyAnalysis a = detail::analyze_choosy(sample.channels, levels, 0);
    const int top = levels - 1;
    detail::GridLevel out;
    out.gaussian = a.gaussian[top];
    static const std::vector<Plane> none;
    for (int l = top; l >= 0; --l) {
        const int w = a.gaussian[l][0].width(), h = a.gaussian[l][0].height();
        out.source.assign(size_t(w) * size_t(h), 0);
        out.orientation.assign(out.source.size(), detail::kNotChosen);
        out.children.clear();
        if (l > 0)
            out.children.assign(sample.channels.size(), Plane(2 * w, 2 * h));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                detail::copy_choice(
                    out, x, y, a.gaussian[l], l > 0 ? a.laplacian[l - 1] : none, x, y, 0);
        if (l > 0)
            out.gaussian = detail::invert_level(out.children, out.gaussian, Boundary::Reflect, 0);
    }
    for (size_t c = 0; c < sample.channels.size(); ++c)
        for (size_t i = 0; i < sample.channels[c].size(); ++i)
            ASSERT_NEAR(out.gaussian[c].data()[i], sample.channels[c].data()[i], 2e-6)
                << "channel " << c << " pixel " << i;
}

// Algorithm 2's counts: c_min follows the least used site and the penalty on the squared
// distance is 4^(penalty (c - c_min)).
TEST(ChoosyCounts, MinimumAndPenalty)
{
    detail::UseCounts counts(3, 1.0f);
    EXPECT_EQ(counts.min(), 0u);
    counts.add(0);
    counts.add(1);
    EXPECT_EQ(counts.min(), 0u);
    counts.add(2);
    EXPECT_EQ(counts.min(), 1u);
    counts.add(0);
    EXPECT_EQ(counts.factor(counts.count(0)), 4.0f);
    EXPECT_EQ(counts.factor(counts.count(1)), 1.0f);
    detail::UseCounts greedy(3, 0.0f);
    greedy.add(0);
    greedy.add(0);
    EXPECT_EQ(greedy.factor(greedy.count(0)), 1.0f);
    counts.reset();
    EXPECT_EQ(counts.count(0), 0u);
    EXPECT_EQ(counts.min(), 0u);
}

namespace {

// The points of a real sample level (stucco, 64x64, all 8 orientations) and queries that are
// its own output-like neighbourhoods: sample points with noise added.
struct ChoiceCase {
    PlanarImage sample;
    detail::AnalysisPoints points;
    std::vector<float> queries;
    size_t nqueries = 0;
};

ChoiceCase choice_case(size_t nqueries)
{
    ChoiceCase k;
    k.sample = planes_of(linear_crop("stucco_yellow.png", 48, 48));
    k.points = detail::grid_points(k.sample.channels, 8);
    k.nqueries = nqueries;
    k.queries.resize(nqueries * size_t(k.points.dim));
    for (size_t q = 0; q < nqueries; ++q) {
        const size_t p = size_t(random_bits(11, 1, q) % k.points.count);
        float* v = k.queries.data() + q * size_t(k.points.dim);
        k.points.vector(p, v);
        for (int i = 0; i < k.points.dim; ++i)
            v[i] += 0.02f * (random_uniform(11, 2, q * 1000 + size_t(i)) - 0.5f);
    }
    return k;
}

// Runs both indexes over the queries with the counts the exact index's choices give (both
// record the exact choice), and returns the fraction of queries where they agree.
double agreement(const ChoiceCase& k, detail::ChoiceIndex& exact, detail::ChoiceIndex& other)
{
    exact.reset();
    other.reset();
    size_t same = 0;
    for (size_t q = 0; q < k.nqueries; ++q) {
        const float* v = k.queries.data() + q * size_t(k.points.dim);
        const uint32_t e = exact.choose(v, nullptr, 0);
        same += other.choose(v, nullptr, 0) == e;
        exact.record(e);
        other.record(e);
        if (q % 16 == 15) { // rounds of 16 choices
            exact.settle();
            other.settle();
        }
    }
    return double(same) / double(k.nqueries);
}

} // namespace

// §6.4's set of dynamic kd-trees returns exactly the exhaustive choices when the projection
// keeps every dimension (and nanoflann is exact), through thousands of count changes that
// move points between trees, for the paper's penalty and for greedy selection.
TEST(ChoosyKdTrees, AgreeWithExhaustiveWithAllDimensions)
{
    const ChoiceCase k = choice_case(6000); // ~4 uses per sample site: counts 0..6
    for (float penalty : { 1.0f, 0.0f }) {
        auto exact = detail::make_exhaustive_choice(k.points, penalty, 0);
        auto trees = detail::make_kdtree_choice(k.points, penalty, k.points.dim, 0.0f, 0);
        EXPECT_EQ(agreement(k, *exact, *trees), 1.0) << "penalty " << penalty;
        EXPECT_GE(exact->counts().max(), 3u);
    }
}

// With the paper's 20 of 72 dimensions the choices are nearly the same: measured, 0.83 of
// the choices agree with exhaustive search for an exact kd-tree search (eps=0) and 0.82 with
// the default eps=30 (docs/choosy.md). Disagreements pick a near-equal neighbourhood.
TEST(ChoosyKdTrees, NearlyAgreeWithTwentyDimensions)
{
    const ChoiceCase k = choice_case(3000);
    auto exact = detail::make_exhaustive_choice(k.points, 1.0f, 0);
    for (float eps : { 0.0f, ChoosyOptions().eps }) {
        auto trees = detail::make_kdtree_choice(k.points, 1.0f, 20, eps, 0);
        const double a = agreement(k, *exact, *trees);
        std::cout << "agreement with 20 dimensions, eps=" << eps << ": " << a << "\n";
        EXPECT_GE(a, 0.8);
    }
}

// Wildcards (§3.12): choose_masked with every component counting is choose, and the
// kd-trees' masked choice (an exact loop over the full vectors) is the exhaustive index's,
// with half the slots masked, through count changes, for the paper's penalty and greedy.
TEST(ChoosyMasked, ExactOnBothIndices)
{
    const ChoiceCase k = choice_case(400);
    const size_t dim = size_t(k.points.dim);
    std::vector<float> all(dim, 1.0f), half(dim);
    for (size_t i = 0; i < dim; ++i)
        half[i] = (i / 3) % 2 == 0 ? 1.0f : 0.0f; // every other slot of 3 channels
    for (float penalty : { 1.0f, 0.0f }) {
        auto exact = detail::make_exhaustive_choice(k.points, penalty, 0);
        auto trees = detail::make_kdtree_choice(k.points, penalty, 20, ChoosyOptions().eps, 0);
        for (size_t q = 0; q < k.nqueries; ++q) {
            const float* v = k.queries.data() + q * dim;
            const uint32_t e = exact->choose(v, nullptr, 0);
            ASSERT_EQ(exact->choose_masked(v, all.data(), nullptr, 0), e) << q;
            const uint32_t m = exact->choose_masked(v, half.data(), nullptr, 0);
            ASSERT_EQ(trees->choose_masked(v, half.data(), nullptr, 0), m) << q;
            exact->record(m);
            trees->record(m);
            if (q % 16 == 15) {
                exact->settle();
                trees->settle();
            }
        }
        EXPECT_GE(exact->counts().max(), 1u);
    }
}

// Every output pixel is a copy of a sample pixel, the source map says which, and the
// output tiles.
TEST(Choosy, EveryPixelIsASamplePixelAndTheOutputTiles)
{
    const OIIO::ImageBuf sample = linear_crop("stucco_yellow.png", 64, 64);
    OIIO::ImageBuf map;
    const OIIO::ImageBuf out = choosy_synthesize(sample, options(96, 64, 3), &map);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    ASSERT_EQ(out.spec().width, 96);
    ASSERT_EQ(out.spec().height, 64);
    EXPECT_EQ(out.spec().get_string_attribute("synth:method"), "choosy");
    EXPECT_EQ(map.spec().get_string_attribute("synth:sample_size"), "64x64");
    const PlanarImage o = planes_of(out), s = planes_of(sample), m = planes_of(map);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 96; ++x) {
            const int sx = int(m.channels[0](x, y)), sy = int(m.channels[1](x, y));
            ASSERT_TRUE(sx >= 2 && sx < 62 && sy >= 2 && sy < 62) << sx << "," << sy;
            for (size_t c = 0; c < 3; ++c)
                ASSERT_EQ(o.channels[c](x, y), s.channels[c](sx, sy));
        }
    EXPECT_LT(seam_ratio(out), 1.3);
}

// Rounds of visits are searched in parallel but applied in order: the result is the same
// for any thread count, for both searches.
TEST(Choosy, ResultIgnoresThreadCount)
{
    const OIIO::ImageBuf sample = linear_crop("flowers.png", 64, 64);
    for (ChoosySearch search : { ChoosySearch::KdTree, ChoosySearch::Exhaustive }) {
        ChoosyOptions opt = options(64, 64, 3);
        opt.search = search;
        opt.iterations = { 1, 2 };
        std::string first;
        for (int threads : { 1, 2, 4 }) {
            opt.nthreads = threads;
            const OIIO::ImageBuf out = choosy_synthesize(sample, opt);
            ASSERT_FALSE(out.has_error()) << out.geterror();
            if (first.empty())
                first = pixel_hash(out);
            EXPECT_EQ(pixel_hash(out), first) << threads << " threads";
        }
        opt.seed = 8;
        EXPECT_NE(pixel_hash(choosy_synthesize(sample, opt)), first);
    }
}

// The paper's central claim (§3.11, §5, Fig. 13): on samples with many distinct colours the
// penalty keeps the output's histograms close to the sample's, where greedy best-match
// selection (penalty=0, Wei & Levoy's) over the same neighbourhoods skews them. Measured
// W1 per channel is in docs/choosy.md.
TEST(ChoosyQuality, MatchesFirstOrderStatisticsFarBetterThanGreedy)
{
    for (const char* name : { "flowers.png", "leaves_autumn.png", "pebbles.png" }) {
        const OIIO::ImageBuf sample = linear_sample(name);
        ChoosyOptions opt = options(256, 256, 4);
        const std::vector<double> choosy = channel_w1(choosy_synthesize(sample, opt), sample);
        opt.penalty = 0.0f;
        const std::vector<double> greedy = channel_w1(choosy_synthesize(sample, opt), sample);
        for (size_t c = 0; c < 3; ++c) {
            test::doc_number(
                std::string("choosy.") + name + ".w1." + "RGB"[c] + ".choosy", choosy[c], 4);
            test::doc_number(
                std::string("choosy.") + name + ".w1." + "RGB"[c] + ".greedy", greedy[c], 3);
            std::cout << name << " channel " << c << ": W1 choosy " << choosy[c] << ", greedy "
                      << greedy[c] << "\n";
            EXPECT_LE(choosy[c], 0.5 * greedy[c]) << name << " channel " << c;
        }
    }
}

// isotropic=1 compares with the sample in 8 orientations, so an oriented sample (wood
// grain) gives an isotropic variant (§5, Figs. 15–16); isotropic=0 keeps the orientation.
// Measured horizontal/vertical gradient energy: sample 0.061, isotropic=0 0.18, isotropic=1
// 1.31.
TEST(ChoosyQuality, IsotropicModeRemovesTheSamplesOrientation)
{
    const OIIO::ImageBuf sample = linear_sample("wood_grain.png");
    const double in = gradient_ratio(sample);
    ChoosyOptions opt = options(128, 128, 4);
    opt.isotropic = 0;
    const double kept = gradient_ratio(choosy_synthesize(sample, opt));
    opt.isotropic = 1;
    const double iso = gradient_ratio(choosy_synthesize(sample, opt));
    std::cout << "gradient ratio: sample " << in << ", isotropic=0 " << kept << ", isotropic=1 "
              << iso << "\n";
    EXPECT_GT(std::abs(std::log(kept)), 0.5 * std::abs(std::log(in)));
    EXPECT_LT(std::abs(std::log(iso)), 0.25 * std::abs(std::log(in)));
}

TEST(Choosy, RefusesBadSizes)
{
    const OIIO::ImageBuf sample = linear_crop("stucco_yellow.png", 64, 64);
    auto error_of = [&](const ChoosyOptions& opt) {
        OIIO::ImageBuf out;
        EXPECT_FALSE(choosy_synthesize(out, sample, opt));
        return out.geterror();
    };
    EXPECT_NE(error_of(options(100, 64, 4)).find("multiple of 8"), std::string::npos);
    EXPECT_NE(error_of(options(64, 64, 5)).find("use levels=4"), std::string::npos);
    EXPECT_NE(error_of(options(32, 32, 4)).find("coarsest output level"), std::string::npos);
    ChoosyOptions opt = options(64, 64, 2);
    opt.iterations = { 1, 2, 3 };
    EXPECT_NE(error_of(opt).find("iterations"), std::string::npos);
    EXPECT_NE(error_of(options(65536, 65536, 4)).find("size=65536x65536"), std::string::npos);
}
