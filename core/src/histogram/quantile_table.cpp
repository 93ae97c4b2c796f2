// SPDX-License-Identifier: Apache-2.0
#include <texsyn/histogram.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "histogram_pvt.h"

namespace texsyn {

QuantileTable::QuantileTable(const float* values, size_t n)
    : m_sorted(n)
{
    // The O(n) radix ranking of match_histogram: analysis sorts every band of the sample.
    const uint64_t* order = histogram_pvt::rank_by_value(values, n, 1);
    for (size_t i = 0; i < n; ++i)
        m_sorted[i] = values[order ? size_t(uint32_t(order[i])) : i];
}

QuantileTable QuantileTable::from_sorted(std::vector<float> sorted)
{
    QuantileTable t;
    t.m_sorted = std::move(sorted);
    // Cheap guard: an unsorted table would make quantile() non-monotone.
    if (!std::is_sorted(t.m_sorted.begin(), t.m_sorted.end()))
        std::sort(t.m_sorted.begin(), t.m_sorted.end());
    return t;
}

float QuantileTable::quantile(double u) const
{
    if (m_sorted.empty())
        return 0.0f;
    return histogram_pvt::quantile_of_sorted(m_sorted.data(), m_sorted.size(), u);
}

namespace {

// Integral over [u0, u1] of |d| for d linear from d0 to d1.
double abs_linear_integral(double d0, double d1, double len)
{
    if ((d0 >= 0) == (d1 >= 0) || d0 == 0 || d1 == 0)
        return 0.5 * (std::abs(d0) + std::abs(d1)) * len;
    // Sign change: two triangles meeting at the zero crossing.
    return 0.5 * (d0 * d0 + d1 * d1) / (std::abs(d0) + std::abs(d1)) * len;
}

} // namespace

// Exact: both quantile functions are piecewise linear with knots at (k + 0.5)/m, so
// integrating |Qa - Qb| over the merged knots (plus 0 and 1) is exact up to rounding.
double wasserstein1(const QuantileTable& a, const QuantileTable& b)
{
    if (a.empty() || b.empty())
        return 0.0;
    const std::vector<float>& sa = a.sorted();
    const std::vector<float>& sb = b.sorted();
    const size_t ma = sa.size(), mb = sb.size();
    size_t ka = 0, kb = 0;
    double u0 = 0.0, d0 = double(sa.front()) - double(sb.front());
    double sum = 0.0;
    while (u0 < 1.0) {
        const double ua = ka < ma ? (double(ka) + 0.5) / double(ma) : 1.0;
        const double ub = kb < mb ? (double(kb) + 0.5) / double(mb) : 1.0;
        const double u1 = std::min(ua, ub);
        if (ua == u1)
            ++ka;
        if (ub == u1)
            ++kb;
        const double d1 = histogram_pvt::quantile_of_sorted_d(sa.data(), ma, u1)
            - histogram_pvt::quantile_of_sorted_d(sb.data(), mb, u1);
        sum += abs_linear_integral(d0, d1, u1 - u0);
        u0 = u1;
        d0 = d1;
    }
    return sum;
}

} // namespace texsyn
