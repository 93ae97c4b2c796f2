// SPDX-License-Identifier: Apache-2.0
#include "method_helpers_pvt.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <unistd.h>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/parallel.h>

#include <texsyn/random.h>
#include <texsyn/version.h>

#include "image/parallel_pvt.h"

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

void scale_sample(PlanarImage& in, float k, int nthreads)
{
    if (k == 1.0f || in.channels.empty())
        return;
    const int w = std::max(1, int(std::lround(in.width() * double(k))));
    const int h = std::max(1, int(std::lround(in.height() * double(k))));
    PlanarImage plain = in;
    plain.alpha_channel = -1; // resampled as they are: no association
    OIIO::ImageBuf buf;
    imagebuf_from_planes(plain, buf, false, nthreads);
    OIIO::ImageBuf resized;
    if (!OIIO::ImageBufAlgo::resize(resized, buf, "", 0.0f, OIIO::ROI(0, w, 0, h), nthreads))
        throw std::runtime_error("scale: " + resized.geterror());
    std::vector<float> pixels(size_t(w) * size_t(h) * size_t(in.nchannels()));
    resized.get_pixels(
        OIIO::ROI(0, w, 0, h, 0, 1, 0, in.nchannels()), OIIO::TypeFloat, pixels.data());
    for (int c = 0; c < in.nchannels(); ++c) {
        const Plane& old = in.channels[size_t(c)];
        const auto [lo, hi] = std::minmax_element(old.data(), old.data() + old.size());
        Plane p(w, h);
        for (size_t i = 0; i < p.size(); ++i)
            p.data()[i] = std::clamp(pixels[i * size_t(in.nchannels()) + size_t(c)], *lo, *hi);
        in.channels[size_t(c)] = std::move(p);
    }
}

Plane seeded_noise(int width, int height, uint64_t seed, uint64_t stream, int nthreads)
{
    Plane p(width, height);
    OIIO::parallel_for(
        0, height,
        [&](int64_t y) {
            for (int x = 0; x < width; ++x)
                p(x, int(y))
                    = random_uniform(seed, stream, uint64_t(y) * uint64_t(width) + uint64_t(x));
        },
        split_every_item(nthreads));
    return p;
}

} // namespace texsyn::detail
