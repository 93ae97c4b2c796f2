// SPDX-License-Identifier: Apache-2.0
// PcaProjection (pca_pvt.h): covariance of a strided subsample, Eigen's self-adjoint
// eigen-solver, components kept as float rows for a vectorisable projection. The same
// components on every machine: nothing here depends on the CPU's cache sizes.
#include "pca_pvt.h"

#include <algorithm>

#include <Eigen/Dense>

namespace texsyn::detail {

namespace {

// a . b summed in `Lanes` interleaved lanes (the loop vectorises), then lane l with lane
// l + Lanes / 2 and neighbours pairwise: a fixed order, whatever the machine.
template <class T, size_t Lanes>
T lane_dot(const T* a, const T* b, size_t n)
{
    T acc[Lanes] = {};
    size_t i = 0;
    for (; i + Lanes <= n; i += Lanes)
        for (size_t l = 0; l < Lanes; ++l)
            acc[l] += a[i + l] * b[i + l];
    for (size_t l = 0; i + l < n; ++l)
        acc[l] += a[i + l] * b[i + l];
    T pair[Lanes / 2];
    for (size_t l = 0; l < Lanes / 2; ++l)
        pair[l] = acc[l] + acc[l + Lanes / 2];
    for (size_t w = Lanes / 2; w > 1; w /= 2)
        for (size_t l = 0; l < w / 2; ++l)
            pair[l] = pair[2 * l] + pair[2 * l + 1];
    return pair[0];
}

} // namespace

PcaProjection::PcaProjection(const VectorSet& vectors, int dims, double fraction)
    : m_dim(vectors.dim)
{
    const size_t samples = std::min(vectors.count, kMaxSamples);
    const Eigen::Index dim = m_dim;
    // Sample s is vector floor(s * count / samples): evenly spread, the same every run.
    Eigen::MatrixXf x(Eigen::Index(samples), dim);
    for (size_t s = 0; s < samples; ++s)
        x.row(Eigen::Index(s))
            = Eigen::Map<const Eigen::RowVectorXf>(vectors.row(s * vectors.count / samples), dim);
    const Eigen::RowVectorXd mean = x.cast<double>().colwise().mean();
    x.rowwise() -= mean.cast<float>();
    // The covariance of the centred data, summed sample by sample in double. Not Eigen's
    // product (rankUpdate): it splits the sum into blocks sized by the CPU's caches, so the
    // components, and every kd-tree search after them, would differ between machines.
    const Eigen::MatrixXd centred = x.cast<double>();
    x.resize(0, 0);
    Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(dim, dim);
    for (Eigen::Index j = 0; j < dim; ++j)
        for (Eigen::Index i = j; i < dim; ++i) {
            const double sum
                = lane_dot<double, 4>(centred.col(i).data(), centred.col(j).data(), samples);
            covariance(i, j) = covariance(j, i) = sum / double(samples);
        }
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        covariance, Eigen::ComputeEigenvectors);
    // Eigen returns eigenvalues in increasing order: component j is column dim - 1 - j.
    m_variances.resize(size_t(dim));
    double total = 0.0;
    for (Eigen::Index j = 0; j < dim; ++j) {
        m_variances[size_t(j)] = std::max(0.0, solver.eigenvalues()[dim - 1 - j]);
        total += m_variances[size_t(j)];
    }
    if (dims > 0) {
        m_out = std::min(dims, m_dim);
    } else {
        double kept = 0.0;
        m_out = 0;
        while (m_out < m_dim && (m_out == 0 || kept < fraction * total))
            kept += m_variances[size_t(m_out++)];
    }
    m_components.resize(size_t(m_out) * size_t(m_dim));
    m_offsets.resize(size_t(m_out));
    for (int j = 0; j < m_out; ++j) {
        float* c = m_components.data() + size_t(j) * size_t(m_dim);
        const auto column = solver.eigenvectors().col(dim - 1 - j);
        for (int i = 0; i < m_dim; ++i)
            c[i] = float(column[i]);
        m_offsets[size_t(j)] = float(column.dot(mean.transpose()));
    }
}

double PcaProjection::explained() const
{
    double total = 0.0, kept = 0.0;
    for (size_t j = 0; j < m_variances.size(); ++j) {
        total += m_variances[j];
        if (j < size_t(m_out))
            kept += m_variances[j];
    }
    return total > 0.0 ? kept / total : 1.0;
}

void PcaProjection::project(const float* v, float* out) const
{
    for (int j = 0; j < m_out; ++j)
        out[j]
            = lane_dot<float, 8>(m_components.data() + size_t(j) * size_t(m_dim), v, size_t(m_dim))
            - m_offsets[size_t(j)];
}

size_t PcaProjection::memory_bytes() const
{
    return (m_components.size() + m_offsets.size()) * sizeof(float)
        + m_variances.size() * sizeof(double);
}

} // namespace texsyn::detail
