// SPDX-License-Identifier: Apache-2.0
// The autocorrelation (by FFT, zero-padded so that it is linear) along the axes and over a
// window of shifts, and the period it shows.
#include "feature_scale_pvt.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <texsyn/fft.h>

namespace texsyn::detail {

namespace {

// A peak counts if it rises this much above the lowest value before it (a ripple of a
// stochastic texture's autocorrelation rises far less)…
constexpr double kMinProminence = 0.2;
// …and is at least this high.
constexpr double kMinPeak = 0.1;
// The period is the first peak at least this fraction of the highest: a running bond's
// half-period peak (one course, bricks offset) is lower than its full period's.
constexpr double kPeakShare = 0.8;

// The sums of products of `plane`'s deviations from its mean at every shift, by FFT,
// zero-padded so that they are linear: at(dx, dy) is the mean product at that shift.
class ShiftProducts {
public:
    ShiftProducts(const Plane& plane, int nthreads)
        : w_(plane.width())
        , h_(plane.height())
        , pw_(2 * w_)
        , ph_(2 * h_)
        , sums_(size_t(pw_) * size_t(ph_), 0.0f)
    {
        std::string error;
        const auto fft = RealFft2D::create(pw_, ph_, FftBackend::Kiss, error);
        double mean = 0.0;
        for (size_t i = 0; i < plane.size(); ++i)
            mean += plane.data()[i];
        mean /= double(plane.size());
        for (int y = 0; y < h_; ++y)
            for (int x = 0; x < w_; ++x)
                sums_[size_t(y) * size_t(pw_) + size_t(x)] = float(plane(x, y) - mean);
        std::vector<std::complex<float>> spectrum(fft->spectrum_size());
        fft->forward(sums_.data(), spectrum.data(), nthreads);
        for (auto& c : spectrum)
            c = std::norm(c);
        fft->inverse(spectrum.data(), sums_.data(), nthreads);
    }

    double at(int dx, int dy) const
    {
        const int x = (dx + pw_) % pw_, y = (dy + ph_) % ph_;
        const double count = double(w_ - std::abs(dx)) * double(h_ - std::abs(dy));
        return double(sums_[size_t(y) * size_t(pw_) + size_t(x)]) / count;
    }

private:
    int w_, h_, pw_, ph_;
    std::vector<float> sums_;
};

} // namespace

void axis_autocorrelation(
    const Plane& plane, int nthreads, std::vector<double>& along_x, std::vector<double>& along_y)
{
    const int w = plane.width(), h = plane.height();
    const ShiftProducts products(plane, nthreads);
    auto at = [&](int dx, int dy) { return products.at(dx, dy); };
    const double zero = at(0, 0);
    along_x.assign(size_t(w / 2 + 1), 0.0);
    along_y.assign(size_t(h / 2 + 1), 0.0);
    if (!(zero > 0.0))
        return;
    for (int d = 0; d <= w / 2; ++d)
        along_x[size_t(d)] = (at(d, -1) + at(d, 0) + at(d, 1)) / (3.0 * zero);
    for (int d = 0; d <= h / 2; ++d)
        along_y[size_t(d)] = (at(-1, d) + at(0, d) + at(1, d)) / (3.0 * zero);
    along_x[0] = along_y[0] = 1.0;
}

std::vector<double> autocorrelation_window(const Plane& plane, int radius, int nthreads)
{
    const int r = std::max(0, std::min({ radius, plane.width() - 1, plane.height() - 1 }));
    const int side = 2 * r + 1;
    std::vector<double> window(size_t(side) * size_t(side), 0.0);
    const ShiftProducts products(plane, nthreads);
    const double zero = products.at(0, 0);
    if (!(zero > 0.0))
        return window;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
            window[size_t(dy + r) * size_t(side) + size_t(dx + r)] = products.at(dx, dy) / zero;
    return window;
}

double autocorrelation_ring_max(const Plane& plane, double inner, double outer, int nthreads)
{
    const int rx = std::min(int(outer), plane.width() / 2);
    const int ry = std::min(int(outer), plane.height() / 2);
    const ShiftProducts products(plane, nthreads);
    const double zero = products.at(0, 0);
    double most = 0.0;
    if (!(zero > 0.0))
        return most;
    for (int dy = -ry; dy <= ry; ++dy)
        for (int dx = -rx; dx <= rx; ++dx) {
            const double r = std::sqrt(double(dx) * dx + double(dy) * dy);
            if (r >= inner && r <= outer)
                most = std::max(most, products.at(dx, dy) / zero);
        }
    return most;
}

double profile_period(const std::vector<double>& r, double& strength)
{
    struct Peak {
        double at, value;
    };
    std::vector<Peak> peaks;
    double low = r.empty() ? 0.0 : r[0];
    for (size_t d = 1; d + 1 < r.size(); ++d) {
        low = std::min(low, r[d]);
        if (!(r[d] > r[d - 1] && r[d] >= r[d + 1]) || r[d] - low < kMinProminence
            || r[d] < kMinPeak)
            continue;
        // The vertex of the parabola through the three values around the peak.
        const double curve = r[d - 1] - 2.0 * r[d] + r[d + 1];
        const double offset
            = curve < 0.0 ? std::clamp(0.5 * (r[d - 1] - r[d + 1]) / curve, -0.5, 0.5) : 0.0;
        peaks.push_back({ double(d) + offset, r[d] });
    }
    strength = 0.0;
    double highest = 0.0;
    for (const Peak& p : peaks)
        highest = std::max(highest, p.value);
    for (const Peak& p : peaks)
        if (p.value >= kPeakShare * highest) {
            strength = p.value;
            return p.at;
        }
    return 0.0;
}

} // namespace texsyn::detail
