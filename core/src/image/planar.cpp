// SPDX-License-Identifier: Apache-2.0
#include <texsyn/image.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <new>
#include <vector>

#include "parallel_pvt.h"
#include "planar_pvt.h"

namespace texsyn {

Plane::Plane(int width, int height, float value)
    : m_width(width)
    , m_height(height)
    , m_data(size_t(width) * size_t(height), value)
{ }

int wrap_coordinate(int i, int n, Boundary b)
{
    if (i >= 0 && i < n)
        return i;
    if (n == 1)
        return 0;
    if (b == Boundary::Circular) {
        int r = i % n;
        return r < 0 ? r + n : r;
    }
    // Whole-sample mirror about the edge pixels: period 2n-2, no repeated edge value.
    int period = 2 * n - 2;
    int r = i % period;
    if (r < 0)
        r += period;
    return r < n ? r : period - r;
}

float Plane::at(int x, int y, Boundary b) const
{
    return (*this)(wrap_coordinate(x, m_width, b), wrap_coordinate(y, m_height, b));
}

namespace {

// "pixel (X, Y) channel C is NaN; texsyn needs finite pixel values"
std::string non_finite_pixel(int x, int y, const std::string& channel, float value)
{
    return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " + channel
        + " is " + (std::isnan(value) ? "NaN" : "infinite") + "; texsyn needs finite pixel values";
}

} // namespace

bool check_finite_pixels(const OIIO::ImageBuf& src, std::string& error)
{
    const OIIO::ImageSpec& spec = src.spec();
    for (OIIO::ImageBuf::ConstIterator<float> p(src); !p.done(); ++p)
        for (int c = 0; c < spec.nchannels; ++c)
            if (!std::isfinite(p[c])) {
                error = non_finite_pixel(p.x(), p.y(),
                    c < int(spec.channelnames.size()) ? spec.channelnames[c]
                                                      : "c" + std::to_string(c),
                    p[c]);
                return false;
            }
    return true;
}

bool planes_from_imagebuf(
    const OIIO::ImageBuf& src, PlanarImage& dst, std::string& error, int nthreads)
{
    if (src.has_error()) {
        error = src.geterror();
        return false;
    }
    const OIIO::ImageSpec& spec = src.spec();
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) {
        error = "image is empty";
        return false;
    }
    if (spec.depth > 1) {
        error = "volume images (depth " + std::to_string(spec.depth) + ") are not supported";
        return false;
    }
    const int w = spec.width, h = spec.height, nc = spec.nchannels;
    // Float pixels in memory are read where they are; anything else (another pixel type, a
    // file read lazily through the cache) is converted into a copy first.
    std::vector<float> copy;
    const float* pixels = contiguous_float_pixels(src);
    if (!pixels) {
        copy.resize(size_t(w) * size_t(h) * size_t(nc));
        if (!src.get_pixels(src.roi(), OIIO::TypeFloat, copy.data())) {
            error = src.geterror();
            return false;
        }
        pixels = copy.data();
    }
    PlanarImage out;
    out.alpha_channel
        = spec.alpha_channel >= 1 && spec.alpha_channel < nc ? spec.alpha_channel : -1;
    const bool associated
        = out.alpha_channel >= 0 && !spec.get_int_attribute("oiio:UnassociatedAlpha", 0);
    for (int c = 0; c < nc; ++c) {
        out.channels.emplace_back(w, h);
        out.channel_names.push_back(
            c < int(spec.channelnames.size()) ? spec.channelnames[c] : "c" + std::to_string(c));
    }
    // Rows are copied independently; each notes its first non-finite value, and the
    // message names the first of those in scanline order.
    std::vector<int> first_bad(size_t(h), -1);
    OIIO::parallel_for(
        0, h,
        [&](int64_t row) {
            const int y = int(row);
            const float* p = pixels + size_t(y) * size_t(w) * size_t(nc);
            std::vector<float*> rows(static_cast<size_t>(nc));
            for (int c = 0; c < nc; ++c)
                rows[size_t(c)] = out.channels[size_t(c)].row(y);
            for (int x = 0; x < w; ++x, p += nc) {
                for (int c = 0; c < nc; ++c) {
                    if (!std::isfinite(p[c])) {
                        first_bad[size_t(y)] = x * nc + c;
                        return;
                    }
                    rows[size_t(c)][x] = p[c];
                }
                if (associated) {
                    float a = p[out.alpha_channel];
                    if (a > 0.0f && a != 1.0f)
                        for (int c = 0; c < out.alpha_channel; ++c)
                            rows[size_t(c)][x] /= a;
                }
            }
        },
        detail::split_every_item(nthreads));
    for (int y = 0; y < h; ++y)
        if (first_bad[size_t(y)] >= 0) {
            const int x = first_bad[size_t(y)] / nc, c = first_bad[size_t(y)] % nc;
            const float bad = pixels[(size_t(y) * size_t(w) + size_t(x)) * size_t(nc) + size_t(c)];
            error = non_finite_pixel(x + spec.x, y + spec.y, out.channel_names[size_t(c)], bad);
            return false;
        }
    dst = std::move(out);
    return true;
}

void imagebuf_from_planes(const PlanarImage& src, OIIO::ImageBuf& dst, bool associate, int nthreads)
{
    const int w = src.width(), h = src.height(), nc = src.nchannels();
    OIIO::ImageSpec spec(w, h, nc, OIIO::TypeFloat);
    spec.channelnames = src.channel_names;
    spec.alpha_channel = src.alpha_channel;
    const bool multiply = associate && src.alpha_channel >= 0;
    if (!associate && src.alpha_channel >= 0)
        spec.attribute("oiio:UnassociatedAlpha", 1);
    // Every pixel is written below: no zero fill first.
    dst.reset(spec, OIIO::InitializePixels::No);
    auto* pixels = static_cast<float*>(dst.localpixels());
    if (!pixels) {
        if (w > 0 && h > 0 && nc > 0) // OIIO logs a failed allocation and leaves no pixels
            throw std::bad_alloc();
        return;
    }
    OIIO::parallel_for(
        0, h,
        [&](int64_t row) {
            const int y = int(row);
            const float* alpha
                = src.alpha_channel >= 0 ? src.channels[size_t(src.alpha_channel)].row(y) : nullptr;
            std::vector<const float*> rows(static_cast<size_t>(nc));
            for (int c = 0; c < nc; ++c)
                rows[size_t(c)] = src.channels[size_t(c)].row(y);
            float* p = pixels + size_t(y) * size_t(w) * size_t(nc);
            for (int x = 0; x < w; ++x, p += nc) {
                const float a = alpha ? alpha[x] : 1.0f;
                for (int c = 0; c < nc; ++c) {
                    const float v = rows[size_t(c)][x];
                    p[c] = (multiply && c < src.alpha_channel) ? v * a : v;
                }
            }
        },
        detail::split_every_item(nthreads));
}

const float* contiguous_float_pixels(const OIIO::ImageBuf& buf)
{
    const OIIO::ImageSpec& spec = buf.spec();
    const auto pixel = OIIO::stride_t(spec.nchannels) * OIIO::stride_t(sizeof(float));
    if (!buf.localpixels() || spec.format != OIIO::TypeFloat || !spec.channelformats.empty()
        || buf.pixel_stride() != pixel || buf.scanline_stride() != pixel * spec.width)
        return nullptr;
    return static_cast<const float*>(buf.localpixels());
}

bool copy_without_planes(const OIIO::ImageBuf& src, OIIO::ImageBuf& dst)
{
    const OIIO::ImageSpec& spec = src.spec();
    const int nc = spec.nchannels;
    const float* pixels = contiguous_float_pixels(src);
    if (!pixels || src.has_error() || spec.width < 1 || spec.height < 1 || nc < 1 || spec.depth > 1
        || int(spec.channelnames.size()) != nc
        || (spec.alpha_channel >= 1 && spec.alpha_channel < nc))
        return false;
    const size_t n = size_t(spec.width) * size_t(spec.height) * size_t(nc);
    // All exponent bits set is Inf or NaN; or-ing a flag per value keeps the loop vectorised.
    uint32_t not_finite = 0;
    for (size_t i = 0; i < n; ++i) {
        uint32_t bits;
        std::memcpy(&bits, pixels + i, sizeof bits);
        not_finite |= uint32_t((bits & 0x7f800000u) == 0x7f800000u);
    }
    if (not_finite)
        return false;
    OIIO::ImageSpec out(spec.width, spec.height, nc, OIIO::TypeFloat);
    out.channelnames = spec.channelnames;
    out.alpha_channel = -1;
    OIIO::ImageBuf result(out, OIIO::InitializePixels::No);
    if (!result.localpixels())
        throw std::bad_alloc();
    std::memcpy(result.localpixels(), pixels, n * sizeof(float));
    dst = std::move(result);
    return true;
}

} // namespace texsyn
