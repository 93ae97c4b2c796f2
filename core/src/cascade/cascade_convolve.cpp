// SPDX-License-Identifier: Apache-2.0
// The cascade's circular convolutions (cascade_pvt.h).
#include "cascade_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {

namespace {

int wrap_index(int i, int n)
{
    const int r = i % n;
    return r < 0 ? r + n : r;
}

// Bilinear value of `in` at (x, y), circular; an integral position reads the pixel itself
// (so that dilation 1 repeats the undilated sums exactly).
float sample_circular(const Plane& in, float x, float y)
{
    const float fx0 = std::floor(x), fy0 = std::floor(y);
    const int w = in.width(), h = in.height();
    const int x0 = wrap_index(int(fx0), w), y0 = wrap_index(int(fy0), h);
    const float fx = x - fx0, fy = y - fy0;
    if (fx == 0.0f && fy == 0.0f)
        return in(x0, y0);
    const int x1 = x0 + 1 == w ? 0 : x0 + 1, y1 = y0 + 1 == h ? 0 : y0 + 1;
    const float top = in(x0, y0) + fx * (in(x1, y0) - in(x0, y0));
    const float bottom = in(x0, y1) + fx * (in(x1, y1) - in(x0, y1));
    return top + fy * (bottom - top);
}

} // namespace

void convolve_circular(const Plane& in, const CascadeKernelWeights& k, Plane& out, int nthreads)
{
    const int w = in.width(), h = in.height(), half = k.size / 2;
    if (out.width() != w || out.height() != h)
        out = Plane(w, h);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(h),
        [&](int64_t begin, int64_t end) {
            std::vector<float> padded(size_t(w + 2 * half));
            for (int64_t y = begin; y < end; ++y) {
                float* acc = out.row(int(y));
                std::fill(acc, acc + w, 0.0f);
                for (int j = 0; j < k.size; ++j) {
                    const float* src = in.row(wrap_index(int(y) + j - half, h));
                    std::copy_n(src, w, padded.data() + half);
                    for (int x = 0; x < half; ++x) {
                        padded[size_t(x)] = src[wrap_index(x - half, w)];
                        padded[size_t(w + half + x)] = src[wrap_index(w + x, w)];
                    }
                    for (int i = 0; i < k.size; ++i) {
                        const float wt = k.at(i, j);
                        const float* p = padded.data() + i;
                        for (int x = 0; x < w; ++x)
                            acc[x] += wt * p[x];
                    }
                }
            }
        },
        detail::split_every_item(nthreads));
}

void convolve_warped(const Plane& in, const CascadeKernelWeights& k, const Plane& dilation,
    const Plane& angle, Plane& out, int nthreads)
{
    const int w = in.width(), h = in.height(), half = k.size / 2;
    if (out.width() != w || out.height() != h)
        out = Plane(w, h);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(h),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y) {
                float* acc = out.row(int(y));
                for (int x = 0; x < w; ++x) {
                    const float d = dilation.empty() ? 1.0f : dilation(x, int(y));
                    const float a = angle.empty() ? 0.0f : angle(x, int(y));
                    const float c = d * std::cos(a), s = d * std::sin(a);
                    float sum = 0.0f;
                    for (int j = 0; j < k.size; ++j)
                        for (int i = 0; i < k.size; ++i) {
                            const float u = float(i - half), v = float(j - half);
                            sum += k.at(i, j)
                                * sample_circular(
                                    in, float(x) + c * u - s * v, float(y) + s * u + c * v);
                        }
                    acc[x] = sum;
                }
            }
        },
        detail::split_every_item(nthreads));
}

} // namespace texsyn::detail
