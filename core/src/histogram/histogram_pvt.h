// SPDX-License-Identifier: Apache-2.0
// Private helpers shared by the histogram sources.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace texsyn {
namespace histogram_pvt {

/// Q(u) of sorted values s[0..m-1]: linear interpolation at position u*m - 0.5, clamped,
/// in double (exact integrals and barycentres need it unrounded).
inline double quantile_of_sorted_d(const float* s, size_t m, double u)
{
    const double pos = u * double(m) - 0.5;
    if (!(pos > 0.0)) // also catches NaN u
        return s[0];
    if (pos >= double(m - 1))
        return s[m - 1];
    const size_t i = size_t(pos);
    const double f = pos - double(i);
    return double(s[i]) + f * (double(s[i + 1]) - double(s[i]));
}

/// The same, rounded to float. One definition, so match_histogram and
/// QuantileTable::quantile agree bit for bit; a + f*(b - a) in double stays in [a, b] after
/// rounding to float, so it is monotone in u.
inline float quantile_of_sorted(const float* s, size_t m, double u)
{
    return float(quantile_of_sorted_d(s, m, u));
}

/// Orders the n values by (value, index) with an O(n) LSD radix sort. Returns n packed
/// entries (monotone key << 32 | index) in ascending order, or nullptr when all values
/// are equal (the order is then the identity). The storage is thread-local scratch, valid
/// until the calling thread's next call. Requires n < 2^32.
const uint64_t* rank_by_value(const float* values, size_t n, int nthreads);

/// Exact histogram matching in place: values[j] = Q((rank_j + 0.5)/n) with Q the quantile
/// function of sorted[0..m-1] and rank_j the (value, index) rank of j. The quantile
/// write-back is fused with the last radix pass (one scatter fewer than ranking first).
/// Requires n < 2^32, m >= 1.
void assign_quantiles_by_rank(float* values, size_t n, const float* sorted, size_t m, int nthreads);

} // namespace histogram_pvt
} // namespace texsyn
