// SPDX-License-Identifier: Apache-2.0
// Texture optimization coarse to fine (Kwatra et al. 2005; Kaspar et al. 2015): the levels,
// the EM loop of search and vote per patch size, and the final copy.
#include <texsyn/patch.h>

#include <algorithm>
#include <cmath>

#include <texsyn/feature_scale.h>
#include <texsyn/homogeneity.h>
#include <texsyn/pyramid.h>
#include <texsyn/random.h>

#include "feature_scale/structure_distance_pvt.h"
#include "methods/method_helpers_pvt.h"
#include "methods/source_map_pvt.h"
#include "patch_pvt.h"
#include "patch_schedule_pvt.h"

namespace texsyn {

namespace {

using detail::PatchField;
using detail::SampleLevel;

// The random search's first radius below the coarsest level.
constexpr int kFineRadius = 8;
// The trial that chooses between level counts (chosen_copies) is this many times the
// sample's size: enough output for the layouts to differ as they will in the result.
constexpr double kTrialScale = 2.0;

std::string size_text(int w, int h)
{
    return std::to_string(w) + "x" + std::to_string(h);
}

// The patch sizes level `level` optimizes with: all of them, but only the smallest at the
// finest level.
std::vector<int> patches_at(const PatchOptions& opt, int level)
{
    return level == 0 ? std::vector<int> { opt.patch.back() } : opt.patch;
}

// Level sizes: each ceil(half) of the one below (reduce_plane's).
std::vector<std::pair<int, int>> level_sizes(int w, int h, int levels)
{
    std::vector<std::pair<int, int>> sizes { { w, h } };
    for (int l = 1; l < levels; ++l)
        sizes.emplace_back((sizes.back().first + 1) / 2, (sizes.back().second + 1) / 2);
    return sizes;
}

// The most levels (<= `wanted`) whose sample and output levels all hold their largest
// patch; 0 if not even the finest does.
int levels_that_fit(int sw, int sh, int w, int h, int wanted, const PatchOptions& opt)
{
    const auto samples = level_sizes(sw, sh, wanted), outs = level_sizes(w, h, wanted);
    for (int l = 0; l < wanted; ++l) {
        const int p = patches_at(opt, l).front();
        if (std::min(samples[size_t(l)].first, samples[size_t(l)].second) < p
            || std::min(outs[size_t(l)].first, outs[size_t(l)].second) < p)
            return l;
    }
    return wanted;
}

// The options as they run: the patch sizes, levels and iterations that are automatic
// chosen (patch_schedule_pvt.h; `reason` says how the levels were), and given levels
// checked against the sample's and output's sizes. False with a message if the sample or
// output is too small.
bool resolve_schedule(int sw, int sh, int w, int h, const FeatureScale& scale, PatchOptions& o,
    std::string& reason, std::string& error)
{
    if (o.patch.empty())
        o.patch = detail::automatic_patch_sizes(std::min({ sw, sh, w, h }));
    if (o.levels == 0) {
        const int wanted
            = detail::automatic_levels(std::min(sw, sh), scale, o.patch.front(), reason);
        o.levels = std::max(1, levels_that_fit(sw, sh, w, h, wanted, o));
        if (o.levels < wanted)
            reason += "; " + std::to_string(o.levels) + " fit the output";
    } else {
        const int fit = levels_that_fit(sw, sh, w, h, o.levels, o);
        if (fit > 0 && fit < o.levels) {
            error = "levels=" + std::to_string(o.levels) + " is too many for a " + size_text(sw, sh)
                + " sample and a " + size_text(w, h) + " output: level " + std::to_string(fit)
                + " would be smaller than its " + std::to_string(patches_at(o, fit).front())
                + "-pixel patch (use levels=" + std::to_string(fit) + " or less)";
            return false;
        }
        reason = std::to_string(o.levels) + " levels, as given";
    }
    const int p = o.patch.back();
    if (std::min(sw, sh) < p || std::min(w, h) < p) {
        error = std::min(sw, sh) < p ? "the sample (" + size_text(sw, sh) + ") is smaller than the "
                + std::to_string(p) + "-pixel patch (give a smaller patch=)"
                                     : "size=" + size_text(w, h) + " is smaller than the "
                + std::to_string(p) + "-pixel patch";
        return false;
    }
    if (o.iterations.empty())
        for (int l = 0; l < o.levels; ++l)
            o.iterations.push_back(detail::automatic_iterations(l, o.levels));
    return true;
}

// The coarsest field: seeded random sources.
PatchField random_field(int w, int h, const detail::CentreRange& range, uint64_t seed)
{
    PatchField field { w, h, std::vector<uint32_t>(size_t(w) * size_t(h)),
        std::vector<float>(size_t(w) * size_t(h), 0.0f) };
    const int columns = range.columns(), rows = range.y1() - range.y0() + 1;
    for (size_t q = 0; q < field.source.size(); ++q) {
        const uint64_t bits = random_bits(seed, 0x5041000000000001ull, q);
        field.source[q] = range.clamp(range.column_x(int(bits % uint64_t(columns))),
            range.y0() + int((bits >> 32) % uint64_t(rows)));
    }
    return field;
}

// The guide image as a plane scaled like the automatic guidance channel: zero mean and the
// colour channels' mean standard deviation (guidance_channel's scale).
bool guide_plane(const OIIO::ImageBuf& guide, int sw, int sh, const std::vector<Plane>& colour,
    Plane& plane, std::string& error)
{
    PlanarImage g;
    if (!planes_from_imagebuf(guide, g, error)) {
        error = "guide: " + error;
        return false;
    }
    if (g.nchannels() != 1 || g.width() != sw || g.height() != sh) {
        error = "the guide is " + size_text(g.width(), g.height()) + " with "
            + detail::count_text(g.nchannels(), "channel") + "; it must be one channel of the "
            + "sample's size (" + size_text(sw, sh) + ")";
        return false;
    }
    plane = g.channels[0];
    detail::scale_like_colour(plane, colour);
    return true;
}

// What one run of the schedule copies: per output pixel, the picked pixel of the finest
// level's sample atlas (a variant's pixel with isotropic=1), `atlas_width` wide.
struct Copies {
    std::vector<uint32_t> picked;
    int atlas_width = 0;
};

// Texture optimization of the sample's levels into opt.width x opt.height with opt's
// resolved schedule (opt.levels at most those `sample` holds), coarse to fine. Progress
// goes from `progress_from` over `progress_span`.
Copies optimize(detail::SampleLevels& sample, const PatchOptions& opt, double progress_from,
    double progress_span)
{
    const int w = opt.width, h = opt.height, levels = opt.levels;
    const detail::Wrap wrap { opt.wrap == PatchWrap::Both || opt.wrap == PatchWrap::X,
        opt.wrap == PatchWrap::Both || opt.wrap == PatchWrap::Y };
    const auto out_sizes = level_sizes(w, h, levels);

    // Progress: one unit per output pixel searched and voted, per iteration.
    double total = 0.0, done = 0.0;
    for (int l = 0; l < levels; ++l)
        total += double(patches_at(opt, l).size()) * opt.iterations_at(l)
            * double(out_sizes[size_t(l)].first) * double(out_sizes[size_t(l)].second);

    PatchField field;
    detail::CentreRange coarse_range;
    std::vector<Plane> out;
    auto match_histograms = [&](const SampleLevel& level) {
        for (size_t c = 0; c < out.size(); ++c) {
            detail::throw_if_stopped(opt.stop);
            match_histogram(out[c], level.histograms[c], HistogramMode::Exact, opt.nthreads);
        }
    };
    for (int l = levels - 1; l >= 0; --l) {
        const bool coarsest = l == levels - 1;
        const SampleLevel& level = sample.level(l);
        const int lw = out_sizes[size_t(l)].first, lh = out_sizes[size_t(l)].second;
        const std::vector<int> patches = patches_at(opt, l);
        const detail::CentreRange first { level.pixels.width, level.pixels.height,
            patches.front() / 2, level.cell_width };
        field = coarsest ? random_field(lw, lh, first, opt.seed)
                         : detail::upsample_field(field, coarse_range, lw, lh, first);
        coarse_range = first;
        // The start: the vote of the random field, or of the coarser level's matches carried
        // to this level (its own, sharp pixels rather than the coarser result blurred up:
        // the finer level then starts where the coarser one converged).
        detail::vote(level, field, patches.front(), coarsest ? PatchVote::Mean : opt.vote,
            opt.nthreads, opt.stop, out, wrap);
        if (!coarsest)
            match_histograms(level);
        // k-coherence where the layout forms (the lists of the level's largest patch serve
        // its smaller ones); the finest level refines its coarser level's field with
        // propagation and a local random search.
        static const std::vector<uint32_t> none;
        const std::vector<uint32_t>& similar = l == 0 ? none : sample.similar(l, opt.stop);
        detail::throw_if_stopped(opt.stop);
        for (size_t pi = 0; pi < patches.size(); ++pi) {
            const int p = patches[pi];
            const detail::CentreRange range { level.pixels.width, level.pixels.height, p / 2,
                level.cell_width };
            for (uint32_t& s : field.source) // a smaller patch reaches nearer the edges
                s = range.clamp(int(s % uint32_t(range.width)), int(s / uint32_t(range.width)));
            for (int it = 0; it < opt.iterations_at(l); ++it) {
                const detail::PixelImage padded
                    = detail::interleave_padded(out, p / 2, opt.nthreads, wrap);
                detail::MatchSettings match;
                match.patch = p;
                match.coherence = opt.coherence;
                match.repetition = opt.repetition;
                // The coarsest level lays the texture out with its largest patch: jump-flood
                // passes every iteration spread good matches far, so that its matches grow
                // coherent before the votes smooth it. Finer levels, and smaller patches,
                // start from that layout and search near it.
                match.steps
                    = coarsest && pi == 0 ? std::vector<int> { 4, 2, 1 } : std::vector<int> { 1 };
                match.radius = coarsest ? 0 : kFineRadius;
                match.seed = opt.seed;
                match.stream = (uint64_t(l) * 8 + pi) * 64 + uint64_t(it);
                match.nthreads = opt.nthreads;
                match.stop = opt.stop;
                match.wrap = wrap;
                detail::patch_match(level, padded, p / 2, similar, match, field);
                detail::throw_if_stopped(opt.stop);
                detail::vote(level, field, p, opt.vote, opt.nthreads, opt.stop, out, wrap);
                match_histograms(level);
                done += double(lw) * double(lh);
                detail::report_progress(
                    opt.progress, opt.stop, float(progress_from + progress_span * done / total));
            }
        }
    }

    // The copy: each pixel the voted-for sample pixel nearest the average.
    const SampleLevel& finest = sample.level(0);
    Copies copies;
    copies.picked
        = detail::nearest_votes(finest, field, opt.patch.back(), out, opt.nthreads, opt.stop, wrap);
    copies.atlas_width = finest.pixels.width;
    detail::throw_if_stopped(opt.stop);
    return copies;
}

// The output `copies` make, as pixels of the sample as given (a variant's pixel is one of
// the sample's): per output pixel the sample index in `chosen` and the variant in `turns`.
struct Copied {
    std::vector<uint32_t> chosen;
    std::vector<uint8_t> turns;
    PlanarImage image;
};

Copied copied(const Copies& copies, const PlanarImage& in, int w, int h)
{
    const int sw = in.width(), sh = in.height();
    Copied c;
    c.chosen.resize(copies.picked.size());
    c.turns.resize(copies.picked.size());
    for (size_t q = 0; q < copies.picked.size(); ++q) {
        const int x = int(copies.picked[q] % uint32_t(copies.atlas_width));
        const int y = int(copies.picked[q] / uint32_t(copies.atlas_width));
        c.chosen[q] = detail::variant_source(x / sw, sw, sh, x % sw, y);
        c.turns[q] = uint8_t(x / sw);
    }
    c.image.channel_names = in.channel_names;
    c.image.alpha_channel = in.alpha_channel;
    c.image.channels.assign(size_t(in.nchannels()), Plane(w, h));
    for (size_t ch = 0; ch < c.image.channels.size(); ++ch)
        for (size_t q = 0; q < c.chosen.size(); ++q)
            c.image.channels[ch].data()[q] = in.channels[ch].data()[c.chosen[q]];
    return c;
}

// A trial of one schedule: how far its arrangement is from the sample's
// (structure_distance), and how much it repeats itself at the sample's scale
// (repetition_excess).
struct Trial {
    double distance = 0.0, repetition = 0.0;
};

// A repetition excess above this shows as the same block recurring across the output (the
// sample pasted side by side gives 0.5 or more; new arrangements about 0)…
constexpr double kMaxRepetition = 0.1;

// …or above the autocorrelation's own noise on the trial, if that is more: a trial `side`
// pixels across holds about (side / feature)² independent features, and an autocorrelation
// measured over n of them varies by about 1/√n from one arrangement to the next.
double repetition_limit(double feature, int side)
{
    return std::max(kMaxRepetition, feature / double(side));
}

// Whether `a` is the better of two trials: the one that repeats itself less where either
// repeats beyond `limit`, else the nearer arrangement.
bool better_trial(const Trial& a, const Trial& b, double limit)
{
    if (std::max(a.repetition, b.repetition) > limit)
        return a.repetition < b.repetition;
    return a.distance < b.distance;
}

Trial trial_of(
    const Copies& copies, const PlanarImage& in, int w, int h, double feature, int nthreads)
{
    const PlanarImage image = copied(copies, in, w, h).image;
    return { detail::structure_distance(image, in, feature, nthreads),
        detail::repetition_excess(image, in, nthreads) };
}

// The copies of the synthesis with opt's schedule, or, where the automatic levels could as
// well be one more or fewer (patch_schedule_pvt.h: alternative_levels), of whichever of the
// two arranges the sample's features nearer the way the sample does without repeating
// itself: both run on a trial output (kTrialScale times the sample's size, or the output
// itself where that is smaller) and are compared as Trial says. The deeper schedule is
// tried first: where it repeats itself, the shallower one, which lays out smaller pieces
// and so repeats less, is kept without a trial of its own. `schedule` then says which was
// kept and why, and `opt` holds the kept levels and iterations.
Copies chosen_copies(const std::vector<Plane>& planes, const PlanarImage& in,
    const FeatureScale& scale, bool automatic_levels, PatchOptions& opt, std::string& schedule)
{
    const int sw = in.width(), sh = in.height();
    const int other
        = automatic_levels ? detail::alternative_levels(std::min(sw, sh), scale, opt.levels) : 0;
    const int deepest = std::max(opt.levels, other);
    detail::SampleLevels sample(
        planes, deepest, opt.isotropic != 0, opt.patch.front(), opt.coherence, opt.nthreads);
    PatchOptions trial = opt; // the trial's size
    trial.width = std::min(opt.width, int(kTrialScale * sw));
    trial.height = std::min(opt.height, int(kTrialScale * sh));
    if (other == 0 || levels_that_fit(sw, sh, trial.width, trial.height, deepest, opt) < deepest)
        return optimize(sample, opt, 0.0, 1.0);
    const bool final_size = trial.width == opt.width && trial.height == opt.height;
    const double span = final_size ? 0.5 : 0.25;
    PatchOptions alternative = trial; // the other level count
    alternative.levels = other;
    alternative.iterations.clear();
    for (int l = 0; l < other; ++l)
        alternative.iterations.push_back(opt.iterations_at(l));
    const PatchOptions& deep = other > opt.levels ? alternative : trial;
    const PatchOptions& shallow = other > opt.levels ? trial : alternative;
    const double limit = repetition_limit(scale.size, std::min(trial.width, trial.height));
    auto keep = [&](const PatchOptions& kept) {
        opt.levels = kept.levels;
        opt.iterations = kept.iterations;
    };
    char why[240];
    Copies d = optimize(sample, deep, 0.0, span);
    const Trial td = trial_of(d, in, trial.width, trial.height, scale.size, opt.nthreads);
    if (td.repetition > limit) {
        std::snprintf(why, sizeof(why),
            "; %d levels kept over %d, which repeats itself on a %dx%d trial (repetition %.3f)",
            shallow.levels, deep.levels, trial.width, trial.height, td.repetition);
        schedule += why;
        keep(shallow);
        return optimize(sample, opt, span, 1.0 - span);
    }
    Copies s = optimize(sample, shallow, span, span);
    const Trial ts = trial_of(s, in, trial.width, trial.height, scale.size, opt.nthreads);
    const bool keep_deep = better_trial(td, ts, limit);
    const Trial& kept = keep_deep ? td : ts;
    const Trial& dropped = keep_deep ? ts : td;
    std::snprintf(why, sizeof(why),
        "; %d levels kept over %d: structure distance %.3f against %.3f%s on a %dx%d trial",
        keep_deep ? deep.levels : shallow.levels, keep_deep ? shallow.levels : deep.levels,
        kept.distance, dropped.distance, dropped.repetition > limit ? ", which repeats itself" : "",
        trial.width, trial.height);
    schedule += why;
    keep(keep_deep ? deep : shallow);
    if (final_size)
        return keep_deep ? std::move(d) : std::move(s);
    return optimize(sample, opt, 2 * span, 1.0 - 2 * span);
}

bool synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const PatchOptions& given,
    OIIO::ImageBuf* source_map, const OIIO::ImageBuf* guide, PatchReport* report)
{
    std::string error;
    PlanarImage in;
    if (!detail::validated_sample(dst, sample, given, in))
        return false;
    auto fail = [&](const std::string& message) {
        dst.errorfmt("{}", message);
        return false;
    };
    const int sw = in.width(), sh = in.height();
    const int w = given.width ? given.width : sw, h = given.height ? given.height : sh;
    const std::vector<Plane> colour(in.channels.begin(), in.channels.begin() + in.ncolor());
    const FeatureScale scale = estimate_feature_scale(in, given.nthreads);
    PatchOptions opt = given;
    opt.width = w;
    opt.height = h;
    std::string schedule;
    if (!resolve_schedule(sw, sh, w, h, scale, opt, schedule, error)
        || !detail::check_memory(patch_memory_estimate(sw, sh, in.nchannels(), w, h, opt),
            "size=" + size_text(w, h), error))
        return fail(error);
    if (guide && opt.guidance <= 0.0f)
        return fail("guidance=0 : a guide needs a guidance weight above 0");

    // The planes synthesized: the sample's, then the guidance channel (weighted).
    std::vector<Plane> planes = in.channels;
    if (opt.guidance > 0.0f) {
        Plane g;
        if (guide) {
            if (!guide_plane(*guide, sw, sh, colour, g, error))
                return fail(error);
        } else {
            g = detail::guidance_channel(
                colour, int(std::lround(scale.size)), opt.nthreads, opt.stop);
        }
        for (size_t i = 0; i < g.size(); ++i)
            g.data()[i] *= opt.guidance;
        planes.push_back(std::move(g));
    }
    const Copies copies = chosen_copies(planes, in, scale, given.levels == 0, opt, schedule);
    Copied result = copied(copies, in, w, h);
    const detail::Wrap wrap { opt.wrap == PatchWrap::Both || opt.wrap == PatchWrap::X,
        opt.wrap == PatchWrap::Both || opt.wrap == PatchWrap::Y };
    if (report) {
        report->levels = opt.levels;
        report->scale = scale;
        report->schedule = schedule;
        report->used_fraction = detail::used_fraction(result.chosen, size_t(sw) * size_t(sh));
        report->largest_copy
            = detail::largest_copy(copies.picked, w, h, copies.atlas_width, sh, wrap.x, wrap.y);
        report->largest_copy_fraction = double(report->largest_copy) / (double(sw) * double(sh));
    }
    if (source_map)
        detail::write_source_map(
            *source_map, result.chosen, w, h, sw, sw, sh, opt.isotropic ? &result.turns : nullptr);
    detail::write_synthesis(
        dst, std::move(result.image.channels), in, sample, "patch", opt, source_map);
    if (wrap.x || wrap.y)
        dst.specmod().attribute("wrapmodes",
            std::string(wrap.x ? "periodic" : "black") + "," + (wrap.y ? "periodic" : "black"));
    return true;
}

} // namespace

bool patch_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const PatchOptions& opt,
    OIIO::ImageBuf* source_map, const OIIO::ImageBuf* guide, PatchReport* report)
{
    return detail::guarded(dst, "patch_synthesize",
        [&] { return synthesize(dst, sample, opt, source_map, guide, report); });
}

OIIO::ImageBuf patch_synthesize(const OIIO::ImageBuf& sample, const PatchOptions& opt,
    OIIO::ImageBuf* source_map, const OIIO::ImageBuf* guide, PatchReport* report)
{
    return detail::value_form("patch_synthesize", [&](OIIO::ImageBuf& dst) {
        return patch_synthesize(dst, sample, opt, source_map, guide, report);
    });
}

} // namespace texsyn
