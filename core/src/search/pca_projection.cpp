// SPDX-License-Identifier: Apache-2.0
// PcaProjection (pca_pvt.h): covariance of a strided subsample, Eigen's self-adjoint
// eigen-solver, components kept as float rows for a vectorisable projection.
#include "pca_pvt.h"

#include <algorithm>

#include <Eigen/Dense>

namespace texsyn::detail {

namespace {

// a . b in eight interleaved lanes (the loop vectorises), then added pairwise.
float dot(const float* a, const float* b, int n)
{
    float acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    int i = 0;
    for (; i + 8 <= n; i += 8)
        for (int l = 0; l < 8; ++l)
            acc[l] += a[i + l] * b[i + l];
    for (int l = 0; i + l < n; ++l)
        acc[l] += a[i + l] * b[i + l];
    return ((acc[0] + acc[4]) + (acc[1] + acc[5])) + ((acc[2] + acc[6]) + (acc[3] + acc[7]));
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
    // Centred float data: rounding stays far below the variances that decide the ranking.
    Eigen::MatrixXf covariance = Eigen::MatrixXf::Zero(dim, dim);
    covariance.selfadjointView<Eigen::Lower>().rankUpdate(x.transpose(), 1.0f / float(samples));
    x.resize(0, 0);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        covariance.cast<double>(), Eigen::ComputeEigenvectors);
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
            = dot(m_components.data() + size_t(j) * size_t(m_dim), v, m_dim) - m_offsets[size_t(j)];
}

size_t PcaProjection::memory_bytes() const
{
    return (m_components.size() + m_offsets.size()) * sizeof(float)
        + m_variances.size() * sizeof(double);
}

} // namespace texsyn::detail
