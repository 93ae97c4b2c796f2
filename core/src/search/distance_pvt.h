// SPDX-License-Identifier: Apache-2.0
// The squared distance every search back-end uses, inline so their inner loops vectorise:
// eight interleaved partial sums (one SIMD register of lanes), added in a fixed pairwise
// order. search.h's squared_distance and squared_distance_below are these.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

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

/// Asks the cache for a vector of `dim` floats ahead of its use: candidate vectors lie
/// anywhere in the set (tens of MB), so evaluating a list of them one after the other
/// would wait for memory once per vector instead of once per list.
inline void prefetch_row(const float* row, int dim)
{
    const char* p = reinterpret_cast<const char*>(row);
    const char* end = reinterpret_cast<const char*>(row + dim);
#if defined(__GNUC__)
    for (; p < end; p += 64)
        __builtin_prefetch(p);
#else
    (void)p;
    (void)end;
#endif
}

/// The nearest of candidates offered one at a time, by distance2 to `query`; ties go to the
/// lowest index whatever the order of the offers (search.h's rule). Distances are bounded
/// by the best so far, so a losing candidate costs only part of its sum.
class NearestCandidate {
public:
    static constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

    NearestCandidate(const float* query, int dim)
        : m_query(query)
        , m_dim(dim)
    { }

    void offer(uint32_t index, const float* row)
    {
        if (m_index == kNone) {
            m_distance = distance2(m_query, row, m_dim);
            m_index = index;
            return;
        }
        // A lower index also wins an equal distance: bound just above the best so that an
        // equal sum comes back exact (distance2_below is exact below its bound).
        const float bound = index < m_index
            ? std::nextafter(m_distance, std::numeric_limits<float>::infinity())
            : m_distance;
        const float d = distance2_below(m_query, row, m_dim, bound);
        if (d < bound) {
            m_distance = d;
            m_index = index;
        }
    }

    bool found() const { return m_index != kNone; }
    uint32_t index() const { return m_index; }
    float distance() const { return m_distance; }

private:
    const float* m_query;
    int m_dim;
    float m_distance = std::numeric_limits<float>::infinity();
    uint32_t m_index = kNone;
};

} // namespace texsyn::detail
