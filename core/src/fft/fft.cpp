// SPDX-License-Identifier: Apache-2.0
#include <texsyn/fft.h>

#include <new>
#include <stdexcept>

#include "fft/fft_pvt.h"

namespace texsyn {

bool fft_backend_available(FftBackend backend)
{
    switch (backend) {
    case FftBackend::Kiss:
        return true;
#if TEXSYN_HAVE_FFTW
    case FftBackend::Fftw:
        return true;
#else
    case FftBackend::Fftw:
        return false;
#endif
    }
    return false;
}

const char* fft_backend_name(FftBackend backend)
{
    return backend == FftBackend::Fftw ? "fftw" : "kiss";
}

std::unique_ptr<RealFft2D> RealFft2D::create(
    int width, int height, FftBackend backend, std::string& error)
{
    if (width < 1 || height < 1) {
        error = "FFT size " + std::to_string(width) + "x" + std::to_string(height)
            + " is invalid (width and height must be >= 1)";
        return nullptr;
    }
    if (!fft_backend_available(backend)) {
        error = std::string("FFT backend '") + fft_backend_name(backend)
            + "' is not built into this texsyn (configure with -DTEXSYN_WITH_FFTW=ON)";
        return nullptr;
    }
    try {
#if TEXSYN_HAVE_FFTW
        if (backend == FftBackend::Fftw)
            return make_fftw_fft(width, height);
#endif
        return make_kiss_fft(width, height);
    } catch (const std::bad_alloc&) {
        error = "out of memory planning a " + std::to_string(width) + "x" + std::to_string(height)
            + " FFT";
        return nullptr;
    } catch (const std::runtime_error& e) { // the FFT library could not be loaded
        error = e.what();
        return nullptr;
    }
}

} // namespace texsyn
