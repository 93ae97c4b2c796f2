// SPDX-License-Identifier: Apache-2.0
// The squared distance every search back-end uses, inline so that their inner loops keep
// the eight interleaved partial sums in registers, added in a fixed pairwise order.
// search.h's squared_distance and squared_distance_below are these.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include <OpenImageIO/simd.h>

namespace texsyn::detail {

/// A partial sum of squared differences in eight interleaved lanes (two SIMD registers),
/// added in a fixed pairwise order, so that the sum of a given sequence of add() calls is
/// the same bits on every machine and whatever the thread count.
class SquaredDifferenceLanes {
public:
    /// Adds (a[i] - b[i])^2 for i in [0, n) to lane i mod 8.
    void add(const float* a, const float* b, int n)
    {
        using OIIO::simd::vfloat4;
        int i = 0;
        for (; i + 8 <= n; i += 8) {
            const vfloat4 d0 = vfloat4(a + i) - vfloat4(b + i);
            const vfloat4 d1 = vfloat4(a + i + 4) - vfloat4(b + i + 4);
            m_low += d0 * d0;
            m_high += d1 * d1;
        }
        if (i + 4 <= n) {
            const vfloat4 d = vfloat4(a + i) - vfloat4(b + i);
            m_low += d * d;
            i += 4;
            if (i < n)
                m_high += squared_first(a + i, b + i, n - i);
        } else if (i < n)
            m_low += squared_first(a + i, b + i, n - i);
    }

    /// Adds (mask[i] (a[i] - b[i]))^2 for i in [0, n) to lane i mod 8; n a multiple of 8.
    void add_masked(const float* a, const float* b, const float* mask, int n)
    {
        using OIIO::simd::vfloat4;
        for (int i = 0; i < n; i += 8) {
            const vfloat4 d0 = (vfloat4(a + i) - vfloat4(b + i)) * vfloat4(mask + i);
            const vfloat4 d1 = (vfloat4(a + i + 4) - vfloat4(b + i + 4)) * vfloat4(mask + i + 4);
            m_low += d0 * d0;
            m_high += d1 * d1;
        }
    }

    /// The lanes added: ((l0 + l4) + (l1 + l5)) + ((l2 + l6) + (l3 + l7)).
    float sum() const
    {
        const OIIO::simd::vfloat4 pairs = m_low + m_high;
        return (pairs[0] + pairs[1]) + (pairs[2] + pairs[3]);
    }

private:
    // (a[l] - b[l])^2 in lanes l < k (k in 1..3), 0 in the others, which adds nothing.
    static OIIO::simd::vfloat4 squared_first(const float* a, const float* b, int k)
    {
        using namespace OIIO::simd;
        vfloat4 va, vb;
        va.load(a, k); // (loads k values; the other lanes are masked off below)
        vb.load(b, k);
        const vfloat4 d = blend0(va - vb, vint4::Iota() < vint4(k));
        return d * d;
    }

    OIIO::simd::vfloat4 m_low = OIIO::simd::vfloat4::Zero();
    OIIO::simd::vfloat4 m_high = OIIO::simd::vfloat4::Zero();
};

inline float distance2(const float* a, const float* b, int dim)
{
    SquaredDifferenceLanes lanes;
    lanes.add(a, b, dim);
    return lanes.sum();
}

/// distance2(a, b, dim) if it is < bound, else a value >= bound. Checked every 32
/// components; exact because every lane only grows and the sum is monotone in each.
inline float distance2_below(const float* a, const float* b, int dim, float bound)
{
    SquaredDifferenceLanes lanes;
    constexpr int block = 32;
    int i = 0;
    for (; i + block < dim; i += block) {
        lanes.add(a + i, b + i, block);
        const float partial = lanes.sum();
        if (partial >= bound)
            return partial;
    }
    lanes.add(a + i, b + i, dim - i);
    return lanes.sum();
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
