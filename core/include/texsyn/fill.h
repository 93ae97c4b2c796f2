// SPDX-License-Identifier: Apache-2.0
// Fill: the masked part of an image (a tracking marker, a rig, a logo on a wall) replaced
// by texture synthesized from the rest of it, or from another sample. Texture optimization
// with the known pixels held fixed (Wexler, Shechtman & Irani 2007, "Space-Time Completion
// of Video"; Kwatra et al. 2005), on the patch method's PatchMatch search and vote.
//
// Same conventions as synthesis.h: ImageBufAlgo-style two forms, errors in dst, scene-linear
// float in and out, bit-identical for a seed whatever nthreads is.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/options.h>
#include <texsyn/patch.h>
#include <texsyn/stop.h>

namespace texsyn {

/// Options of a fill.
struct FillOptions {
    /// Gaussian pyramid levels, filled coarse to fine; 0 = from each hole's thickness (at
    /// most three of the largest patches at the coarsest level; at least 3 where the image
    /// is large enough).
    int levels = 0;
    /// Patch sizes (odd), largest first, as PatchOptions::patch.
    std::vector<int> patch = { 11, 7 };
    /// EM iterations per patch size, per level, finest first, as PatchOptions::iterations.
    std::vector<int> iterations = { 4, 6, 8 };
    /// Pixels around each hole's bounding box that patches come from; 0 = automatic (at
    /// least three of the largest patches at the coarsest level, and half the hole's larger
    /// side). Ignored with a separate sample, which gives every patch.
    int context = 0;
    /// The spatial-uniformity penalty, as PatchOptions::repetition.
    float repetition = 0.5f;
    /// Weight of the guidance channel, as PatchOptions::guidance: the distance to the
    /// nearest strong edge, filled with the colours so that patches agree on where mortar
    /// lines, joints and outlines run; 0 = none.
    float guidance = 4.0f;
    /// k of k-coherence, as PatchOptions::coherence.
    int coherence = 2;
    PatchVote vote = PatchVote::Robust;
    uint64_t seed = 0; ///< set by the tool's --seed, not a `:name=` option
    int nthreads = 0;  ///< 0 = OIIO's default; never changes the result
    /// Called with the fraction done (0..1) from the calling thread; may be empty.
    std::function<void(float)> progress;
    /// Set from any thread to stop the run (stop.h); may be null. Not an option.
    const StopFlag* stop = nullptr;

    /// The table behind `--fill:name=value`, recipes, synth:options and the docs.
    static const OptionTable<FillOptions>& table();

    /// Checks the options alone (ranges, odd sizes, list order). False with a message.
    bool validate(std::string& error) const;

    /// EM iterations at level `level` (0 finest).
    int iterations_at(int level) const;
};

/// What a fill did (the tool prints it with -v).
struct FillReport {
    int holes = 0;          ///< separate regions filled (holes closer than a patch are one)
    size_t filled = 0;      ///< pixels replaced (mask > 0)
    int levels = 0;         ///< levels of the largest region
    size_t work_pixels = 0; ///< pixels of every region's working crop, summed
};

/// Fills the pixels of `image` where `mask` (one channel, image's size; read as its numbers)
/// is above 0 with texture from the pixels where it is 0, or from `sample` if not null.
///
/// Each region of the mask (holes closer than the largest patch merge) is filled on its own
/// crop: the hole's bounding box and opt.context pixels around it, so the cost follows the
/// holes, not the image. Coarse to fine, the hole starts from a push-pull interpolation and
/// is refined by EM iterations: a PatchMatch search, for every patch over the hole, among
/// the patches of known pixels (none touching `exclude` > 0, if given, nor the image's
/// edge), then a vote in which only hole pixels change, so patches agree across the mask's
/// edge. At the end every hole pixel copies, from the image (or sample) as given, all its
/// channels at the pixel its patches voted for; a mask value m between 0 and 1 blends:
/// (1 - m) x the image + m x the copy. Pixels where the mask is 0 are the image's,
/// bit-identical; an empty mask returns the image unchanged.
///
/// Fails (false, message in dst) on invalid options; an image, mask, exclude or sample that
/// has an error, NaN or Inf; a mask or exclude that is not one channel of the image's size;
/// a sample whose channels differ from the image's; a mask that covers the whole image
/// without a sample; or a context (or sample) with no patch of known pixels at some level.
bool texture_fill(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask,
    const FillOptions& opt, const OIIO::ImageBuf* sample = nullptr,
    const OIIO::ImageBuf* exclude = nullptr, FillReport* report = nullptr);
OIIO::ImageBuf texture_fill(const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask,
    const FillOptions& opt, const OIIO::ImageBuf* sample = nullptr,
    const OIIO::ImageBuf* exclude = nullptr, FillReport* report = nullptr);

/// Options of make_tileable().
struct TileableOptions {
    /// The fill of the band (its context is the whole image, so `context` is not used).
    FillOptions options;
    /// Width in pixels of the band across each wrap-around seam that is re-synthesized;
    /// 0 = automatic: 3/16 of the image's shorter side, at least two of the largest
    /// patches. At most a third of the shorter side.
    int band = 0;

    /// The table behind `--tileable:name=value`, recipes, synth:options and the docs.
    static const OptionTable<TileableOptions>& table();

    /// Checks the options alone. False with a message.
    bool validate(std::string& error) const;
};

/// What make_tileable() changed.
struct TileableReport {
    int band = 0;                  ///< the band's width in pixels (the automatic choice if 0)
    double changed_fraction = 0.0; ///< fraction of the pixels whose value changed
};

/// The image made to tile at its own size: the image is rolled by half its size so that
/// its wrap-around seams cross in the middle, a band `opt.band` wide along them is filled
/// (texture_fill) from the rest of the image, and the result is rolled back. Pixels outside
/// the band (a frame away from the image's edges) are the image's, bit-identical; the result
/// has no seam where it wraps around, and carries wrapmodes "periodic,periodic".
///
/// Fails (false, message in dst) as texture_fill() does, and on a band too wide for the
/// image.
bool make_tileable(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const TileableOptions& opt,
    TileableReport* report = nullptr);
OIIO::ImageBuf make_tileable(
    const OIIO::ImageBuf& image, const TileableOptions& opt, TileableReport* report = nullptr);

} // namespace texsyn
