// SPDX-License-Identifier: Apache-2.0
// The vote of texture optimization (Kwatra et al. 2005 §3): each output pixel is the
// (robustly) weighted average of the pixels the overlapping source patches put on it,
// gathered per pixel, so that rows run in parallel with no shared writes.
#include "patch_pvt.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

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

// One row of the field's votes onto one row of accumulators: add(x0, x1, offset, shift)
// adds to pixels x in [x0, x1) the vote of the patch centred at field pixel x + offset,
// its source moved by `shift` (that patch's pixel over x), weighted by the centre's weight.
struct VoteRow {
    const uint32_t* source;
    const float* weight;
    const float* pixels;
    float* acc;
    float* total;
    int channels;

    template <int C>
    void add_channels(int x0, int x1, int offset, int shift, int c) const
    {
        const int n = C > 0 ? C : c;
        for (int x = x0; x < x1; ++x) {
            const int q = x + offset;
            const float* p = pixels + size_t(int(source[q]) + shift) * size_t(n);
            const float wq = weight[q];
            float* a = acc + size_t(x) * size_t(n);
            for (int k = 0; k < n; ++k)
                a[k] += wq * p[k];
            total[x] += wq;
        }
    }

    void add(int x0, int x1, int offset, int shift) const
    {
        if (channels == 3)
            add_channels<3>(x0, x1, offset, shift, 3);
        else
            add_channels<0>(x0, x1, offset, shift, channels);
    }
};

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
            detail::split_every_item(nthreads));
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
            // along a row of the field. Each pixel adds its votes in the order of the
            // offsets, whatever the order of the pixels.
            std::vector<float> acc(size_t(w) * size_t(c), 0.0f), total(size_t(w), 0.0f);
            for (int dy = -half; dy <= half; ++dy) {
                if (!wrapping.y && (int(y) - dy < 0 || int(y) - dy >= h))
                    continue;
                const size_t row = size_t(wrap(int(y) - dy, h)) * size_t(w);
                const VoteRow votes { field.source.data() + row, weight.data() + row, pixels,
                    acc.data(), total.data(), c };
                for (int dx = -half; dx <= half; ++dx) {
                    // Output pixel x takes the patch centred at x - dx: without wrap, only
                    // the pixels whose centre is inside; with it, the centres that run off
                    // one edge come from the other.
                    const int shift = dy * sw + dx;
                    const int x0 = std::max(0, dx), x1 = std::min(w, w + dx);
                    if (!wrapping.x)
                        votes.add(x0, x1, -dx, shift);
                    else if (std::abs(dx) < w) {
                        votes.add(0, x0, w - dx, shift);
                        votes.add(x0, x1, -dx, shift);
                        votes.add(x1, w, -w - dx, shift);
                    } else // a patch wider than the field
                        for (int x = 0; x < w; ++x)
                            votes.add(x, x + 1, wrap(x - dx, w) - x, shift);
                }
            }
            for (int k = 0; k < c; ++k) {
                float* out_row = out[size_t(k)].row(int(y));
                for (int x = 0; x < w; ++x)
                    out_row[x] = acc[size_t(x) * size_t(c) + size_t(k)] / total[size_t(x)];
            }
        },
        detail::split_every_item(nthreads));
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
        detail::split_every_item(nthreads));
    return chosen;
}

} // namespace texsyn::detail
