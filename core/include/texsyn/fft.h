// SPDX-License-Identifier: Apache-2.0
// Two-dimensional real FFTs behind one small interface, so the FFT library is a build
// choice and not something the algorithms know about.
//
// Backends: KissFFT (BSD-3, the default) and FFTW (GPL-2+, only when texsyn is configured
// with -DTEXSYN_WITH_FFTW=ON). FFTW plans use FFTW_ESTIMATE (no timing-based planning),
// so every backend is deterministic.
//
// Conventions for every function here:
//  - Spectra are "half spectra": height rows of (width/2 + 1) complex values; row ky holds
//    the vertical frequency ky (ky > height/2 are the negative frequencies ky - height),
//    column kx the horizontal frequency kx in [0, width/2].
//  - forward() is unnormalised (X[k] = sum x[n] e^{-2 pi i k n / N}); inverse() divides by
//    width*height, so inverse(forward(x)) == x to float rounding.
//  - Any width, height >= 1 (not only powers of two).
//  - Thread safety: a plan is immutable after creation; forward() and inverse() may be
//    called concurrently on one plan with different buffers. `nthreads` (0 = OIIO's
//    default) parallelises over rows and columns; the result does not depend on it.
#pragma once

#include <complex>
#include <memory>
#include <string>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

enum class FftBackend { Kiss, Fftw };

/// Whether this build of texsyn contains `backend`.
bool fft_backend_available(FftBackend backend);

/// "kiss" or "fftw".
const char* fft_backend_name(FftBackend backend);

/// A plan for real width x height transforms.
class RealFft2D {
public:
    virtual ~RealFft2D() = default;
    int width() const { return m_width; }
    int height() const { return m_height; }
    /// Complex values in a half spectrum: height * (width/2 + 1).
    size_t spectrum_size() const { return size_t(m_height) * size_t(m_width / 2 + 1); }

    /// `in`: width*height floats, row-major. `out`: spectrum_size() values.
    virtual void forward(const float* in, std::complex<float>* out, int nthreads = 0) const = 0;
    /// `in`: a Hermitian half spectrum (not modified); `out`: width*height floats.
    virtual void inverse(const std::complex<float>* in, float* out, int nthreads = 0) const = 0;

    /// Makes a plan, or returns nullptr and sets `error` if the backend is not built in
    /// or the size is < 1.
    static std::unique_ptr<RealFft2D> create(
        int width, int height, FftBackend backend, std::string& error);

protected:
    RealFft2D(int width, int height)
        : m_width(width)
        , m_height(height)
    { }
    int m_width;
    int m_height;
};

} // namespace texsyn
#pragma GCC visibility pop
