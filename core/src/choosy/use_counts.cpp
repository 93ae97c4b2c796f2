// SPDX-License-Identifier: Apache-2.0
// UseCounts (choosy_pvt.h): Algorithm 2's c[] and c_min, and the penalty they give.
#include "choosy_pvt.h"

#include <algorithm>
#include <cmath>

namespace texsyn::detail {

namespace {
// Penalties are tabulated this far above c_min; beyond it the last (capped) value applies.
constexpr size_t kFactorTable = 128;
constexpr double kFactorCap = 1e30;
} // namespace

UseCounts::UseCounts(size_t nsites, float penalty)
    : m_counts(nsites, 0)
    , m_penalized(penalty > 0.0f)
{
    // The paper scales the distance by 2^(c - c_min) per unit of penalty; on the squared
    // distance that is 4^(penalty (c - c_min)). Exact powers of two for integer penalties.
    m_factors.resize(kFactorTable);
    for (size_t d = 0; d < kFactorTable; ++d)
        m_factors[d] = float(std::min(kFactorCap, std::exp2(2.0 * double(penalty) * double(d))));
    reset();
}

void UseCounts::reset()
{
    std::fill(m_counts.begin(), m_counts.end(), 0u);
    m_histogram.assign(1, m_counts.size());
    m_min = 0;
}

void UseCounts::add(size_t site)
{
    const uint32_t c = m_counts[site]++;
    --m_histogram[c];
    if (c + 1 >= m_histogram.size())
        m_histogram.push_back(0);
    ++m_histogram[c + 1];
    while (m_histogram[m_min] == 0)
        ++m_min;
}

} // namespace texsyn::detail
