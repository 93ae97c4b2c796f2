// SPDX-License-Identifier: Apache-2.0
// PCA colour decorrelation, Heeger & Bergen 1995 §3.5 (notes/pyramid-math.md).
#include <texsyn/color.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Dense>
#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn {

namespace {

// Singular values below this fraction of the largest carry no signal (rounding noise).
constexpr double kRelativeEpsilon = 1e-6;

// Largest-|component| positive (first such component on ties): the eigensolver's sign is
// arbitrary, and a fixed one keeps the pc channels comparable between runs and builds.
void fix_sign(Eigen::Ref<Eigen::VectorXd> v)
{
    Eigen::Index imax = 0;
    for (Eigen::Index i = 1; i < v.size(); ++i)
        if (std::abs(v[i]) > std::abs(v[imax]))
            imax = i;
    if (v[imax] < 0)
        v = -v;
}

// out_r = add_r + sum_c m[r*n + c] * (in_c - sub_c) over the first n channels, in place.
void apply_affine(PlanarImage& image, int n, const std::vector<double>& m,
    const std::vector<double>& sub, const std::vector<double>& add, int nthreads)
{
    if (n < 1 || image.nchannels() < n)
        return; // not fitted to this image: leave it alone
    std::vector<float*> ch(size_t(n), nullptr);
    for (int c = 0; c < n; ++c)
        ch[size_t(c)] = image.channels[size_t(c)].data();
    const int64_t npix = int64_t(image.channels[0].size());
    OIIO::parallel_for_chunked(
        0, npix, int64_t(1) << 14,
        [&](int64_t begin, int64_t end) {
            std::vector<double> x(static_cast<size_t>(n)), y(x.size()); // per chunk: negligible
            for (int64_t i = begin; i < end; ++i) {
                for (int c = 0; c < n; ++c)
                    x[size_t(c)] = double(ch[size_t(c)][i]) - sub[size_t(c)];
                for (int r = 0; r < n; ++r) {
                    double acc = add[size_t(r)];
                    for (int c = 0; c < n; ++c)
                        acc += m[size_t(r * n + c)] * x[size_t(c)];
                    y[size_t(r)] = acc;
                }
                for (int c = 0; c < n; ++c)
                    ch[size_t(c)][i] = float(y[size_t(c)]);
            }
        },
        detail::split_every_item(nthreads));
}

} // namespace

ColorMoments color_moments(const PlanarImage& image, int ncolor)
{
    ColorMoments m;
    const int n = std::max(0, std::min(ncolor, image.nchannels()));
    const size_t npix = n > 0 ? image.channels[0].size() : 0;
    if (n == 0 || npix == 0)
        return m;
    m.n = n;

    // Two passes (mean, then centred products), serial in pixel order: exact same sums
    // whatever the thread count, and no cancellation from E[x^2] - E[x]^2.
    m.mean.assign(size_t(n), 0.0);
    for (int c = 0; c < n; ++c) {
        const float* p = image.channels[size_t(c)].data();
        m.mean[size_t(c)] = std::accumulate(p, p + npix, 0.0) / double(npix);
    }
    Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(n, n);
    std::vector<double> d(static_cast<size_t>(n));
    for (size_t i = 0; i < npix; ++i) {
        for (int c = 0; c < n; ++c)
            d[size_t(c)] = double(image.channels[size_t(c)].data()[i]) - m.mean[size_t(c)];
        for (int r = 0; r < n; ++r)
            for (int c = 0; c <= r; ++c)
                cov(r, c) += d[size_t(r)] * d[size_t(c)];
    }
    cov /= double(npix);
    cov = cov.selfadjointView<Eigen::Lower>();
    m.covariance.assign(cov.data(), cov.data() + n * n); // symmetric: either order
    return m;
}

ColorMoments mixture_moments(const std::vector<ColorMoments>& parts, std::vector<double> weights)
{
    ColorMoments m;
    if (parts.empty() || parts.size() != weights.size())
        return m;
    const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
    if (!(total > 0.0))
        return m;
    const int n = parts[0].n;
    for (const ColorMoments& p : parts)
        if (p.n != n)
            return m;
    m.n = n;
    m.mean.assign(size_t(n), 0.0);
    m.covariance.assign(size_t(n * n), 0.0);
    for (double& w : weights)
        w /= total;
    for (size_t i = 0; i < parts.size(); ++i)
        for (int c = 0; c < n; ++c)
            m.mean[size_t(c)] += weights[i] * parts[i].mean[size_t(c)];
    // Law of total covariance: within-part covariance plus the spread of the part means.
    for (size_t i = 0; i < parts.size(); ++i)
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                const double dr = parts[i].mean[size_t(r)] - m.mean[size_t(r)];
                const double dc = parts[i].mean[size_t(c)] - m.mean[size_t(c)];
                m.covariance[size_t(r * n + c)]
                    += weights[i] * (parts[i].covariance[size_t(r * n + c)] + dr * dc);
            }
    return m;
}

ColorTransform color_transform_from_moments(const ColorMoments& moments)
{
    ColorTransform t;
    const int n = moments.n;
    if (n < 1)
        return t;
    t.n = n;
    t.mean = moments.mean;
    const Eigen::MatrixXd cov = Eigen::Map<const Eigen::MatrixXd>(moments.covariance.data(), n, n);

    // C = U S^2 U^T. Eigen returns eigenvalues ascending; take them descending.
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);
    Eigen::MatrixXd u = eig.eigenvectors().rowwise().reverse();
    Eigen::VectorXd s = eig.eigenvalues().reverse().cwiseMax(0.0).cwiseSqrt();
    const double smax = s.size() ? s[0] : 0.0;

    t.forward.assign(size_t(n * n), 0.0);
    t.inverse.assign(size_t(n * n), 0.0);
    t.constant.assign(size_t(n), false);
    for (int k = 0; k < n; ++k) {
        fix_sign(u.col(k));
        const bool constant = !(s[k] > kRelativeEpsilon * smax) || smax == 0.0;
        const double scale = constant ? 1.0 : s[k];
        t.constant[size_t(k)] = constant;
        for (int c = 0; c < n; ++c) {
            t.forward[size_t(k * n + c)] = u(c, k) / scale; // M = S^-1 U^T
            t.inverse[size_t(c * n + k)] = u(c, k) * scale; // M^-1 = U S
        }
    }
    return t;
}

ColorTransform fit_color_transform(const PlanarImage& image, int ncolor)
{
    return color_transform_from_moments(color_moments(image, ncolor));
}

void decorrelate(PlanarImage& image, const ColorTransform& t, int nthreads)
{
    const std::vector<double> zero(size_t(t.n), 0.0);
    apply_affine(image, t.n, t.forward, t.mean, zero, nthreads);
}

void recorrelate(PlanarImage& image, const ColorTransform& t, int nthreads)
{
    const std::vector<double> zero(size_t(t.n), 0.0);
    apply_affine(image, t.n, t.inverse, zero, t.mean, nthreads);
}

} // namespace texsyn
