// SPDX-License-Identifier: Apache-2.0
// Backend factories behind RealFft2D::create (sizes already validated there).
#pragma once

#include <memory>

#include <texsyn/fft.h>

namespace texsyn {

std::unique_ptr<RealFft2D> make_kiss_fft(int width, int height);
#if TEXSYN_HAVE_FFTW
std::unique_ptr<RealFft2D> make_fftw_fft(int width, int height);
#endif

} // namespace texsyn
