// SPDX-License-Identifier: Apache-2.0
// The patch method: texture optimization (Kwatra et al. 2005, "Texture Optimization for
// Example-based Synthesis") with PatchMatch nearest-neighbour fields (Barnes et al. 2009)
// and the additions of Kaspar et al. 2015 ("Self Tuning Texture Optimization"): histogram
// matching inside the loop, a spatial-uniformity penalty against repetition, and an
// automatic guidance channel. For structured textures: bricks, tiles, weave, wood, flowers.
//
// Same conventions as synthesis.h: ImageBufAlgo-style two forms, errors in dst, scene-linear
// float in and out, bit-identical for a seed whatever nthreads is.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/feature_scale.h>
#include <texsyn/options.h>
#include <texsyn/run_controls.h>
#include <texsyn/source_map.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// How the overlapping source patches of a pixel are averaged (the "vote").
enum class PatchVote {
    /// Each patch weighted by its match: (distance per value + e)^-0.6, Kwatra et al.'s
    /// robust (IRLS, r = 0.8) weights: a poorly matching patch has little say. Sharper.
    Robust,
    /// The plain mean of the overlapping patches (the L2 optimum).
    Mean,
};

/// Which axes the patch method's output wraps around along: it tiles along them.
enum class PatchWrap { Both, X, Y, None };

/// Options of the patch method. Left automatic (levels 0, patch and iterations empty), the
/// schedule tunes itself to the sample (feature_scale.h): the result's synth:options
/// records what was chosen.
struct PatchOptions : RunControls {
    int width = 0; ///< output size; 0x0 = the sample's size
    int height = 0;
    /// Gaussian pyramid levels, synthesized coarse to fine; 0 = chosen from the sample's
    /// feature scale and size: a feature at most three quarters of the largest patch at the
    /// coarsest level, whose sample keeps at least 16 pixels and (unless the pattern
    /// repeats) an eighth of the sample's side; at least 3 where they fit.
    int levels = 0;
    /// Patch sizes (odd), largest first: every level but the finest optimizes with each in
    /// turn; the finest only refines with the last (smallest). Empty = 11 and 7 (smaller
    /// for a sample or output under 33 pixels).
    std::vector<int> patch;
    /// EM iterations (search, then vote) per patch size, per level, finest first; one value
    /// = every level; coarser levels missing from the list repeat the last. Empty = 1 at
    /// the finest level, 3 at the next, 8 at the coarser ones.
    std::vector<int> iterations;
    /// Strength of the spatial-uniformity penalty (Kaspar et al. §4.3): a source patch used
    /// more often than an even use of the sample would use it costs repetition x its excess
    /// use x the sample's patch variance. 0 = the plain method.
    float repetition = 0.5f;
    /// Weight of the automatic guidance channel (Kaspar et al. §4.2: the distance transform
    /// of the sample's edge mask, synthesized with the colours so that patches agree on
    /// where features lie beyond their own extent); 0 = none.
    float guidance = 1.0f;
    /// k of k-coherence: each propagated candidate also brings the k - 1 sample patches
    /// most similar to it (Tong et al. 2002); 1 = PatchMatch's propagation alone.
    int coherence = 2;
    PatchVote vote = PatchVote::Robust;
    /// 1: patches may also come from the sample rotated and mirrored (its 8 rotations and
    /// mirror images if square, else its 3 mirror images besides itself), for samples
    /// without a direction; 0: the sample's orientation is kept (courses stay horizontal).
    int isotropic = 0;
    /// 1: the sample's low-order lighting is divided out first (flatten_illumination,
    /// homogeneity.h), so that a lit sample is not re-tiled as light and dark blocks; the
    /// result copies the flattened sample's pixels.
    int flatten = 0;
    /// The axes the result tiles along (trim sheets tile along one): along an axis that
    /// does not wrap, the result has edges like a photograph's.
    PatchWrap wrap = PatchWrap::Both;
    /// The result's features this many times as large as the sample's, 0.25..4: the sample
    /// is resampled by it first (its source map then refers to the resampled sample).
    float scale = 1.0f;

    /// The table behind `--patch:name=value`, recipes, synth:options and the docs.
    static const OptionTable<PatchOptions>& table();

    /// Checks the options alone (ranges, odd sizes, list lengths). False with a message.
    bool validate(std::string& error) const;

    /// EM iterations at level `level` (0 finest); with iterations empty, the automatic
    /// count for `levels` levels (levels 0: as if `level` were the coarsest).
    int iterations_at(int level) const;
};

/// What a synthesis measured of its result (the tool prints it with -v).
struct PatchReport {
    int levels = 0;             ///< levels synthesized (the automatic choice if levels=0)
    FeatureScale scale;         ///< the sample's feature scale (the automatic schedule's input)
    std::string schedule;       ///< how the levels were chosen, one phrase
    double used_fraction = 0.0; ///< fraction of the sample's pixels the result copies
    size_t largest_copy = 0;    ///< pixels of the largest region copied verbatim
    double largest_copy_fraction = 0.0; ///< largest_copy / the sample's pixels
};

/// Bytes of memory a synthesis needs (the estimate the size check uses).
size_t patch_memory_estimate(int sample_width, int sample_height, int nchannels, int out_width,
    int out_height, const PatchOptions& opt);

/// Texture optimization, coarse to fine.
///
/// Gaussian pyramids (the (1,4,6,4,1)/16 kernel) of the sample (reflected) and the output,
/// `levels` levels. Every output pixel is the centre of a patch, toroidal along the axes
/// opt.wrap names (so the output tiles along them), with a source: the centre of a patch
/// inside the sample at the same level. The coarsest level starts from seeded random
/// sources; each finer level from its coarser level's sources, doubled, voted with its
/// own pixels. Each EM iteration searches — PatchMatch passes that read the previous field
/// and write a new one (propagation with k-coherence candidates, then a random search
/// around the best at halving radii; at the coarsest level jump-flood propagation at
/// steps 4, 2, 1 every iteration), so the field does not depend on the schedule — and
/// then votes: each pixel the (robust) average of the overlapping source patches' pixels,
/// whose histogram is matched to the sample level's, channel by channel. The result is a copy: each
/// pixel takes the sample pixel, of those its overlapping patches voted for, nearest the average,
/// so every output pixel is a sample pixel and the source map reproduces it. All channels (colour,
/// alpha, extra channels) are part of the patches and copied; `guide` (one channel, the sample's
/// size), if given, replaces the automatic guidance channel.
///
/// `dst` receives opt.width x opt.height with the sample's channels; `source_map`, if not
/// null, the source map (source_map.h); `report`, if not null, what the result copies.
/// Fails (false, message in dst) on invalid options, a sample with an error or NaN/Inf
/// pixels, a sample or output smaller than the patch at any level, a guide of the wrong
/// size or channels, or an output that would need more memory than the machine has
/// (checked before allocating).
bool patch_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const PatchOptions& opt,
    OIIO::ImageBuf* source_map = nullptr, const OIIO::ImageBuf* guide = nullptr,
    PatchReport* report = nullptr);
OIIO::ImageBuf patch_synthesize(const OIIO::ImageBuf& sample, const PatchOptions& opt,
    OIIO::ImageBuf* source_map = nullptr, const OIIO::ImageBuf* guide = nullptr,
    PatchReport* report = nullptr);

} // namespace texsyn
#pragma GCC visibility pop
