// SPDX-License-Identifier: Apache-2.0
// The vote of texture optimization (Kwatra et al. 2005 §3): each output pixel is the
// (robustly) weighted average of the pixels the overlapping source patches put on it,
// gathered per pixel, so that rows run in parallel with no shared writes.
#include "patch_pvt.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <OpenImageIO/parallel.h>

namespace texsyn::detail {

namespace {

// Calls f(sample pixel index, weight index q) for the patch x patch patches over output
// pixel (x, y): the patch centred at q = (x - dx, y - dy) puts its pixel (dx, dy) there.
// Along an axis that does not wrap, only patches centred inside the field.
template <class F>
void for_each_vote(
    const PatchField& field, int sample_width, int patch, int x, int y, Wrap wrapping, F&& f)
{
    const int half = patch / 2;
    auto inside = [](int i, int n, bool wraps) { return wraps || (i >= 0 && i < n); };
    for (int dy = -half; dy <= half; ++dy) {
        if (!inside(y - dy, field.height, wrapping.y))
            continue;
        const size_t row = size_t(wrap(y - dy, field.height)) * size_t(field.width);
        for (int dx = -half; dx <= half; ++dx) {
            if (!inside(x - dx, field.width, wrapping.x))
                continue;
            const size_t q = row + size_t(wrap(x - dx, field.width));
            const uint32_t s = field.source[q];
            f(uint32_t(int(s) + dy * sample_width + dx), q);
        }
    }
}

} // namespace

void vote(const SampleLevel& sample, const PatchField& field, int patch, PatchVote kind,
    int nthreads, const StopFlag* stop, std::vector<Plane>& out, Wrap wrapping)
{
    const int c = sample.pixels.channels, w = field.width, h = field.height;
    const size_t n = size_t(w) * size_t(h);
    // Kwatra et al.'s IRLS weights for r = 0.8: |x_p - z_p|^(r - 2) with the squared
    // distance per value, regularised by a hundredth of the sample's variance per value.
    std::vector<float> weight(n, 1.0f);
    if (kind == PatchVote::Robust) {
        const float values = float(patch) * float(patch) * float(c);
        // (a constant sample has none: a tiny floor keeps the weights finite)
        const float floor = float(std::max(0.01 * sample.variance / double(c), 1e-12));
        OIIO::parallel_for(
            0, h,
            [&](int64_t y) {
                for (size_t q = size_t(y) * size_t(w); q < size_t(y + 1) * size_t(w); ++q)
                    weight[q] = std::pow(field.distance[q] / values + floor, -0.6f);
            },
            OIIO::paropt(nthreads));
    }
    out.assign(size_t(c), Plane(w, h));
    const int half = patch / 2, sw = sample.pixels.width;
    const float* pixels = sample.pixels.data.data();
    OIIO::parallel_for(
        0, h,
        [&](int64_t y) {
            if (stop_requested(stop))
                return;
            // Row accumulators, interleaved; offsets outermost so that the inner loop runs
            // along a row of the field.
            std::vector<float> acc(size_t(w) * size_t(c), 0.0f), total(size_t(w), 0.0f);
            for (int dy = -half; dy <= half; ++dy) {
                if (!wrapping.y && (int(y) - dy < 0 || int(y) - dy >= h))
                    continue;
                const uint32_t* src
                    = field.source.data() + size_t(wrap(int(y) - dy, h)) * size_t(w);
                const float* wt = weight.data() + size_t(wrap(int(y) - dy, h)) * size_t(w);
                for (int dx = -half; dx <= half; ++dx) {
                    const int shift = dy * sw + dx;
                    // Without wrap, the pixels whose patch centre x - dx is inside.
                    const int x0 = wrapping.x ? 0 : std::max(0, dx);
                    const int x1 = wrapping.x ? w : std::min(w, w + dx);
                    for (int x = x0; x < x1; ++x) {
                        const int q = wrap(x - dx, w);
                        const float* p = pixels + size_t(int(src[q]) + shift) * size_t(c);
                        const float wq = wt[q];
                        float* a = acc.data() + size_t(x) * size_t(c);
                        for (int k = 0; k < c; ++k)
                            a[k] += wq * p[k];
                        total[size_t(x)] += wq;
                    }
                }
            }
            for (int k = 0; k < c; ++k) {
                float* row = out[size_t(k)].row(int(y));
                for (int x = 0; x < w; ++x)
                    row[x] = acc[size_t(x) * size_t(c) + size_t(k)] / total[size_t(x)];
            }
        },
        OIIO::paropt(nthreads));
}

std::vector<uint32_t> nearest_votes(const SampleLevel& sample, const PatchField& field, int patch,
    const std::vector<Plane>& average, int nthreads, const StopFlag* stop, Wrap wrapping)
{
    const int c = sample.pixels.channels, w = field.width, h = field.height;
    std::vector<uint32_t> chosen(size_t(w) * size_t(h));
    OIIO::parallel_for(
        0, h,
        [&](int64_t y) {
            if (stop_requested(stop))
                return;
            std::vector<float> mean(static_cast<size_t>(c));
            for (int x = 0; x < w; ++x) {
                for (int k = 0; k < c; ++k)
                    mean[size_t(k)] = average[size_t(k)](x, int(y));
                float best = std::numeric_limits<float>::infinity();
                uint32_t pick = 0;
                for_each_vote(field, sample.pixels.width, patch, x, int(y), wrapping,
                    [&](uint32_t s, size_t) {
                        const float* p = sample.pixels.data.data() + size_t(s) * size_t(c);
                        float d = 0.0f;
                        for (int k = 0; k < c; ++k)
                            d += (p[k] - mean[size_t(k)]) * (p[k] - mean[size_t(k)]);
                        if (d < best) {
                            best = d;
                            pick = s;
                        }
                    });
                chosen[size_t(y) * size_t(w) + size_t(x)] = pick;
            }
        },
        OIIO::paropt(nthreads));
    return chosen;
}

} // namespace texsyn::detail
