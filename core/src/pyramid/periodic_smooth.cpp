// SPDX-License-Identifier: Apache-2.0
// Moisan 2011, "Periodic plus smooth image decomposition": p = u - s, where s solves a
// periodic Poisson equation driven by the jumps between opposite edges.
#include <texsyn/pyramid.h>

#include <cmath>
#include <vector>

namespace texsyn {

namespace {
constexpr double kPi = 3.14159265358979323846;
} // namespace

Plane periodic_component(const Plane& image, FftBackend fft, int nthreads)
{
    const int M = image.width(), N = image.height();
    std::string error;
    // The decomposition is the same maths on any backend: fall back to the built-in one.
    auto plan = RealFft2D::create(M, N, fft_backend_available(fft) ? fft : FftBackend::Kiss, error);
    if (!plan)
        return Plane();

    // Boundary image v: zero inside, the jumps between opposite edges on the border
    // (summed in double: corner pixels collect two of them).
    std::vector<double> v(size_t(M) * size_t(N), 0.0);
    for (int y = 0; y < N; ++y) {
        const double d = double(image(M - 1, y)) - double(image(0, y));
        v[size_t(y) * M] += d;
        v[size_t(y) * M + M - 1] -= d;
    }
    for (int x = 0; x < M; ++x) {
        const double d = double(image(x, N - 1)) - double(image(x, 0));
        v[size_t(x)] += d;
        v[size_t(N - 1) * M + x] -= d;
    }
    std::vector<float> vf(v.begin(), v.end());
    std::vector<std::complex<float>> spec(plan->spectrum_size());
    plan->forward(vf.data(), spec.data(), nthreads);

    const int wc = M / 2 + 1;
    std::vector<double> cos_x(static_cast<size_t>(wc)), cos_y(static_cast<size_t>(N));
    for (int q = 0; q < wc; ++q)
        cos_x[size_t(q)] = 2.0 * std::cos(2.0 * kPi * q / M);
    for (int r = 0; r < N; ++r)
        cos_y[size_t(r)] = 2.0 * std::cos(2.0 * kPi * r / N);
    for (int r = 0; r < N; ++r) {
        for (int q = 0; q < wc; ++q) {
            std::complex<float>& c = spec[size_t(r) * wc + q];
            const double denom = cos_x[size_t(q)] + cos_y[size_t(r)] - 4.0;
            // s-hat(0,0) = 0: s has zero mean, so p keeps the image's mean.
            c = (q == 0 && r == 0) ? 0.0f : std::complex<float>(std::complex<double>(c) / denom);
        }
    }
    Plane p(M, N);
    plan->inverse(spec.data(), p.data(), nthreads);
    for (size_t i = 0; i < p.size(); ++i)
        p.data()[i] = image.data()[i] - p.data()[i];
    return p;
}

} // namespace texsyn
