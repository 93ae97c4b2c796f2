// SPDX-License-Identifier: Apache-2.0
#include "synthesis_pvt.h"

#include <algorithm>
#include <cstdio>

#include <unistd.h>

#include <texsyn/random.h>

namespace texsyn::detail {

void tag_synthesis(
    OIIO::ImageSpec& spec, const char* method, uint64_t seed, const std::string& options)
{
    spec.attribute("synth:version", version());
    spec.attribute("synth:method", method);
    spec.attribute("synth:seed", int(seed));
    spec.attribute("synth:options", options);
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

std::unique_ptr<Pyramid> make_pyramid(const PyramidOptions& opt, int width, int height, int scales,
    Boundary boundary, std::string& error)
{
    if (opt.pyramid == PyramidKind::Laplacian)
        return make_laplacian_pyramid(width, height, scales, boundary);
    return make_steerable_pyramid(width, height, scales, opt.orientations, opt.fft, error);
}

Plane seeded_noise(int width, int height, uint64_t seed, uint64_t stream)
{
    Plane p(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            p(x, y) = random_uniform(seed, stream, uint64_t(y) * uint64_t(width) + uint64_t(x));
    return p;
}

bool is_constant(const Plane& p)
{
    auto [lo, hi] = std::minmax_element(p.data(), p.data() + p.size());
    return *lo == *hi;
}

float plane_mean(const Plane& p)
{
    double sum = 0.0;
    for (size_t i = 0; i < p.size(); ++i)
        sum += p.data()[i];
    return float(sum / double(p.size()));
}

void append_subbands(const std::string& prefix, const std::vector<std::string>& band_names,
    const std::vector<std::vector<Plane>>& per_component,
    const std::vector<std::string>& component_names, std::vector<NamedImage>& out)
{
    for (size_t b = 0; b < band_names.size(); ++b) {
        NamedImage ni;
        ni.name = prefix + "." + band_names[b];
        for (size_t c = 0; c < per_component.size(); ++c) {
            ni.image.channels.push_back(per_component[c][b]);
            ni.image.channel_names.push_back(component_names[c]);
        }
        ni.image.alpha_channel = -1; // "A" is a band here: never multiplied into colour
        out.push_back(std::move(ni));
    }
}

} // namespace texsyn::detail
