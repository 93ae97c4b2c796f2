// SPDX-License-Identifier: Apache-2.0
// The patch method's options: table, validation, memory estimate.
#include <texsyn/patch.h>

#include <algorithm>

#include "methods/common_options_pvt.h"
#include "patch_options_pvt.h"
#include "patch_schedule_pvt.h"

namespace texsyn {

namespace {

constexpr int kMaxLevels = 8;

} // namespace

const OptionTable<PatchOptions>& PatchOptions::table()
{
    return declared_table<PatchOptions>([](OptionTable<PatchOptions>& t) {
        using O = PatchOptions;
        detail::add_output_size(t);
        t.integer("levels", &O::levels, 0, kMaxLevels,
             "Gaussian pyramid levels, synthesized coarse to fine; 0 = from the sample's "
             "feature size (its features about one patch wide at the coarsest level; a small "
             "sample also tries one level more or fewer and keeps the result nearer its "
             "arrangement that does not repeat itself)")
            .shared();
        detail::add_patch_schedule(t, kMaxLevels,
            "11,7 (smaller for a sample or output under 33 px)",
            "1 at the finest level, 3 at the next, 8 at the coarser ones");
        t.real("repetition", &O::repetition, 0.0f, 10.0f,
            "spatial-uniformity penalty: a source patch used more than an even use of the "
            "sample would use it costs more (spreads the result over the whole sample); 0 = "
            "the plain method");
        t.real("guidance", &O::guidance, 0.0f, 10.0f,
            "weight of the automatic guidance channel (distance to the sample's edges), "
            "which keeps features whole; 0 = none");
        detail::add_patch_terms(t);
        t.integer("isotropic", &O::isotropic, 0, 1,
            "1 = patches may also come from the sample rotated and mirrored (8 variants if "
            "square, else 4); 0 = the sample's orientation is kept");
        detail::add_flatten(t);
        t.choice("wrap", &O::wrap,
            { { "both", PatchWrap::Both }, { "x", PatchWrap::X }, { "y", PatchWrap::Y },
                { "none", PatchWrap::None } },
            "the axes the result tiles along: both, x (a strip that repeats sideways: a trim "
            "sheet), y, or none (edges like a photograph's)");
        detail::add_scale(t);
    });
}

bool PatchOptions::validate(std::string& error) const
{
    return table().check(*this, error)
        && detail::check_patch_schedule(patch, iterations, levels, error);
}

namespace detail {

bool check_patch_schedule(const std::vector<int>& patch, const std::vector<int>& iterations,
    int levels, std::string& error)
{
    if (!std::is_sorted(patch.rbegin(), patch.rend())) {
        error = option_error("patch", format_int_list(patch), "list the sizes largest first");
        return false;
    }
    return levels == 0 || iterations.empty()
        || check_level_list(
            "iterations", format_int_list(iterations), iterations.size(), levels, error);
}

} // namespace detail

int PatchOptions::iterations_at(int level) const
{
    if (iterations.empty())
        return detail::automatic_iterations(level, std::max(levels, level + 1));
    return at_level(iterations, level, 1);
}

size_t patch_memory_estimate(int sample_width, int sample_height, int nchannels, int out_width,
    int out_height, const PatchOptions& opt)
{
    // With the guidance channel; the pyramids add a third.
    const double c = double(nchannels + (opt.guidance > 0.0f ? 1 : 0));
    const double variants = opt.isotropic ? (sample_width == sample_height ? 8.0 : 4.0) : 1.0;
    const double sample = double(sample_width) * double(sample_height) * variants;
    const double out = double(out_width) * double(out_height);
    // The sample: its planes and interleaved pixels. The output: the vote's planes, the
    // padded interleaved copy, the field twice (source, distance), the vote's weights and
    // the result with its source map.
    const double pyramid = 4.0 / 3.0;
    const double sample_bytes = sample * c * 4.0 * 2.0 * pyramid;
    const double out_bytes = out * (c * 4.0 * 3.0 + 8.0 * 2.0 + 8.0) * pyramid + out * 8.0;
    // k-coherence: the patch vectors of the finest level's smallest patch or the next
    // level's largest, and their kd-tree.
    const double small = opt.patch.empty() ? 7.0 : double(opt.patch.back());
    const double large = opt.patch.empty() ? 11.0 : double(opt.patch.front());
    const double vectors = opt.coherence > 1
        ? std::max(sample * small * small, sample / 4.0 * large * large) * c * 4.0
            + sample * (4.0 * double(opt.coherence) + 40.0)
        : 0.0;
    const double bytes = sample_bytes + out_bytes + vectors;
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
