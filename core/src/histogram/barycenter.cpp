// SPDX-License-Identifier: Apache-2.0
// The 1-D Wasserstein barycentre: Heeger & Bergen §5's "averaging their pyramid
// histograms", done on quantile functions so that the average of two textures' band
// distributions is a distribution between them rather than a two-peaked sum.
#include <texsyn/histogram.h>

#include <algorithm>

#include "histogram_pvt.h"

namespace texsyn {

QuantileTable wasserstein_barycenter(
    const std::vector<const QuantileTable*>& tables, const std::vector<double>& weights)
{
    if (tables.empty() || tables.size() != weights.size())
        return {};
    double total = 0.0;
    size_t n = 0;
    for (size_t k = 0; k < tables.size(); ++k) {
        if (!tables[k] || tables[k]->empty() || !(weights[k] >= 0.0))
            return {};
        total += weights[k];
        if (weights[k] > 0.0)
            n = std::max(n, tables[k]->sorted().size());
    }
    if (!(total > 0.0))
        return {};

    std::vector<double> sum(n, 0.0);
    for (size_t k = 0; k < tables.size(); ++k) {
        if (weights[k] == 0.0)
            continue;
        const double w = weights[k] / total;
        const std::vector<float>& s = tables[k]->sorted();
        // A table of n values has its knots exactly at (i + 0.5)/n: take them as they are
        // (interpolating there would round), so weight 1 reproduces the table bit for bit.
        if (s.size() == n)
            for (size_t i = 0; i < n; ++i)
                sum[i] += w * double(s[i]);
        else
            for (size_t i = 0; i < n; ++i)
                sum[i] += w
                    * histogram_pvt::quantile_of_sorted_d(
                        s.data(), s.size(), (double(i) + 0.5) / double(n));
    }
    // Each Q_k is non-decreasing and the weights are >= 0, so the sum is too, and rounding
    // to float is monotone: sorted by construction.
    std::vector<float> values(n);
    for (size_t i = 0; i < n; ++i)
        values[i] = float(sum[i]);
    return QuantileTable::from_sorted(std::move(values));
}

} // namespace texsyn
