// SPDX-License-Identifier: Apache-2.0
// The squared distance every search back-end uses, inline so their inner loops vectorise:
// eight interleaved partial sums (one SIMD register of lanes), added in a fixed pairwise
// order. search.h's squared_distance and squared_distance_below are these.
#pragma once

namespace texsyn::detail {

/// The eight lanes of a partial sum, added in a fixed order.
inline float sum_lanes(const float* acc)
{
    return ((acc[0] + acc[4]) + (acc[1] + acc[5])) + ((acc[2] + acc[6]) + (acc[3] + acc[7]));
}

/// Adds (a[i] - b[i])^2 for i in [begin, end) to the lanes (lane = i mod 8 of the block).
inline void accumulate_lanes(const float* a, const float* b, int begin, int end, float* acc)
{
    int i = begin;
    for (; i + 8 <= end; i += 8)
        for (int l = 0; l < 8; ++l) {
            const float d = a[i + l] - b[i + l];
            acc[l] += d * d;
        }
    for (int l = 0; i + l < end; ++l) {
        const float d = a[i + l] - b[i + l];
        acc[l] += d * d;
    }
}

inline float distance2(const float* a, const float* b, int dim)
{
    float acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    accumulate_lanes(a, b, 0, dim, acc);
    return sum_lanes(acc);
}

/// distance2(a, b, dim) if it is < bound, else a value >= bound. Checked every 32
/// components; exact because every lane only grows and sum_lanes is monotone in each.
inline float distance2_below(const float* a, const float* b, int dim, float bound)
{
    float acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    constexpr int block = 32;
    int i = 0;
    for (; i + block < dim; i += block) {
        accumulate_lanes(a, b, i, i + block, acc);
        const float partial = sum_lanes(acc);
        if (partial >= bound)
            return partial;
    }
    accumulate_lanes(a, b, i, dim, acc);
    return sum_lanes(acc);
}

} // namespace texsyn::detail
