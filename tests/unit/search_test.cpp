// SPDX-License-Identifier: Apache-2.0
// The search interface and the exhaustive back-end (the oracle of the others).
#include <texsyn/random.h>
#include <texsyn/search.h>

#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "test_vectors.h"

using namespace texsyn;

namespace {

using test::random_vectors;

// The reference: double-precision distances, lowest index on ties.
uint32_t brute_force(const VectorSet& set, const float* q)
{
    double best = std::numeric_limits<double>::infinity();
    uint32_t index = 0;
    for (size_t i = 0; i < set.count; ++i) {
        double d = 0;
        for (int k = 0; k < set.dim; ++k)
            d += (double(q[k]) - set.row(i)[k]) * (double(q[k]) - set.row(i)[k]);
        if (d < best) {
            best = d;
            index = uint32_t(i);
        }
    }
    return index;
}

std::unique_ptr<NeighborSearch> exhaustive(const VectorSet& set, int nthreads = 0)
{
    SearchSettings s;
    s.method = SearchMethod::Exhaustive;
    s.nthreads = nthreads;
    std::string error;
    auto search = make_search(set, s, error);
    EXPECT_TRUE(search) << error;
    return search;
}

} // namespace

TEST(Search, DistanceIsTheSumOfSquares)
{
    for (int dim : { 1, 7, 8, 9, 31, 32, 33, 65, 243 }) {
        const std::vector<float> a = random_vectors(1, dim, 1), b = random_vectors(1, dim, 2);
        double want = 0;
        for (int k = 0; k < dim; ++k)
            want += (double(a[size_t(k)]) - b[size_t(k)]) * (double(a[size_t(k)]) - b[size_t(k)]);
        EXPECT_NEAR(squared_distance(a.data(), b.data(), dim), want, 1e-5 * want) << dim;
    }
}

TEST(Search, BoundedDistanceIsExactBelowTheBound)
{
    const int dim = 100;
    const std::vector<float> v = random_vectors(200, dim, 3);
    for (size_t i = 1; i < 200; ++i) {
        const float d = squared_distance(v.data(), v.data() + i * dim, dim);
        for (float bound : { d * 0.5f, d, std::nextafter(d, 1e30f), d * 2.0f }) {
            const float b = squared_distance_below(v.data(), v.data() + i * dim, dim, bound);
            if (d < bound)
                EXPECT_EQ(b, d);
            else
                EXPECT_GE(b, bound);
        }
    }
}

TEST(Search, ExhaustiveFindsTheNearest)
{
    const int dim = 75;
    const std::vector<float> data = random_vectors(5000, dim, 4);
    const VectorSet set { data.data(), 5000, dim };
    auto search = exhaustive(set);
    const std::vector<float> queries = random_vectors(50, dim, 5);
    for (size_t q = 0; q < 50; ++q)
        EXPECT_EQ(search->nearest(queries.data() + q * dim, nullptr, 0),
            brute_force(set, queries.data() + q * dim));
    // A vector of the set is its own nearest.
    EXPECT_EQ(search->nearest(set.row(4321), nullptr, 0), 4321u);
}

TEST(Search, ExhaustiveBreaksTiesByLowestIndex)
{
    // 6000 vectors (three scan chunks), all copies of two vectors.
    const int dim = 16;
    std::vector<float> data(6000 * dim);
    for (size_t i = 0; i < 6000; ++i)
        for (int k = 0; k < dim; ++k)
            data[i * dim + size_t(k)] = (i % 2 == 0 || i < 3000) ? 1.0f : 0.0f;
    const VectorSet set { data.data(), 6000, dim };
    const std::vector<float> zero(dim, 0.0f), one(dim, 1.0f);
    for (int threads : { 1, 2, 5 }) {
        auto search = exhaustive(set, threads);
        EXPECT_EQ(search->nearest(zero.data(), nullptr, 0), 3001u);
        EXPECT_EQ(search->nearest(one.data(), nullptr, 0), 0u);
    }
}

TEST(Search, ExhaustiveIgnoresThreadCount)
{
    const int dim = 200;
    const std::vector<float> data = random_vectors(20000, dim, 6);
    const VectorSet set { data.data(), 20000, dim };
    const std::vector<float> queries = random_vectors(20, dim, 7);
    auto one = exhaustive(set, 1), many = exhaustive(set, 4);
    for (size_t q = 0; q < 20; ++q)
        EXPECT_EQ(one->nearest(queries.data() + q * dim, nullptr, 0),
            many->nearest(queries.data() + q * dim, nullptr, 0));
}

TEST(Search, RejectsAnEmptySet)
{
    std::string error;
    SearchSettings s;
    EXPECT_FALSE(make_search(VectorSet {}, s, error));
    EXPECT_NE(error.find("vectors"), std::string::npos) << error;
}
