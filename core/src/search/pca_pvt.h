// SPDX-License-Identifier: Apache-2.0
// Principal component projection of a vector set: the dimension reduction in front of the
// kd-tree (search.h, SearchMethod::KdTree).
#pragma once

#include <cstddef>
#include <vector>

#include <texsyn/search.h>

namespace texsyn::detail {

/// The leading principal components of a VectorSet and the projection onto them.
/// Fitting is deterministic (a fixed subsample, serial arithmetic); the components are
/// orthonormal, so with every component kept projected distances equal full distances
/// (up to float rounding).
/// Thread safety: immutable after construction; project() may be called concurrently.
class PcaProjection {
public:
    /// At most this many vectors (evenly strided over the set) estimate the covariance.
    static constexpr size_t kMaxSamples = 4096;

    /// Fits `vectors` (count >= 1): the covariance of the (sub)sample, its eigenvectors by
    /// decreasing eigenvalue. Keeps `dims` components if dims > 0 (at most dim), otherwise
    /// the fewest whose eigenvalues sum to at least `fraction` of the total (at least 1).
    /// May throw std::bad_alloc.
    PcaProjection(const VectorSet& vectors, int dims, double fraction);

    int input_dim() const { return m_dim; }
    int output_dim() const { return m_out; }

    /// Every eigenvalue of the sample covariance (dim of them), decreasing, negatives
    /// (rounding) clamped to 0.
    const std::vector<double>& variances() const { return m_variances; }

    /// The fraction of the sample's total variance the kept components hold (1 if the
    /// total is 0).
    double explained() const;

    /// out[j] = component_j . (v - mean) for j < output_dim(); v holds input_dim() floats.
    void project(const float* v, float* out) const;

    /// Bytes held (mean, components, offsets, eigenvalues).
    size_t memory_bytes() const;

private:
    int m_dim = 0;
    int m_out = 0;
    std::vector<float> m_components; // output_dim x input_dim, row-major
    std::vector<float> m_offsets;    // component_j . mean: subtracted after the dot product
    std::vector<double> m_variances;
};

} // namespace texsyn::detail
