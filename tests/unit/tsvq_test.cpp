// SPDX-License-Identifier: Apache-2.0
// The TSVQ search back-end against its oracle, the exhaustive search; and a synthesis with it.
#include <texsyn/histogram.h>
#include <texsyn/neighborhood.h>
#include <texsyn/random.h>
#include <texsyn/search.h>

#include <cmath>
#include <vector>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "neighborhood/neighborhood_pvt.h"
#include "test_samples.h"

using namespace texsyn;

namespace {

std::unique_ptr<NeighborSearch> searcher(
    const VectorSet& set, SearchMethod method, int candidates = 1, int nthreads = 0)
{
    SearchSettings s;
    s.method = method;
    s.candidates = candidates;
    s.nthreads = nthreads;
    std::string error;
    auto search = make_search(set, s, error);
    EXPECT_TRUE(search) << error;
    return search;
}

// Vectors first..first+count-1 of a set clustered around `centres` random centres (uniform
// in [0, 1)^dim), each component off its centre by up to +-spread: clustered like texture
// neighbourhoods, not uniform noise. Queries are further vectors of the same set.
std::vector<float> clustered(
    size_t first, size_t count, int dim, int centres, float spread, uint64_t seed)
{
    std::vector<float> v(count * size_t(dim));
    for (size_t j = 0; j < count; ++j) {
        const uint64_t i = first + j, c = random_bits(seed, 0, i) % uint64_t(centres);
        for (int k = 0; k < dim; ++k)
            v[j * size_t(dim) + size_t(k)]
                = random_uniform(seed, 1, c * uint64_t(dim) + uint64_t(k))
                + spread * (2.0f * random_uniform(seed, 2, i * uint64_t(dim) + uint64_t(k)) - 1.0f);
    }
    return v;
}

// The causal n=9 neighbourhood vectors (RGB, dim 120) of a w x h crop of rust.png at (x, y).
detail::SampleVectors rust_vectors(int x, int y, int w, int h, VectorSet& set)
{
    static const OIIO::ImageBuf rust = test::linear_sample("rust.png");
    const PlanarImage planes
        = test::planes_of(OIIO::ImageBufAlgo::cut(rust, OIIO::ROI(x, x + w, y, y + h)));
    const detail::NeighborhoodLayout layout
        = detail::make_layout(9, 5, false, NeighborhoodShape::Causal);
    const detail::CandidateGrid grid = detail::candidate_grid(layout, w, h);
    detail::SampleVectors v = detail::sample_vectors(layout, grid, planes.channels, {}, 0);
    set = { v.data(), grid.count(), layout.npixels() * 3 };
    return v;
}

float distance_to(const VectorSet& set, const float* query, uint32_t index)
{
    return squared_distance(query, set.row(index), set.dim);
}

} // namespace

TEST(Tsvq, EveryVectorOfTheSetFindsItself)
{
    // Plain descent (candidates=1): a vector was routed to its leaf by the same comparisons
    // the search makes, so it is found exactly; the set has no duplicates.
    const int dim = 30;
    const std::vector<float> data = clustered(0, 3000, dim, 40, 0.1f, 1);
    const VectorSet set { data.data(), 3000, dim };
    auto tsvq = searcher(set, SearchMethod::Tsvq);
    for (uint32_t i = 0; i < 3000; ++i)
        ASSERT_EQ(tsvq->nearest(set.row(i), nullptr, 0), i);
}

TEST(Tsvq, VisitingEveryLeafIsExhaustive)
{
    // candidates >= the number of leaves (at most count): every vector is compared, with
    // the same distance and tie rule as the exhaustive search. Half the vectors are copies
    // of others so that ties occur.
    const int dim = 24;
    std::vector<float> data = clustered(0, 1200, dim, 10, 0.2f, 2);
    for (size_t i = 600; i < 1200; ++i)
        std::copy_n(data.begin() + long((i * 7 % 600) * dim), dim, data.begin() + long(i * dim));
    const VectorSet set { data.data(), 1200, dim };
    auto tsvq = searcher(set, SearchMethod::Tsvq, 1200);
    auto exact = searcher(set, SearchMethod::Exhaustive);
    const std::vector<float> queries = clustered(1200, 300, dim, 10, 0.2f, 2);
    for (size_t q = 0; q < 300; ++q) {
        const float* query = queries.data() + q * dim;
        ASSERT_EQ(tsvq->nearest(query, nullptr, 0), exact->nearest(query, nullptr, 0)) << q;
    }
    for (uint32_t i = 600; i < 1200; ++i)
        ASSERT_EQ(tsvq->nearest(set.row(i), nullptr, 0), i * 7 % 600);
}

TEST(Tsvq, ApproximationImprovesWithCandidates)
{
    // Set: the neighbourhoods of rust.png's top-left 128x128 (14880 vectors of 120 floats);
    // queries: neighbourhoods of its bottom-right quadrant, which the set does not contain.
    VectorSet set, queries;
    const detail::SampleVectors data = rust_vectors(0, 0, 128, 128, set);
    const detail::SampleVectors qdata = rust_vectors(128, 128, 128, 128, queries);
    auto exact = searcher(set, SearchMethod::Exhaustive);
    const std::vector<int> ks = { 1, 2, 4, 8, 16, 64 };
    std::vector<std::unique_ptr<NeighborSearch>> tsvq;
    for (int k : ks)
        tsvq.push_back(searcher(set, SearchMethod::Tsvq, k));
    std::vector<double> ratio(ks.size(), 0.0);
    size_t n = 0;
    for (size_t q = 0; q < queries.count; q += 37) {
        const float* query = queries.row(q);
        const float best = distance_to(set, query, exact->nearest(query, nullptr, 0));
        ASSERT_GT(best, 0.0f);
        float previous = INFINITY;
        for (size_t j = 0; j < ks.size(); ++j) {
            const float d = distance_to(set, query, tsvq[j]->nearest(query, nullptr, 0));
            // Best-first: the leaves visited with k candidates are the first k visited with
            // more, so the result never gets worse as k grows, and never beats the oracle.
            ASSERT_LE(d, previous) << "query " << q << " candidates " << ks[j];
            ASSERT_GE(d, best);
            previous = d;
            ratio[j] += double(d) / double(best);
        }
        ++n;
    }
    for (double& r : ratio)
        r /= double(n);
    // Mean ratio of squared distances to the exact nearest one's. Measured 1.25, 1.17, 1.11,
    // 1.07, 1.05, 1.02; the bounds leave ~0.1 (0.03 at 64) for changes in the splits.
    const std::vector<double> bound = { 1.35, 1.27, 1.2, 1.15, 1.1, 1.05 };
    for (size_t j = 0; j < ks.size(); ++j)
        EXPECT_LE(ratio[j], bound[j]) << "candidates " << ks[j];
    EXPECT_LT(ratio.back(), ratio.front());
}

TEST(Tsvq, IdenticalVectorsDoNotBreakTheBuild)
{
    const int dim = 12;
    // All equal: one leaf, found at once; the lowest index wins the tie.
    const std::vector<float> same(5000 * dim, 0.25f);
    auto tsvq = searcher({ same.data(), 5000, dim }, SearchMethod::Tsvq, 4);
    const std::vector<float> query(dim, 0.5f);
    EXPECT_EQ(tsvq->nearest(query.data(), nullptr, 0), 0u);
    // The index array, one block of (up to 256) codewords, the queue.
    EXPECT_LT(tsvq->memory_bytes(), 5000 * 4 + 256 * dim * 4 + 1024u);

    // Two values alternating: every vector is equidistant from the root's centroid.
    std::vector<float> two(5000 * dim);
    for (size_t i = 0; i < 5000; ++i)
        std::fill_n(two.begin() + long(i * dim), dim, i % 2 ? 1.0f : 0.0f);
    auto split = searcher({ two.data(), 5000, dim }, SearchMethod::Tsvq);
    EXPECT_EQ(split->nearest(query.data(), nullptr, 0), 0u);
    const std::vector<float> high(dim, 0.9f);
    EXPECT_EQ(split->nearest(high.data(), nullptr, 0), 1u);
}

TEST(Tsvq, ResultIgnoresThreadCount)
{
    // 20000 x 64 floats: the upper levels of the tree are built in parallel.
    const int dim = 64;
    const std::vector<float> data = clustered(0, 20000, dim, 300, 0.15f, 3);
    const VectorSet set { data.data(), 20000, dim };
    const std::vector<float> queries = clustered(20000, 400, dim, 300, 0.15f, 3);
    for (int k : { 1, 4 }) {
        auto one = searcher(set, SearchMethod::Tsvq, k, 1);
        auto four = searcher(set, SearchMethod::Tsvq, k, 4);
        EXPECT_EQ(one->memory_bytes(), four->memory_bytes());
        for (size_t q = 0; q < 400; ++q)
            ASSERT_EQ(one->nearest(queries.data() + q * dim, nullptr, 0),
                four->nearest(queries.data() + q * dim, nullptr, 0))
                << q;
    }
}

TEST(Tsvq, MemoryIsAFractionOfTheVectorSet)
{
    // Leaves hold 1..16 vectors (11 on average on texture data), so the tree has about
    // count / 5.5 nodes of dim floats each, plus a 4-byte index per vector: 0.2x the vector
    // set here (dim 120). Bound: 0.3x.
    VectorSet set;
    const detail::SampleVectors data = rust_vectors(0, 0, 128, 128, set);
    auto tsvq = searcher(set, SearchMethod::Tsvq, 8);
    const double vector_bytes = double(set.count) * set.dim * sizeof(float);
    EXPECT_LT(double(tsvq->memory_bytes()), 0.3 * vector_bytes);
    EXPECT_GT(double(tsvq->memory_bytes()), 0.1 * vector_bytes); // it does hold codewords
}

TEST(Tsvq, RejectsZeroCandidates)
{
    const std::vector<float> data(16, 0.0f);
    SearchSettings s;
    s.method = SearchMethod::Tsvq;
    s.candidates = 0;
    std::string error;
    EXPECT_FALSE(make_search({ data.data(), 4, 4 }, s, error));
    EXPECT_NE(error.find("candidates=0"), std::string::npos) << error;
}

TEST(Tsvq, SynthesisMatchesTheExhaustiveOnesHistograms)
{
    // rust.png's top-left 64x64 grown to 96x96, one level, n=9, candidates=4. The output
    // copies sample pixels, so its per-channel value distribution should be the sample's;
    // TSVQ takes a near-best match where the exhaustive search takes the best, which
    // should not shift the colours.
    const OIIO::ImageBuf sample
        = OIIO::ImageBufAlgo::cut(test::linear_sample("rust.png"), OIIO::ROI(0, 64, 0, 64));
    NeighborhoodOptions opt;
    opt.width = opt.height = 96;
    opt.levels = 1;
    opt.n = { 9 };
    opt.seed = 3;
    opt.search = SearchMethod::Exhaustive;
    const PlanarImage exact = test::planes_of(neighborhood_synthesize(sample, opt));
    opt.search = SearchMethod::Tsvq;
    opt.candidates = 4;
    const PlanarImage tsvq = test::planes_of(neighborhood_synthesize(sample, opt));
    const PlanarImage s = test::planes_of(sample);
    for (size_t c = 0; c < 3; ++c) {
        const QuantileTable ts(s.channels[c]), te(exact.channels[c]), tt(tsvq.channels[c]);
        double mean = 0, var = 0;
        for (float v : ts.sorted())
            mean += v;
        mean /= double(ts.sorted().size());
        for (float v : ts.sorted())
            var += (v - mean) * (v - mean);
        const double sigma = std::sqrt(var / double(ts.sorted().size()));
        // W1 distances in units of the sample's standard deviation. A 64x64 sample grown
        // 1.5x at one level over- and under-uses whole regions: over seeds 1-6 the
        // exhaustive output itself is 0.05-0.23 sigma from the sample, and TSVQ's 0.10-0.26
        // (at most 0.11 further than the exhaustive one's, 0.04-0.17 from it). So the
        // bounds are relative to that spread, not a few %: TSVQ at most 0.15 sigma further
        // from the sample than the exhaustive output, under 0.3 sigma from the sample and
        // under 0.2 sigma from the exhaustive output. (Seed 3: 0.08-0.16, 0.12-0.23 and
        // 0.07-0.14.)
        const double exact_to_sample = wasserstein1(te, ts) / sigma;
        const double tsvq_to_sample = wasserstein1(tt, ts) / sigma;
        const double tsvq_to_exact = wasserstein1(tt, te) / sigma;
        EXPECT_LT(tsvq_to_sample, 0.3) << c;
        EXPECT_LT(tsvq_to_sample, exact_to_sample + 0.15) << c;
        EXPECT_LT(tsvq_to_exact, 0.2) << c;
    }
}
