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

#include <texsyn/feature_scale.h>
#include <texsyn/options.h>
#include <texsyn/patch.h>
#include <texsyn/run_controls.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// How a fill's copies meet the kept pixels at the mask's outline.
enum class FillOutline {
    /// Offset smoothly so that they meet them, and one another, without a step (gradient-
    /// domain compositing, like a healing brush): on a soft plate the outline does not show.
    Match,
    /// Exact copies of known pixels, as the source map records them.
    Copy,
};

/// Options of a fill.
struct FillOptions : RunControls {
    /// Gaussian pyramid levels, filled coarse to fine; 0 = from each hole's thickness (at
    /// most three of the largest patches at the coarsest level; at least 3 where the image
    /// is large enough).
    int levels = 0;
    /// Patch sizes (odd), largest first, as PatchOptions::patch; empty = 11 and 7 (smaller
    /// for an image under 33 pixels).
    std::vector<int> patch;
    /// EM iterations per patch size, per level, finest first, as PatchOptions::iterations;
    /// empty = 4 at the finest level, 6 at the next, 8 at the coarser ones.
    std::vector<int> iterations;
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
    FillOutline outline = FillOutline::Match;
    /// 1: the search compares patches with the image's low-order lighting divided out
    /// (flatten_illumination), so that the fill takes texture from the whole plate, not only
    /// from where it is lit alike; the copies are still the image's own pixels (outline=
    /// match then relights them where they land).
    int flatten = 0;

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
/// edge, and (but at the finest level) the filled pixels' histogram matched to the source
/// pixels', so that a wide hole does not wash out. At the end every hole pixel copies,
/// from the image (or sample) as given, all its channels at the pixel its patches voted
/// for; with outline=match (the default) the copies are then offset smoothly so that they
/// meet the kept pixels across the outline and one another across their seams without a
/// step (gradient-domain compositing, compose_region); a mask value m
/// between 0 and 1 blends: (1 - m) x the image + m x the fill. Pixels where the mask is 0
/// are the image's, bit-identical; an empty mask returns the image unchanged.
///
/// `source_map`, if not null (a fill from the image itself, no sample), receives the fill's
/// source map (source_map.h) with a fourth channel "m": every pixel's source (its own
/// position where the mask is 0) and the mask's value, so that apply_source_map fills
/// another map aligned with the image (a material's height, normal…) with the same copies,
/// blended by the mask; without outline=match's offsets, which each map's own pixels set.
///
/// Fails (false, message in dst) on invalid options; an image, mask, exclude or sample that
/// has an error, NaN or Inf; a mask or exclude that is not one channel of the image's size;
/// a sample whose channels differ from the image's; a mask that covers the whole image
/// without a sample; a source map asked of a fill from a sample; or a context (or sample)
/// with no patch of known pixels at some level.
bool texture_fill(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask,
    const FillOptions& opt, const OIIO::ImageBuf* sample = nullptr,
    const OIIO::ImageBuf* exclude = nullptr, FillReport* report = nullptr,
    OIIO::ImageBuf* source_map = nullptr);
OIIO::ImageBuf texture_fill(const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask,
    const FillOptions& opt, const OIIO::ImageBuf* sample = nullptr,
    const OIIO::ImageBuf* exclude = nullptr, FillReport* report = nullptr,
    OIIO::ImageBuf* source_map = nullptr);

/// The axes make_tileable() makes an image tile along.
enum class TileAxes { Both, X, Y };

/// The fill options make_tileable() starts from: FillOptions with outline=copy.
inline FillOptions band_fill_defaults()
{
    FillOptions o;
    o.outline = FillOutline::Copy;
    return o;
}

/// Options of make_tileable().
struct TileableOptions {
    /// The fill of the band (its context is the whole image, so `context` is not used; nor
    /// is its flatten: see `flatten` below). Its outline is copy by default: the band's
    /// mask ramps into the kept pixels, which blends its edges, and copies stay exact.
    FillOptions options = band_fill_defaults();
    /// Width in pixels of the band across each wrap-around seam that is re-synthesized;
    /// 0 = automatic: 3/16 of the image's shorter side, at least two of the largest
    /// patches. At most a third of the shorter side.
    int band = 0;
    /// X: only the left and right edges are made to meet (a strip that repeats sideways,
    /// as trim sheets do), Y: only the top and bottom, Both: both.
    TileAxes axis = TileAxes::Both;
    /// 1: the image's low-order lighting is divided out first (flatten_illumination): a
    /// lit scan cannot tile, its dark side meeting its bright one. Pixels outside the band
    /// are then the flattened image's.
    int flatten = 0;

    /// The table behind `--tileable:name=value`, recipes, synth:options and the docs.
    static const OptionTable<TileableOptions>& table();

    /// Checks the options alone. False with a message.
    bool validate(std::string& error) const;
};

/// What make_tileable() changed.
struct TileableReport {
    int band = 0; ///< the band's width in pixels (the automatic choice if 0)
    /// Fraction of the pixels whose value changed (from the flattened image, with flatten)
    double changed_fraction = 0.0;
    FeatureScale scale; ///< the image's feature scale
    /// The band is narrower than half a feature (scale.size > 2 band): features crossing
    /// the seams are cut short or smeared; a wider band= or a larger scan holds them.
    bool band_too_narrow = false;
};

/// The image made to tile at its own size: the image is rolled by half its size (along
/// opt.axis) so that its wrap-around seams lie in the middle, a band `opt.band` wide along
/// them is filled (texture_fill) from the rest of the image, and the result is rolled back.
/// The band's mask ramps from 0 to 1 over a quarter of its width on each side, so that the
/// fill blends into the kept pixels. Pixels outside the band (a frame away from the
/// image's edges) are the image's (flattened, with opt.flatten), bit-identical; the result
/// has no seam where it wraps around, and carries wrapmodes "periodic" along opt.axis.
///
/// Fails (false, message in dst) as texture_fill() does, and on a band too wide for the
/// image.
bool make_tileable(OIIO::ImageBuf& dst, const OIIO::ImageBuf& image, const TileableOptions& opt,
    TileableReport* report = nullptr);
OIIO::ImageBuf make_tileable(
    const OIIO::ImageBuf& image, const TileableOptions& opt, TileableReport* report = nullptr);

} // namespace texsyn
#pragma GCC visibility pop
