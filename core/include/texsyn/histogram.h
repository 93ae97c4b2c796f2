// SPDX-License-Identifier: Apache-2.0
// Histogram matching (Heeger & Bergen 1995 §3.2; notes/pyramid-math.md).
//
// A target distribution is prepared once (sorted values) and matched many times, so the
// per-iteration cost is ranking the source only. Source and target may differ in size.
// Deterministic: ties in the source are ranked by index. `nthreads` as in OIIO; results
// do not depend on it.
#pragma once

#include <cstddef>
#include <vector>

#include <texsyn/image.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

enum class HistogramMode {
    Exact,   ///< quantile matching: out[rank i] = Q((i + 0.5)/n) — the default
    Bins256, ///< the paper's 256-bin cdf / inverse-cdf with linear interpolation
};

/// "exact" or "bins256".
const char* histogram_mode_name(HistogramMode mode);

/// The distribution of a set of values (a band of the sample), prepared for matching.
/// Immutable after construction; thread safe.
class QuantileTable {
public:
    QuantileTable() = default;
    /// Copies and sorts `n` finite values (n >= 1).
    QuantileTable(const float* values, size_t n);
    explicit QuantileTable(const Plane& plane)
        : QuantileTable(plane.data(), plane.size())
    { }
    /// Builds from values that are already sorted ascending (e.g. read from a file).
    static QuantileTable from_sorted(std::vector<float> sorted);

    /// Quantile function: linear interpolation of the sorted values at position u*m - 0.5,
    /// clamped to [min, max]; u in [0, 1].
    float quantile(double u) const;
    const std::vector<float>& sorted() const { return m_sorted; }
    bool empty() const { return m_sorted.empty(); }

private:
    std::vector<float> m_sorted;
};

/// Replaces the values of `plane` so that their histogram matches `target` (monotone,
/// order-preserving remap). Exact mode: out[idx[i]] = target.quantile((i + 0.5)/n) where
/// idx orders the source by value, ties by index. Bins256: the paper's method.
void match_histogram(
    Plane& plane, const QuantileTable& target, HistogramMode mode, int nthreads = 0);

/// The 1-D Wasserstein barycentre of distributions: the quantile function
/// Q(u) = sum_k w_k Q_k(u), with the weights normalised to sum 1 — the average of the
/// distributions' quantile functions, not of their bin counts (averaging two narrow peaks
/// gives one peak in between, not two). Evaluated at n points u = (i + 0.5)/n, n the
/// largest table among those with w_k > 0; a table of n values contributes its own values
/// there, so weights (1, 0, …) return the first table exactly. Sorted by construction.
/// Requires tables.size() == weights.size(), no empty table, weights >= 0 with a positive
/// sum; returns an empty table otherwise.
QuantileTable wasserstein_barycenter(
    const std::vector<const QuantileTable*>& tables, const std::vector<double>& weights);

/// 1-D Wasserstein distance between the value distributions of `a` and `b`
/// (mean absolute difference of their quantile functions). Used by quality tests.
double wasserstein1(const QuantileTable& a, const QuantileTable& b);

} // namespace texsyn
#pragma GCC visibility pop
