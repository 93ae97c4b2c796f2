// SPDX-License-Identifier: Apache-2.0
#include "method_helpers_pvt.h"

#include <algorithm>
#include <cstdio>

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

std::string format_bytes(double bytes)
{
    const char* units[] = { "B", "KB", "MB", "GB", "TB", "PB", "EB" };
    int u = 0;
    while (bytes >= 1024.0 && u < 6) {
        bytes /= 1024.0;
        ++u;
    }
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.1f %s", bytes, units[u]);
    return buf;
}

bool check_memory(size_t need, const std::string& what, std::string& error)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
    const size_t have = pages > 0 && page > 0 ? size_t(pages) * size_t(page) : size_t(0);
    if (have && need > have) {
        error = what + " would need about " + format_bytes(double(need))
            + " of memory (this machine has " + format_bytes(double(have)) + ")";
        return false;
    }
    return true;
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
