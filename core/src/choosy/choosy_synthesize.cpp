// SPDX-License-Identifier: Apache-2.0
// Castellanos & Williams Algorithm 1 on the pixel grid (choosy.h).
#include <texsyn/choosy.h>

#include <algorithm>

#include <texsyn/random.h>

#include "choosy_pvt.h"
#include "methods/method_helpers_pvt.h"
#include "methods/source_map_pvt.h"

namespace texsyn {

namespace {

using detail::GridLevel;

// A level must hold the 5x5 neighbourhood (a sample level at least one of them).
constexpr int kMinLevelSide = 5;

std::string size_text(int w, int h)
{
    return std::to_string(w) + "x" + std::to_string(h);
}

// The most levels (<= wanted) whose coarsest level of a w x h image is at least 5x5.
int levels_allowed(int w, int h, int wanted)
{
    int l = 0;
    while (l < wanted && (w >> l) >= kMinLevelSide && (h >> l) >= kMinLevelSide)
        ++l;
    return l;
}

// An output level of w x h with room for its Laplacian children (below the finest).
GridLevel empty_level(int w, int h, size_t nchannels, bool finest)
{
    GridLevel out;
    out.gaussian.assign(nchannels, Plane(w, h));
    if (!finest)
        out.children.assign(nchannels, Plane(2 * w, 2 * h));
    out.source.assign(size_t(w) * size_t(h), 0);
    out.orientation.assign(out.source.size(), detail::kNotChosen);
    return out;
}

// G_0 of Algorithm 1: each pixel a seeded random pixel of the coarsest sample level.
void random_start(GridLevel& out, const std::vector<Plane>& sample, uint64_t seed)
{
    const uint64_t npixels = uint64_t(sample[0].width()) * uint64_t(sample[0].height());
    for (size_t i = 0; i < out.source.size(); ++i) {
        const uint64_t r = random_bits(seed, 0x43570000, i) >> 32;
        out.source[i] = uint32_t((r * npixels) >> 32);
        for (size_t ch = 0; ch < sample.size(); ++ch)
            out.gaussian[ch].data()[i] = sample[ch].data()[out.source[i]];
    }
}

bool synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const ChoosyOptions& opt,
    OIIO::ImageBuf* source_map)
{
    PlanarImage in;
    if (!detail::validated_sample(dst, sample, opt, in))
        return false;
    std::string error;
    const int unit = 1 << (opt.levels - 1);
    const int sw = in.width(), sh = in.height();
    const int cw = std::max(sw / unit * unit, 1), chh = std::max(sh / unit * unit, 1);
    const int w = opt.width ? opt.width : cw, h = opt.height ? opt.height : chh;
    if (!detail::check_choosy_sizes(sw, sh, w, h, opt, error)
        || !detail::check_memory(choosy_memory_estimate(cw, chh, in.nchannels(), w, h, opt),
            "size=" + size_text(w, h), error)) {
        dst.errorfmt("{}", error);
        return false;
    }

    const detail::ChoosyAnalysis analysis = detail::analyze_choosy(
        detail::crop_to_multiple(in.channels, unit), opt.levels, opt.nthreads);
    const int orientations = opt.isotropic ? 8 : 1;
    detail::PassProgress progress;
    progress.total = 0;
    for (int l = 0; l < opt.levels; ++l)
        progress.total += size_t(opt.iterations_at(l)) * size_t(w >> l) * size_t(h >> l);
    const int top = opt.levels - 1;
    GridLevel out = empty_level(w >> top, h >> top, in.nchannels(), top == 0);
    random_start(out, analysis.gaussian[size_t(top)], opt.seed);
    static const std::vector<Plane> none;
    for (int l = top; l >= 0; --l) {
        const std::vector<Plane>& gaussian = analysis.gaussian[size_t(l)];
        const std::vector<Plane>& children = l > 0 ? analysis.laplacian[size_t(l - 1)] : none;
        {
            const detail::AnalysisPoints points = detail::grid_points(gaussian, orientations);
            auto index = detail::make_choice_index(points, opt);
            auto target = detail::make_grid_target(out, gaussian, children, orientations);
            detail::choosy_passes(*target, *index, opt, opt.iterations_at(l),
                0x43530000 + uint64_t(l) * 256, progress);
        }
        if (l > 0) {
            GridLevel next = empty_level(w >> (l - 1), h >> (l - 1), in.nchannels(), l == 1);
            next.gaussian = detail::invert_level(
                out.children, out.gaussian, Boundary::Circular, opt.nthreads);
            out = std::move(next);
        }
    }

    ChoosyOptions resolved = opt;
    resolved.width = w;
    resolved.height = h;
    if (source_map)
        detail::write_source_map(
            *source_map, out.source, w, h, cw, sw, sh, opt.isotropic ? &out.orientation : nullptr);
    detail::write_synthesis(dst, out.gaussian, in, sample, "choosy", resolved, source_map);
    return true;
}

} // namespace

bool choosy_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const ChoosyOptions& opt,
    OIIO::ImageBuf* source_map)
{
    return detail::guarded(
        dst, "choosy_synthesize", [&] { return synthesize(dst, sample, opt, source_map); });
}

OIIO::ImageBuf choosy_synthesize(
    const OIIO::ImageBuf& sample, const ChoosyOptions& opt, OIIO::ImageBuf* source_map)
{
    return detail::value_form("choosy_synthesize",
        [&](OIIO::ImageBuf& dst) { return choosy_synthesize(dst, sample, opt, source_map); });
}

namespace detail {

std::vector<Plane> crop_to_multiple(const std::vector<Plane>& planes, int unit)
{
    const int w = planes[0].width() / unit * unit, h = planes[0].height() / unit * unit;
    if (w == planes[0].width() && h == planes[0].height())
        return planes;
    std::vector<Plane> out;
    for (const Plane& p : planes) {
        Plane c(w, h);
        for (int y = 0; y < h; ++y)
            std::copy_n(p.row(y), w, c.row(y));
        out.push_back(std::move(c));
    }
    return out;
}

std::unique_ptr<ChoiceIndex> make_choice_index(
    const AnalysisPoints& points, const ChoosyOptions& opt)
{
    if (opt.search == ChoosySearch::Exhaustive)
        return make_exhaustive_choice(points, opt.penalty, opt.nthreads);
    return make_kdtree_choice(points, opt.penalty, opt.dims, opt.eps, opt.nthreads);
}

// The sample's size `sw` x `sh` as given (its crop to a multiple of 2^(levels-1) has the
// same coarsest level).
bool check_choosy_sizes(int sw, int sh, int w, int h, const ChoosyOptions& opt, std::string& error)
{
    const int unit = 1 << (opt.levels - 1);
    const int allowed = levels_allowed(sw, sh, opt.levels);
    if (allowed == 0) {
        error = "the sample (" + size_text(sw, sh) + ") is smaller than the 5x5 neighbourhood";
        return false;
    }
    if (allowed < opt.levels) {
        error = "levels=" + std::to_string(opt.levels) + " is too many for the sample ("
            + size_text(sw, sh) + "): its coarsest level would be smaller than the 5x5 "
            + "neighbourhood (use levels=" + std::to_string(allowed) + " or less)";
        return false;
    }
    if (w % unit != 0 || h % unit != 0) {
        auto nearest = [unit](int v) { return std::max(unit, (v + unit / 2) / unit * unit); };
        error = "size=" + size_text(w, h) + ": each side must be a multiple of "
            + std::to_string(unit) + " (2^(levels-1)) for levels=" + std::to_string(opt.levels)
            + "; the nearest is " + size_text(nearest(w), nearest(h));
        return false;
    }
    if (w / unit < kMinLevelSide || h / unit < kMinLevelSide) {
        error = "size=" + size_text(w, h) + " is too small for levels=" + std::to_string(opt.levels)
            + ": the coarsest output level would be " + size_text(w / unit, h / unit)
            + ", smaller than the 5x5 neighbourhood";
        return false;
    }
    return true;
}

} // namespace detail

} // namespace texsyn
