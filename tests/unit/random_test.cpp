// SPDX-License-Identifier: Apache-2.0
#include <texsyn/random.h>

#include <set>

#include <gtest/gtest.h>

using namespace texsyn;

TEST(Random, IsAPureFunctionOfItsArguments)
{
    EXPECT_EQ(random_bits(1, 2, 3), random_bits(1, 2, 3));
    EXPECT_NE(random_bits(1, 2, 3), random_bits(1, 2, 4));
    EXPECT_NE(random_bits(1, 2, 3), random_bits(1, 3, 3));
    EXPECT_NE(random_bits(1, 2, 3), random_bits(2, 2, 3));
    // Swapping words must not collide (a plain XOR of the inputs would).
    EXPECT_NE(random_bits(0, 1, 2), random_bits(0, 2, 1));
}

TEST(Random, UniformIsInRangeWithTheRightMoments)
{
    const int n = 200000;
    double sum = 0.0, sum2 = 0.0;
    int buckets[10] = {};
    for (int i = 0; i < n; ++i) {
        float u = random_uniform(7, 0, uint64_t(i));
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        sum += u;
        sum2 += double(u) * u;
        ++buckets[int(u * 10)];
    }
    // Standard error of the mean is 1/sqrt(12 n) = 6.5e-4; 5 sigma.
    EXPECT_NEAR(sum / n, 0.5, 3.3e-3);
    EXPECT_NEAR(sum2 / n - (sum / n) * (sum / n), 1.0 / 12.0, 2e-3);
    // Each decile holds n/10 = 20000 draws, standard deviation ~134; 5 sigma.
    for (int b : buckets)
        EXPECT_NEAR(b, n / 10, 670);
}

TEST(Random, NoCollisionsInAMillionBits)
{
    std::set<uint64_t> seen;
    for (uint64_t i = 0; i < 1000000; ++i)
        seen.insert(random_bits(0, 0, i));
    EXPECT_EQ(seen.size(), 1000000u);
}
