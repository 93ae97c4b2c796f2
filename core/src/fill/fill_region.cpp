// SPDX-License-Identifier: Apache-2.0
// One region of a fill, coarse to fine: texture optimization over the hole with the known
// pixels held fixed (Wexler et al. 2007), on the patch method's search and vote.
#include "fill_pvt.h"

#include <algorithm>

#include <texsyn/histogram.h>
#include <texsyn/pyramid.h>
#include <texsyn/random.h>

#include "methods/method_helpers_pvt.h"
#include "patch/patch_pvt.h"

namespace texsyn::detail {

namespace {

// The random search's first radius below the coarsest level (the patch method's).
constexpr int kFineRadius = 8;

std::vector<int> patches_at(const FillOptions& opt, int level)
{
    return level == 0 ? std::vector<int> { opt.patch.back() } : opt.patch;
}

// Where a level's patches may come from, for one patch size: the sample level with the
// centres it allows, and those centres listed (for random picks).
struct Sources {
    SampleLevel level;
    CentreRange range;
    std::vector<uint32_t> list;
};

// The sources for patch size `patch`: the crop's (patches wholly of source pixels) or the
// sample's (every centre).
void choose_sources(Sources& s, const CropLevel& crop, bool self, int patch)
{
    const int half = patch / 2, w = s.level.pixels.width, h = s.level.pixels.height;
    s.range = { w, h, half, 0 };
    s.level.valid = self ? erode_box(crop.source, w, h, half) : std::vector<uint8_t>();
    s.list.clear();
    for (int y = s.range.y0(); y <= s.range.y1(); ++y)
        for (int x = half; x < w - half; ++x) {
            const uint32_t q = uint32_t(y) * uint32_t(w) + uint32_t(x);
            if (s.level.allows(q))
                s.list.push_back(q);
        }
}

// Every field source an allowed one: a pixel of the crop whose own patch is a source keeps
// itself (with the image as the source); an active pixel with a disallowed source, and
// any other, gets a random allowed one.
void settle_sources(PatchField& field, const Sources& s, bool self,
    const std::vector<uint8_t>& active, uint64_t seed, uint64_t stream)
{
    for (size_t q = 0; q < field.source.size(); ++q) {
        uint32_t& source = field.source[q];
        if (self && !active[q] && s.level.allows(uint32_t(q))) {
            source = uint32_t(q);
            continue;
        }
        source = s.range.clamp(
            int(source % uint32_t(s.range.width)), int(source / uint32_t(s.range.width)));
        if (!s.level.allows(source))
            source = s.list[random_bits(seed, stream, q) % s.list.size()];
    }
}

// The pixels whose patch (half-width `half`) covers a pixel to fill.
std::vector<uint8_t> active_pixels(const CropLevel& crop, int half)
{
    std::vector<uint8_t> unknown(crop.known.size());
    std::transform(
        crop.known.begin(), crop.known.end(), unknown.begin(), [](uint8_t k) { return !k; });
    return dilate_box(unknown, crop.width(), crop.height(), half);
}

std::string size_text(int w, int h)
{
    return std::to_string(w) + "x" + std::to_string(h);
}

// Per channel, the histogram the filled pixels are matched to: the values of the source
// pixels (the crop's patches come from them), or of the sample's level.
std::vector<QuantileTable> fill_histograms(
    const CropLevel& crop, const std::vector<Plane>& sample_level)
{
    std::vector<QuantileTable> tables;
    if (!sample_level.empty()) {
        for (const Plane& p : sample_level)
            tables.emplace_back(p);
        return tables;
    }
    std::vector<float> values;
    for (const Plane& p : crop.planes) {
        values.clear();
        for (size_t i = 0; i < p.size(); ++i)
            if (crop.source[i])
                values.push_back(p.data()[i]);
        tables.push_back(
            values.empty() ? QuantileTable() : QuantileTable(values.data(), values.size()));
    }
    return tables;
}

// The filled pixels of each channel matched to its histogram (Kaspar et al. 2015 §4.1: the
// vote averages patches that disagree, and without this the fill washes out to a flat
// blur where the hole is wide).
void match_filled(std::vector<Plane>& out, const std::vector<uint8_t>& known,
    const std::vector<QuantileTable>& tables, int nthreads)
{
    std::vector<size_t> filled;
    for (size_t i = 0; i < known.size(); ++i)
        if (!known[i])
            filled.push_back(i);
    if (filled.empty())
        return;
    for (size_t c = 0; c < out.size(); ++c) {
        if (tables[c].empty())
            continue;
        Plane values(int(filled.size()), 1);
        for (size_t j = 0; j < filled.size(); ++j)
            values.data()[j] = out[c].data()[filled[j]];
        match_histogram(values, tables[c], HistogramMode::Exact, nthreads);
        for (size_t j = 0; j < filled.size(); ++j)
            out[c].data()[filled[j]] = values.data()[j];
    }
}

} // namespace

double fill_work(const std::vector<CropLevel>& levels, const FillOptions& opt)
{
    double total = 0.0;
    for (size_t l = 0; l < levels.size(); ++l)
        total += double(patches_at(opt, int(l)).size()) * opt.iterations_at(int(l))
            * double(levels[l].width()) * double(levels[l].height());
    return total;
}

bool fill_region(std::vector<CropLevel>& levels, const std::vector<std::vector<Plane>>& sample,
    const FillOptions& opt, uint64_t stream, double& done, double total, RegionFill& result,
    std::string& error)
{
    const bool self = sample.empty();
    const int nlevels = int(levels.size());
    PatchField field;
    CentreRange coarse_range;
    std::vector<Plane> out;
    Sources sources;
    int last_patch = 0;
    for (int l = nlevels - 1; l >= 0; --l) {
        CropLevel& crop = levels[size_t(l)];
        const int w = crop.width(), h = crop.height();
        sources.level
            = sample_level(self ? crop.planes : sample[size_t(l)], 0, opt.nthreads, false);
        // The start: push-pull at the coarsest level (with nothing known, the vote of
        // random sources, below), the coarser result expanded below it.
        const bool nothing_known
            = std::find(crop.known.begin(), crop.known.end(), uint8_t(1)) == crop.known.end();
        throw_if_stopped(opt.stop);
        if (l == nlevels - 1) {
            if (!nothing_known)
                pushpull_fill(crop, opt.nthreads);
            out = crop.planes;
        } else {
            for (size_t c = 0; c < out.size(); ++c) {
                const Plane up = expand_plane(out[c], w, h, Boundary::Reflect, opt.nthreads);
                Plane next = crop.planes[c];
                for (size_t i = 0; i < next.size(); ++i)
                    if (!crop.known[i])
                        next.data()[i] = up.data()[i];
                out[c] = std::move(next);
            }
        }
        const std::vector<QuantileTable> histograms
            = fill_histograms(crop, self ? std::vector<Plane>() : sample[size_t(l)]);
        const std::vector<int> patches = patches_at(opt, l);
        const std::vector<uint32_t> similar = l == 0
            ? std::vector<uint32_t>()
            : similar_patches(
                sources.level.pixels, 0, patches.front(), opt.coherence, opt.nthreads, opt.stop);
        throw_if_stopped(opt.stop);
        for (size_t pi = 0; pi < patches.size(); ++pi) {
            const int p = patches[pi], half = p / 2;
            choose_sources(sources, crop, self, p);
            if (sources.list.empty()) {
                error = self ? "no " + std::to_string(p) + "x" + std::to_string(p)
                        + " patch of known pixels around the hole at level " + std::to_string(l)
                        + " (a " + size_text(w, h)
                        + " crop): give a larger context=, fewer levels= or a smaller patch="
                             : "the sample is smaller than the " + std::to_string(p)
                        + "-pixel patch at level " + std::to_string(l) + " (give fewer levels=)";
                return false;
            }
            const std::vector<uint8_t> active = active_pixels(crop, half);
            const uint64_t draws = (stream * 16 + uint64_t(l)) * 8 + pi;
            if (field.source.empty()) {
                field = { w, h, std::vector<uint32_t>(size_t(w) * size_t(h), 0),
                    std::vector<float>(size_t(w) * size_t(h), 0.0f) };
            } else if (pi == 0) {
                field = upsample_field(field, coarse_range, w, h, sources.range);
            }
            throw_if_stopped(opt.stop);
            settle_sources(field, sources, self, active, opt.seed, 0x46494c0000000000ull + draws);
            coarse_range = sources.range;
            if (nothing_known && l == nlevels - 1 && pi == 0)
                vote(sources.level, field, p, PatchVote::Mean, opt.nthreads, opt.stop, out,
                    Wrap::none());
            for (int it = 0; it < opt.iterations_at(l); ++it) {
                const PixelImage padded = interleave_padded(out, half, opt.nthreads, Wrap::none());
                MatchSettings match;
                match.patch = p;
                match.coherence = opt.coherence;
                match.repetition = opt.repetition;
                match.steps = l == nlevels - 1 && it == 0 ? std::vector<int> { 4, 2, 1 }
                                                          : std::vector<int> { 1 };
                match.radius = l == nlevels - 1 ? 0 : kFineRadius;
                match.seed = opt.seed;
                match.stream = draws * 64 + uint64_t(it);
                match.nthreads = opt.nthreads;
                match.active = &active;
                match.wrap = Wrap::none();
                match.stop = opt.stop;
                patch_match(sources.level, padded, half, similar, match, field);
                throw_if_stopped(opt.stop);
                std::vector<Plane> voted;
                vote(
                    sources.level, field, p, opt.vote, opt.nthreads, opt.stop, voted, Wrap::none());
                throw_if_stopped(opt.stop);
                for (size_t c = 0; c < out.size(); ++c)
                    for (size_t i = 0; i < out[c].size(); ++i)
                        if (!crop.known[i])
                            out[c].data()[i] = voted[c].data()[i];
                // Not at the finest level, which starts from a layout that has not washed
                // out: there the fill's own proportions (of mortar to brick, say) stand.
                if (l > 0)
                    match_filled(out, crop.known, histograms, opt.nthreads);
                done += double(w) * double(h);
                detail::report_progress(opt.progress, opt.stop, float(std::min(1.0, done / total)));
            }
            last_patch = p;
        }
    }
    result.copied = nearest_votes(
        sources.level, field, last_patch, out, opt.nthreads, opt.stop, Wrap::none());
    throw_if_stopped(opt.stop);
    return true;
}

} // namespace texsyn::detail
