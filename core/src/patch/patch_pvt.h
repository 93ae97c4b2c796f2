// SPDX-License-Identifier: Apache-2.0
// The patch method's parts: interleaved levels, the nearest-neighbour field and its
// PatchMatch search, the vote, the guidance channel and the copy report.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <texsyn/histogram.h>
#include <texsyn/image.h>
#include <texsyn/patch.h>

#include "image/wrap_pvt.h"

namespace texsyn::detail {

/// An image whose channels are interleaved (pixel-major): a patch row is contiguous.
struct PixelImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> data;

    float* pixel(int x, int y)
    {
        return data.data() + (size_t(y) * size_t(width) + size_t(x)) * size_t(channels);
    }
    const float* pixel(int x, int y) const
    {
        return data.data() + (size_t(y) * size_t(width) + size_t(x)) * size_t(channels);
    }
};

/// Which axes of an output wrap around (the output is periodic along them): patches there
/// overlap the opposite edge. Along an axis that does not wrap, only patches centred inside
/// the output overlap a pixel, and a patch centred near the edge reads the output
/// reflected.
struct Wrap {
    bool x = true, y = true;
    static Wrap none() { return { false, false }; }
};

/// `planes` interleaved.
PixelImage interleave(const std::vector<Plane>& planes, int nthreads);

/// `planes` interleaved with a margin of `pad` pixels on every side, circular along the
/// axes that `wrap` and reflected along the others: pixel (x, y) is at (x + pad, y + pad),
/// so a patch centred anywhere reads no wrap.
PixelImage interleave_padded(
    const std::vector<Plane>& planes, int pad, int nthreads, Wrap wrap = Wrap());

/// One level of the sample, as the search and the vote read it.
struct SampleLevel {
    PixelImage pixels;                     ///< every channel, the guidance channel last
    int cell_width = 0;                    ///< its variants' width (CentreRange), 0 = one
    std::vector<QuantileTable> histograms; ///< per channel, the targets of the vote
    double variance = 0.0;                 ///< summed over channels: a patch value's spread
    /// Per pixel (row-major), 1 where a patch centred there may be a source; empty = every
    /// centre of the CentreRange (a fill's context: patches of known pixels only).
    std::vector<uint8_t> valid;

    /// Whether `centre` (a sample index inside the CentreRange) may be a source.
    bool allows(uint32_t centre) const { return valid.empty() || valid[centre] != 0; }
};

/// The sample level of `planes` (variants `cell_width` wide side by side, 0 = one):
/// interleaved, each channel's histogram (unless `histograms` is false), the summed
/// variance.
SampleLevel sample_level(
    const std::vector<Plane>& planes, int cell_width, int nthreads, bool histograms = true);

/// The levels of one sample that the runs of one synthesis read (the level trial's runs
/// and the final one): the sample's Gaussian pyramid (with isotropic=1 each level an atlas
/// of its variants, each reduced on its own), each level's SampleLevel and its k-coherence
/// lists, each made once, when first asked for. Not thread-safe: one synthesis uses it.
class SampleLevels {
public:
    /// `planes` (the sample's, then the weighted guidance channel) up to `levels` levels;
    /// the k-coherence lists for `patch` x `patch` patches and `coherence`.
    SampleLevels(const std::vector<Plane>& planes, int levels, bool isotropic, int patch,
        int coherence, int nthreads);

    /// Level `l` (< levels).
    const SampleLevel& level(int l);

    /// Level `l`'s similar_patches table. A table cut short by `stop` is not kept.
    const std::vector<uint32_t>& similar(int l, const StopFlag* stop);

private:
    struct Entry {
        bool made = false, similar_made = false;
        SampleLevel level;
        std::vector<uint32_t> similar;
    };
    int m_variants, m_patch, m_coherence, m_nthreads;
    std::vector<std::vector<std::vector<Plane>>> m_pyramids; // [variant][level][channel]
    std::vector<Entry> m_entries;
};

/// The number of variants isotropic=1 takes of a width x height sample: its 8 rotations and
/// mirror images if square, else the 4 that keep its size (mirrored in x, in y, both).
int variant_count(int width, int height, bool isotropic);

/// Variant `t` of a plane (t < variant_count): pixel (x, y) of the variant is pixel
/// variant_source(t, …, x, y) of the plane.
Plane variant_plane(const Plane& plane, int t);

/// Where pixel (x, y) of variant `t` of a width x height sample comes from, as a sample
/// index y' * width + x'.
uint32_t variant_source(int t, int width, int height, int x, int y);

/// The nearest-neighbour field of one output level: per output pixel (row-major), the
/// centre of its source patch in the sample level (y * sample width + x) and the squared
/// distance between the two patches.
struct PatchField {
    int width = 0, height = 0;
    std::vector<uint32_t> source;
    std::vector<float> distance;
};

/// The centres a patch of half-width `half` may take in a width x height sample level made
/// of `cells` variants of the sample side by side, each cell_width wide (isotropic=1: the
/// sample rotated and mirrored; 0 = one cell, the whole width). A patch never straddles two
/// cells. Columns are numbered cell by cell.
struct CentreRange {
    int width = 0, height = 0, half = 0;
    int cell_width = 0;

    int cell() const { return cell_width > 0 ? cell_width : width; }
    int cells() const { return width / cell(); }
    int columns_per_cell() const { return cell() - 2 * half; }
    int columns() const { return cells() * columns_per_cell(); }
    int column_x(int i) const
    {
        return (i / columns_per_cell()) * cell() + half + i % columns_per_cell();
    }
    int y0() const { return half; }
    int y1() const { return height - 1 - half; } ///< inclusive
    bool empty() const { return columns_per_cell() < 1 || y1() < y0(); }
    size_t count() const { return empty() ? 0 : size_t(columns()) * size_t(y1() - y0() + 1); }
    /// (x, y) clamped to a valid centre of the cell x falls in (the nearest cell if x is
    /// outside the level), as a sample index.
    uint32_t clamp(int x, int y) const
    {
        const int c = cell();
        const int k = std::clamp(x < 0 ? 0 : x / c, 0, cells() - 1);
        const int local = std::clamp(x - k * c, half, c - 1 - half);
        return uint32_t(std::clamp(y, y0(), y1())) * uint32_t(width) + uint32_t(k * c + local);
    }
};

/// What one search (an EM iteration's) does.
struct MatchSettings {
    int patch = 7;                        ///< odd patch side
    int coherence = 1;                    ///< k of k-coherence (uses `similar`)
    float repetition = 0.0f;              ///< the spatial-uniformity penalty's strength
    std::vector<int> steps = { 4, 2, 1 }; ///< jump-flood propagation steps, one pass each
    int radius = 0; ///< the random search's first radius; 0 = the sample's larger side
    uint64_t seed = 0, stream = 0;
    int nthreads = 0;
    Wrap wrap; ///< propagation reaches across the output's edges along the axes that wrap
    /// Once set (stop.h), the row blocks and passes not yet started are skipped: the
    /// field is then unspecified and the caller checks the flag.
    const StopFlag* stop = nullptr;
    /// Per output pixel, 1 where the field is searched (a fill: patches over the hole);
    /// null = everywhere. Elsewhere source and distance are left as they are.
    const std::vector<uint8_t>* active = nullptr;
};

/// The field of the next finer level (w x h, its sample level's centres in `range`): each
/// pixel's coarse source (in `coarse_range`), doubled within its cell (the variant of the
/// sample it lies in), plus its offset from its coarse pixel's position doubled, clamped to
/// `range`. Distances are 0.
PatchField upsample_field(const PatchField& coarse, const CentreRange& coarse_range, int w, int h,
    const CentreRange& range);

/// Per sample centre (index y * width + x), its coherence - 1 most similar other centres
/// (by the distance of the patches' every other pixel each way, ranked among a kd-tree's
/// nearest in PCA space; centres within 2 pixels of it excluded, padded with itself),
/// coherence - 1 entries each. Empty if coherence < 2. Once `stop` is set (stop.h) it
/// gives up early with unspecified lists: the caller checks the flag.
std::vector<uint32_t> similar_patches(const PixelImage& sample, int cell_width, int patch,
    int coherence, int nthreads, const StopFlag* stop);

/// The squared distance between the patch centred at output (x, y) of `padded` (an
/// interleave_padded with pad >= patch / 2 … only patch / 2 is read around it) and the
/// sample patch centred at `source`; stops early (returning something >= bound) once it
/// reaches `bound`.
float patch_distance(const PixelImage& padded, int pad, int x, int y, const PixelImage& sample,
    uint32_t source, int patch, float bound);

/// Recomputes field.distance for `padded` (the output changed), then runs the search
/// passes of `settings`: each pass reads the previous field and writes a new one (no pixel
/// sees another's update of the same pass), so the result does not depend on nthreads.
/// `similar` is similar_patches' table for this patch size (or empty). Only
/// settings.active pixels are searched, and only sources sample.allows() are taken (the
/// field's sources of active pixels must be allowed ones).
void patch_match(const SampleLevel& sample, const PixelImage& padded, int pad,
    const std::vector<uint32_t>& similar, const MatchSettings& settings, PatchField& field);

/// The vote: every output pixel the weighted average of the `patch` x `patch` source
/// patches that overlap it, channel by channel, into `out` (planes of the field's size,
/// sample.pixels.channels of them); `wrap` says along which axes patches overlap the
/// opposite edge. Once `stop` is set (stop.h) the rows not yet started are skipped, leaving
/// `out` unspecified: the caller checks the flag.
void vote(const SampleLevel& sample, const PatchField& field, int patch, PatchVote kind,
    int nthreads, const StopFlag* stop, std::vector<Plane>& out, Wrap wrap = Wrap());

/// Per output pixel, the sample pixel (index y * width + x) of those its overlapping patches
/// voted for that is nearest (over every channel) to `average` (the vote's result); `wrap`
/// and `stop` as for vote().
std::vector<uint32_t> nearest_votes(const SampleLevel& sample, const PatchField& field, int patch,
    const std::vector<Plane>& average, int nthreads, const StopFlag* stop, Wrap wrap = Wrap());

/// The mean and variance of a plane's values.
void plane_moments(const Plane& plane, double& mean, double& variance);

/// `plane` shifted to zero mean and scaled to the mean standard deviation of the `colour`
/// planes (the guidance channel's scale); a constant plane becomes zeros.
void scale_like_colour(Plane& plane, const std::vector<Plane>& colour);

/// The automatic guidance channel of a sample (its colour planes): the distance to the
/// nearest strong edge of its luminance (gradient magnitude in the top fifth), clipped at
/// `feature_size` and scaled to zero mean and the colour channels' mean standard
/// deviation. The same at any `nthreads`; once `stop` is set, throw_if_stopped's throw.
Plane guidance_channel(
    const std::vector<Plane>& colour, int feature_size, int nthreads, const StopFlag* stop);

/// The fraction of a sample of `npixels` pixels that `source` (sample indices) copies.
double used_fraction(const std::vector<uint32_t>& source, size_t npixels);

/// The largest connected region of a width x height output (4-connected, across the edges
/// along the axes that wrap) whose neighbours copy neighbouring pixels of a sample_width x
/// sample_height sample (a verbatim copy), in pixels.
size_t largest_copy(const std::vector<uint32_t>& source, int width, int height, int sample_width,
    int sample_height, bool wrap_x = true, bool wrap_y = true);

} // namespace texsyn::detail
