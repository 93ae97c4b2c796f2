// SPDX-License-Identifier: Apache-2.0
// The energy per octave of a plane's power spectrum, and the largest wavelength that holds
// a good share of it.
#include "feature_scale_pvt.h"

#include <algorithm>
#include <cmath>
#include <complex>

#include <texsyn/fft.h>

namespace texsyn::detail {

namespace {

// The spectrum is binned this finely in log2 frequency…
constexpr int kBinsPerOctave = 16;
// …and octave-wide bands are centred this often: the answer is interpolated between them.
constexpr int kBandsPerOctave = 8;
// The size is the largest wavelength whose band holds at least this share of the
// strongest band's energy…
constexpr double kEnergyShare = 0.5;
// …the strongest among wavelengths of at least this many pixels: finer energy is grain
// (sensor noise, JPEG blocks, sharpening) that resampling the sample adds or removes.
constexpr double kFinestFeature = 4.0;
// The finest detail: the shortest wavelength whose band holds this share of the strongest.
constexpr double kDetailShare = 0.1;

// Where a log-spaced profile crosses `level` between bands i and i + 1 (log-linearly).
double crossing(const std::vector<double>& wavelength, const std::vector<double>& energy, size_t i,
    double level)
{
    const double a = energy[i], b = energy[i + 1];
    const double t = std::clamp((a - level) / (a - b), 0.0, 1.0);
    return wavelength[i] * std::pow(wavelength[i + 1] / wavelength[i], t);
}

} // namespace

SpectralSizes spectral_sizes(const Plane& plane, int nthreads)
{
    const int w = plane.width(), h = plane.height();
    // Bands up to the whole side, so that structure near the largest size the estimate
    // reports (half the side) is weighed whole.
    const double largest = std::min(w, h);
    if (largest < 2.0 * kFinestFeature)
        return { 1.0, 1.0 };
    std::string error;
    const auto fft = RealFft2D::create(w, h, FftBackend::Kiss, error);
    // Hann-windowed, so that the sample's edges add no energy of their own.
    std::vector<float> windowed(plane.size());
    double mean = 0.0;
    for (size_t i = 0; i < plane.size(); ++i)
        mean += plane.data()[i];
    mean /= double(plane.size());
    const double pi = 3.14159265358979323846;
    for (int y = 0; y < h; ++y) {
        const double wy = 0.5 - 0.5 * std::cos(2.0 * pi * (y + 0.5) / h);
        for (int x = 0; x < w; ++x) {
            const double wx = 0.5 - 0.5 * std::cos(2.0 * pi * (x + 0.5) / w);
            windowed[size_t(y) * size_t(w) + size_t(x)] = float((plane(x, y) - mean) * wx * wy);
        }
    }
    std::vector<std::complex<float>> spectrum(fft->spectrum_size());
    fft->forward(windowed.data(), spectrum.data(), nthreads);

    // Fine bins of log2(0.5 / f): bin 0 holds the Nyquist frequency.
    const int octaves = int(std::ceil(std::log2(largest))) + 2;
    std::vector<double> bins(size_t(octaves * kBinsPerOctave + 1), 0.0);
    const int half = w / 2 + 1;
    for (int ky = 0; ky < h; ++ky) {
        const double fy = double(ky <= h / 2 ? ky : ky - h) / h;
        for (int kx = 0; kx < half; ++kx) {
            const double fx = double(kx) / w;
            const double f = std::sqrt(fx * fx + fy * fy);
            if (f <= 0.0)
                continue;
            // Columns 1 .. w/2 - 1 stand for their negative frequencies too.
            const double weight = kx == 0 || (w % 2 == 0 && kx == w / 2) ? 1.0 : 2.0;
            const int b = int(std::lround(kBinsPerOctave * std::log2(0.5 / f)));
            if (b >= 0 && b < int(bins.size()))
                bins[size_t(b)]
                    += weight * std::norm(spectrum[size_t(ky) * size_t(half) + size_t(kx)]);
        }
    }
    // Octave-wide bands at wavelengths 2 · 2^(j / kBandsPerOctave), up to `largest`.
    std::vector<double> wavelength, energy;
    const int step = kBinsPerOctave / kBandsPerOctave;
    for (int centre = 0; 2.0 * std::exp2(double(centre) / kBinsPerOctave) <= largest;
         centre += step) {
        double sum = 0.0;
        for (int b = centre - kBinsPerOctave / 2; b <= centre + kBinsPerOctave / 2; ++b)
            if (b >= 0 && b < int(bins.size()))
                sum += bins[size_t(b)] * (std::abs(b - centre) == kBinsPerOctave / 2 ? 0.5 : 1.0);
        wavelength.push_back(2.0 * std::exp2(double(centre) / kBinsPerOctave));
        energy.push_back(sum);
    }
    double peak = 0.0, strongest = 0.0;
    for (size_t i = 0; i < energy.size(); ++i) {
        strongest = std::max(strongest, energy[i]);
        if (wavelength[i] >= kFinestFeature)
            peak = std::max(peak, energy[i]);
    }
    if (!(peak > 0.0))
        return { 1.0, 1.0 };
    SpectralSizes sizes;
    size_t last = 0;
    for (size_t i = 0; i < energy.size(); ++i)
        if (energy[i] >= kEnergyShare * peak)
            last = i;
    // Between the last band above the share and the next.
    sizes.largest = last + 1 == energy.size()
        ? wavelength[last]
        : crossing(wavelength, energy, last, kEnergyShare * peak);
    size_t first = 0;
    while (energy[first] < kDetailShare * strongest)
        ++first;
    sizes.finest = first == 0 ? wavelength[0]
                              : crossing(wavelength, energy, first - 1, kDetailShare * strongest);
    return sizes;
}

} // namespace texsyn::detail
