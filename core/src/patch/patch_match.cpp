// SPDX-License-Identifier: Apache-2.0
// PatchMatch (Barnes et al. 2009) made schedule-independent: every pass reads the field of
// the previous pass and writes a new one, propagating at a jump-flood step (Rong & Tan
// 2006) instead of in scan order, with k-coherence candidates (Tong et al. 2002) and the
// random search around the best; and the spatial-uniformity penalty of Kaspar et al. 2015.
#include "patch_pvt.h"

#include <algorithm>
#include <limits>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include <texsyn/random.h>

#include "search/distance_pvt.h"

namespace texsyn::detail {

namespace {

// Rows one task searches: fixed, whatever the thread count.
constexpr int kRowBlock = 4;

inline float distance_at(const PixelImage& padded, int pad, int x, int y, const PixelImage& sample,
    uint32_t source, int patch, float bound)
{
    const int half = patch / 2, c = sample.channels;
    const int sx = int(source % uint32_t(sample.width)), sy = int(source / uint32_t(sample.width));
    const float* o = padded.pixel(x + pad - half, y + pad - half);
    const float* s = sample.pixel(sx - half, sy - half);
    const size_t ostride = size_t(padded.width) * size_t(c),
                 sstride = size_t(sample.width) * size_t(c);
    SquaredDifferenceLanes lanes;
    float sum = 0.0f;
    for (int r = 0; r < patch && sum < bound; ++r, o += ostride, s += sstride) {
        lanes.add(o, s, patch * c);
        sum = lanes.sum();
    }
    return sum;
}

// What one search pass reads and writes.
struct Pass {
    const SampleLevel* sample;
    const PixelImage* padded;
    int pad, patch, step, radius;
    CentreRange range;
    const PatchField* field; // read
    PatchField* next;        // written
    const std::vector<uint32_t>* similar;
    size_t k; // similar entries per centre
    const std::vector<uint32_t>* uses;
    float unit, free_uses;
    uint64_t seed, stream;
    const std::vector<uint8_t>* active; // null = every pixel
    Wrap wrap;
};

// One row of a pass: each pixel's best of its current source, its neighbours' (at the
// pass's step, shifted back, with their k-coherent sources) and a random search around
// the best.
void search_row(const Pass& pass, int y)
{
    const PatchField& field = *pass.field;
    const int w = field.width, h = field.height, sw = pass.sample->pixels.width;
    const CentreRange& range = pass.range;
    auto penalty = [&](uint32_t s) {
        return pass.uses->empty()
            ? 0.0f
            : pass.unit * std::max(0.0f, float((*pass.uses)[s]) - pass.free_uses);
    };
    const SampleLevel& sample = *pass.sample;
    for (int x = 0; x < w; ++x) {
        const size_t q = size_t(y) * size_t(w) + size_t(x);
        if (pass.active && !(*pass.active)[q])
            continue;
        uint32_t best = field.source[q];
        float best_distance = field.distance[q];
        float best_cost = best_distance + penalty(best);
        auto consider = [&](uint32_t s) {
            if (s == best || !sample.allows(s))
                return;
            const float p = penalty(s);
            if (p >= best_cost)
                return;
            const float d = distance_at(
                *pass.padded, pass.pad, x, y, pass.sample->pixels, s, pass.patch, best_cost - p);
            if (d + p < best_cost) {
                best = s;
                best_distance = d;
                best_cost = d + p;
            }
        };
        static const int dirs[4][2] = { { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } };
        for (const auto& dir : dirs) {
            const int dx = dir[0] * pass.step, dy = dir[1] * pass.step;
            if ((!pass.wrap.x && (x + dx < 0 || x + dx >= w))
                || (!pass.wrap.y && (y + dy < 0 || y + dy >= h)))
                continue; // no neighbour across an edge that does not wrap
            const uint32_t s
                = field.source[size_t(wrap(y + dy, h)) * size_t(w) + size_t(wrap(x + dx, w))];
            consider(range.clamp(int(s % uint32_t(sw)) - dx, int(s / uint32_t(sw)) - dy));
            for (size_t j = 0; j < pass.k; ++j) {
                const uint32_t t = (*pass.similar)[size_t(s) * pass.k + j];
                consider(range.clamp(int(t % uint32_t(sw)) - dx, int(t / uint32_t(sw)) - dy));
            }
        }
        uint64_t draw = 0;
        for (int r = pass.radius; r >= 1; r /= 2) {
            const uint64_t bits = random_bits(pass.seed, pass.stream, uint64_t(q) * 32 + draw++);
            const int rx = int(bits % uint64_t(2 * r + 1)) - r;
            const int ry = int((bits >> 32) % uint64_t(2 * r + 1)) - r;
            consider(range.clamp(int(best % uint32_t(sw)) + rx, int(best / uint32_t(sw)) + ry));
        }
        pass.next->source[q] = best;
        pass.next->distance[q] = best_distance;
    }
}

} // namespace

float patch_distance(const PixelImage& padded, int pad, int x, int y, const PixelImage& sample,
    uint32_t source, int patch, float bound)
{
    return distance_at(padded, pad, x, y, sample, source, patch, bound);
}

void patch_match(const SampleLevel& sample, const PixelImage& padded, int pad,
    const std::vector<uint32_t>& similar, const MatchSettings& settings, PatchField& field)
{
    const int w = field.width, h = field.height, sw = sample.pixels.width;
    const CentreRange range { sw, sample.pixels.height, settings.patch / 2, sample.cell_width };
    const size_t n = size_t(w) * size_t(h);
    const int nblocks = (h + kRowBlock - 1) / kRowBlock;
    const float inf = std::numeric_limits<float>::infinity();

    // The output changed since the field was made: measure every source again.
    OIIO::parallel_for(
        0, nblocks,
        [&](int64_t b) {
            if (stop_requested(settings.stop))
                return;
            for (int y = int(b) * kRowBlock; y < std::min(h, int(b + 1) * kRowBlock); ++y)
                for (int x = 0; x < w; ++x) {
                    const size_t q = size_t(y) * size_t(w) + size_t(x);
                    if (settings.active && !(*settings.active)[q])
                        continue;
                    field.distance[q] = distance_at(
                        padded, pad, x, y, sample.pixels, field.source[q], settings.patch, inf);
                }
        },
        detail::split_every_item(settings.nthreads));

    // The penalty of a source used `count` times: repetition x the field's mean distance
    // for each use beyond the count an even use of the sample gives each centre, so that
    // over-used sources give way and the rest are free (no churn among them).
    auto searched = [&](size_t q) { return !settings.active || (*settings.active)[q] != 0; };
    size_t nsearched = 0;
    double mean = 0.0; // summed in row order: the same whatever the thread count
    for (size_t q = 0; q < n; ++q)
        if (searched(q)) {
            ++nsearched;
            mean += double(field.distance[q]);
        }
    const size_t sources = sample.valid.empty()
        ? range.count()
        : size_t(std::count(sample.valid.begin(), sample.valid.end(), uint8_t(1)));
    const double ideal = double(nsearched) / double(std::max<size_t>(sources, 1));
    mean /= double(std::max<size_t>(nsearched, 1));
    const float unit = float(double(settings.repetition) * mean / ideal);
    const float free_uses = float(ideal);
    std::vector<uint32_t> uses(
        settings.repetition > 0.0f ? size_t(sw) * size_t(sample.pixels.height) : 0);
    const size_t k
        = settings.coherence > 1 && !similar.empty() ? size_t(settings.coherence - 1) : 0;

    PatchField next = field;
    const int radius0 = settings.radius > 0 ? settings.radius : std::max(sw, sample.pixels.height);
    for (size_t pass = 0; pass < settings.steps.size(); ++pass) {
        if (stop_requested(settings.stop))
            return;
        const int step = settings.steps[pass];
        if (!uses.empty()) {
            std::fill(uses.begin(), uses.end(), 0u);
            for (size_t q = 0; q < n; ++q)
                if (searched(q))
                    ++uses[field.source[q]];
        }
        const Pass context { &sample, &padded, pad, settings.patch, step, radius0, range, &field,
            &next, &similar, k, &uses, unit, free_uses, settings.seed, settings.stream * 16 + pass,
            settings.active, settings.wrap };
        OIIO::parallel_for(
            0, nblocks,
            [&](int64_t b) {
                if (stop_requested(settings.stop))
                    return;
                for (int y = int(b) * kRowBlock; y < std::min(h, int(b + 1) * kRowBlock); ++y)
                    search_row(context, y);
            },
            detail::split_every_item(settings.nthreads));
        std::swap(field.source, next.source);
        std::swap(field.distance, next.distance);
    }
}

} // namespace texsyn::detail
