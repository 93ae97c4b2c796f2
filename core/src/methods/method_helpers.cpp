// SPDX-License-Identifier: Apache-2.0
#include "method_helpers_pvt.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include <unistd.h>

#include <texsyn/random.h>
#include <texsyn/version.h>

namespace texsyn::detail {

void tag_synthesis(
    OIIO::ImageSpec& spec, const char* method, uint64_t seed, const std::string& options)
{
    spec.attribute("synth:version", version());
    spec.attribute("synth:method", method);
    spec.attribute("synth:seed", int(seed));
    spec.attribute("synth:options", options);
}

bool check_fft_backend(FftBackend fft, std::string& error)
{
    if (fft_backend_available(fft))
        return true;
    error = option_error("fft", fft_backend_name(fft),
        "not available: texsyn was built without it (-DTEXSYN_WITH_FFTW=ON)");
    return false;
}

std::string count_text(int n, const std::string& noun)
{
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

void throw_if_stopped(const StopFlag* stop)
{
    if (stop_requested(stop))
        throw std::runtime_error("stopped");
}

void report_progress(
    const std::function<void(float)>& progress, const StopFlag* stop, float fraction)
{
    throw_if_stopped(stop);
    if (progress)
        progress(fraction);
}

Plane seeded_noise(int width, int height, uint64_t seed, uint64_t stream)
{
    Plane p(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            p(x, y) = random_uniform(seed, stream, uint64_t(y) * uint64_t(width) + uint64_t(x));
    return p;
}

} // namespace texsyn::detail
