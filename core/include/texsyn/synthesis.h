// SPDX-License-Identifier: Apache-2.0
// Texture synthesis entry points, in the ImageBufAlgo style (DESIGN.md "API conventions").
//
// Rules for every function here:
//  - Two forms: `bool f(ImageBuf& dst, …)` does the work; `ImageBuf f(…)` wraps it and
//    returns an ImageBuf whose has_error() is true on failure. Errors go to
//    dst.errorfmt(); nothing throws across this API and nothing exits.
//  - The sample is read as float (any pixel type, any channel count 1..n; the channel
//    named by spec.alpha_channel is alpha). Its pixels must already be scene-linear:
//    ColorConfig::convert (color.h) does that; the `texsyn` tool does it for you.
//  - The result is a float image with the sample's channels and channel names, its
//    pixels scene-linear, origin (0,0), carrying synth:version, synth:method, synth:seed
//    and synth:options metadata. Colour is associated with alpha as in the sample: a
//    sample flagged "oiio:UnassociatedAlpha" gives an un-associated result, so flagged.
//  - Deterministic: a seed gives bit-identical output whatever opt.nthreads is.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/fft.h>
#include <texsyn/histogram.h>
#include <texsyn/image.h>
#include <texsyn/options.h>
#include <texsyn/pyramid.h>
#include <texsyn/stats.h>
#include <texsyn/volume.h>

namespace texsyn {

/// Options of the pyramid method. Defaults are Heeger & Bergen's.
struct PyramidOptions {
    int width = 0; ///< output size; 0x0 = the sample's size
    int height = 0;
    int iterations = 5; ///< §3.3: "about 5 iterations"
    PyramidKind pyramid = PyramidKind::Steerable;
    int scales = 0;       ///< 0 = min(max_pyramid_scales(sample), (output)), at least 1
    int orientations = 4; ///< steerable bands per scale, 1..8
    HistogramMode histogram = HistogramMode::Exact;
    FftBackend fft = FftBackend::Kiss;
    /// §6 "a slider for each parameter": contrast gain of each scale's bands (s0 finest;
    /// the high-pass residual follows s0), applied to the sample's band statistics.
    /// Empty = all 1; missing trailing scales are 1.
    std::vector<float> gain;
    /// Orientation-energy balance of each scale, in [-1, 1] (steerable only): band k of K
    /// is scaled by 1 + b cos(2 pi k / K), so b > 0 strengthens orientation 0 (vertical
    /// structure, horizontal frequency) against orientation K/2, b < 0 the opposite.
    std::vector<float> balance;
    /// 1: divide the sample by its fitted low-order illumination before analysis
    /// (flatten_illumination, homogeneity.h; Heeger & Bergen 1995 §6). Not the paper's: 0.
    int flatten = 0;
    uint64_t seed = 0; ///< set by the tool's --seed, not a `:name=` option
    int nthreads = 0;  ///< 0 = OIIO's default; never changes the result
    /// Called with the fraction done (0..1) after each iteration of each channel, from the
    /// calling thread; may be empty. Not an option: it never changes the result.
    std::function<void(float)> progress;

    /// The table behind `--pyramid:name=value`, recipes, synth:options and the docs.
    static const OptionTable<PyramidOptions>& table();

    /// Checks the options alone (ranges, backend availability). False with a message.
    bool validate(std::string& error) const;
};

/// A named multi-channel image: one subband of one pyramid (for --subbands output).
struct NamedImage {
    std::string name;  ///< e.g. "sample.s2.o1", "synth.highpass", "synth.L3"
    PlanarImage image; ///< channels pc0, pc1, … (decorrelated colour) plus A if alpha
};

/// Heeger & Bergen's analysis of `sample` (§3.3, §3.5): PCA colour transform (or
/// `basis` if not null, so several samples can share one), then per component its
/// histogram and the histograms of its subbands (steerable: of the periodic component;
/// laplacian: reflected edges, §3.4). Uses opt.pyramid, opt.orientations and opt.scales
/// (0 = the most that keeps the coarsest band of the sample and of an opt.width x
/// opt.height output >= 8 px). If `subbands` is not null it receives the sample's
/// subbands ("sample.<band>"). Fails (false, `error`) on invalid options, NaN/Inf
/// pixels, a sample too small for the pyramid, or a basis with the wrong channel count.
bool analyze_texture(const OIIO::ImageBuf& sample, const PyramidOptions& opt,
    TextureStatistics& stats, std::string& error, const ColorTransform* basis = nullptr,
    std::vector<NamedImage>* subbands = nullptr);

/// The synthesis half of pyramid_synthesize: match-texture towards `stats` (opt.gain and
/// opt.balance applied to its band statistics). opt.pyramid, orientations and scales
/// must agree with the analysis (scales 0 = the analysis's). Starts from seeded noise, or
/// from `start` if not null (texture transfer, §5: the image's layout, the statistics of
/// `stats`; same channel count, output size = its size). Writes subbands "synth.<band>"
/// if `subbands` is not null. Same result conventions as pyramid_synthesize.
bool synthesize_from_statistics(OIIO::ImageBuf& dst, const TextureStatistics& stats,
    const PyramidOptions& opt, const OIIO::ImageBuf* start = nullptr,
    std::vector<NamedImage>* subbands = nullptr);

/// Bytes of memory a synthesis of this size needs (the estimate the size check uses).
size_t pyramid_memory_estimate(int width, int height, int nchannels, const PyramidOptions& opt);

/// Heeger & Bergen 1995 §3.3 match-texture with §3.4 edge handling and §3.5 colour.
/// Decorrelates the sample's colour channels (PCA), analyses each component (steerable
/// or Laplacian pyramid of the sample's periodic component; exact or 256-bin histograms),
/// starts from seeded uniform noise, and iterates `iterations` times: build pyramid, match
/// every subband, collapse, match the image histogram. Alpha is synthesized as its own
/// channel. After undoing the decorrelation, each channel is histogram-matched to the
/// sample once more. Output: opt.width x opt.height (any size, larger or smaller than the
/// sample), tiling seamlessly (circular synthesis).
/// Fails if the options are invalid, the sample has an error, NaN/Inf pixels, or is too
/// small for the pyramid (message says the largest `scales` it allows), or if the output
/// would need more memory than the machine has (message gives the amount).
/// If `subbands` is not null it receives the sample's and the final synthesis's subbands
/// (names "sample.<band>" and "synth.<band>").
bool pyramid_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands = nullptr);
OIIO::ImageBuf pyramid_synthesize(const OIIO::ImageBuf& sample, const PyramidOptions& opt,
    std::vector<NamedImage>* subbands = nullptr);

/// The pyramids of the solid method (Heeger & Bergen 1995 §4).
enum class SolidPyramid {
    /// 2-D Laplacian and steerable analysis; 3-D Laplacian synthesis plus steerable
    /// pyramids of every xy, xz and yz slice, the four solids averaged (the paper's better
    /// looking variant, the default).
    Combined,
    /// 2-D Laplacian analysis, 3-D Laplacian synthesis.
    Laplacian,
};

/// "combined" or "laplacian".
const char* solid_pyramid_name(SolidPyramid kind);

/// Options of the solid method. Defaults are Heeger & Bergen's.
struct SolidOptions {
    int width = 0; ///< block size; 0x0x0 = the sample's width x height x the smaller of them
    int height = 0;
    int depth = 0;
    int iterations = 5; ///< §3.3: "about 5 iterations"
    SolidPyramid pyramid = SolidPyramid::Combined;
    int scales = 0;       ///< 0 = the most that keeps the coarsest band of the sample and of the
                          ///< block's smallest side >= 8 px, at least 1
    int orientations = 4; ///< steerable bands per scale, 1..8 (combined only)
    HistogramMode histogram = HistogramMode::Exact;
    FftBackend fft = FftBackend::Kiss;
    uint64_t seed = 0; ///< set by the tool's --seed, not a `:name=` option
    int nthreads = 0;  ///< 0 = OIIO's default; never changes the result
    /// Called with the fraction done (0..1) after each iteration of each channel, from the
    /// calling thread; may be empty. Not an option: it never changes the result.
    std::function<void(float)> progress;

    /// The table behind `--solid:name=value`, synth:options and the docs.
    static const OptionTable<SolidOptions>& table();

    /// Checks the options alone (ranges, backend availability). False with a message.
    bool validate(std::string& error) const;
};

/// Bytes of memory a solid synthesis of this size needs (the estimate the size check uses).
size_t solid_memory_estimate(int width, int height, int depth, int nchannels);

/// Heeger & Bergen 1995 §4 solid texture: a 3-D block whose slices along x, y and z look
/// like the 2-D `sample`. Analysis as pyramid_synthesize's (PCA colour decorrelation, §3.5;
/// per component its histogram and its 2-D Laplacian subbands' histograms, and for
/// `combined` its steerable subbands' too, with one colour basis and one `scales`). Per
/// component: seeded uniform noise (stream = channel, index = voxel index), its histogram
/// matched, then `iterations` times: the 3-D Laplacian pyramid (circular) with every band
/// matched to the sample's 2-D Laplacian band; for `combined` also every xy, xz and yz
/// slice through a 2-D steerable pyramid with its oriented bands matched to the sample's
/// steerable bands, and the four solids averaged; then the histogram matched again. (The
/// paper matches the slices' high-pass and low-pass residuals too; texsyn leaves them to
/// the 3-D Laplacian pyramid, because matching them slice by slice streaks the block along
/// the axes: docs/solid.md.) Alpha is
/// synthesized as its own channel. After undoing the decorrelation each channel is
/// matched to the sample's once more. The block tiles seamlessly along all three axes.
///
/// `dst` receives opt.width x opt.height x opt.depth voxels with the sample's channels and
/// channel names, scene-linear float, colour un-associated from alpha, and attributes
/// synth:version, synth:method ("solid"), synth:seed, synth:options. Same input rules as
/// the functions above (a scene-linear sample; deterministic at any opt.nthreads). Fails
/// (false, `error`; `dst` untouched) if the options are invalid, the sample has an error,
/// NaN/Inf pixels or is too small for the pyramid (the message gives the largest `scales`
/// it allows), the block's smallest side is under 2^scales, or the block would need more
/// memory than the machine has (checked before allocating; the message gives the amount).
bool solid_synthesize(
    PlanarVolume& dst, const OIIO::ImageBuf& sample, const SolidOptions& opt, std::string& error);

/// Options of texture mixtures (Heeger & Bergen 1995 §5). Exactly one mode:
///  - palette=I:pattern=J — the palette (colour transform, pixel and channel histograms)
///    of sample I, the pattern (subband histograms, analysed in I's colour basis) of J;
///  - split=S — two samples: scales >= S and the low-pass from sample 0 ("low bands"), the
///    high-pass residual and scales < S from sample 1 ("high bands"; Laplacian: levels);
///    colour from sample `palette` (default 0);
///  - weights=W0,W1,… — one sample per weight (>= 0, normalised to sum 1): every histogram
///    is the weighted Wasserstein barycentre of the samples' (in one colour basis, the PCA
///    of the weighted mixture of their colours).
struct MixOptions {
    /// The synthesis settings, as for the pyramid method: size (0x0 = the first sample's),
    /// iterations, pyramid, scales (0 = the most every sample and the output allow),
    /// orientations, histogram, fft, gain, balance, and the seed, threads and progress.
    PyramidOptions synthesis;
    std::optional<int> palette; ///< the sample giving the colour
    std::optional<int> pattern; ///< the sample giving the subband statistics
    std::optional<int> split;   ///< the scale where low and high bands meet, >= 1
    std::vector<float> weights; ///< one per sample; empty = not this mode

    /// How many samples the mix takes: weights.size() if weights are given, else 2.
    int nsamples() const { return weights.empty() ? 2 : int(weights.size()); }

    /// The table behind `--mix:name=value` and synth:options: the PyramidOptions table
    /// plus palette, pattern, split (each an index or "none") and weights ("none" = empty).
    static const OptionTable<MixOptions>& table();

    /// Checks the options alone: synthesis.validate(), exactly one mode, indices below
    /// nsamples(), pattern with palette, palette with pattern or split, palette != pattern,
    /// split <= scales if scales is given, weights with a positive sum. False with a message
    /// naming the option.
    bool validate(std::string& error) const;
};

/// The statistics of a texture mixture (§5): analyses every sample with analyze_texture
/// at one common number of scales and combines the tables as the mode says (MixOptions).
/// palette/pattern and split: each sample in its own colour basis, so that every component
/// has unit variance and one sample's bands agree in scale with another's pixel histograms;
/// components are paired by rank (pc0 with pc0: the strongest colour direction of the
/// pattern becomes the palette's strongest). A component that is constant in the sample
/// that should give its bands (no pattern to take there, e.g. the chroma of a grey sample)
/// keeps the palette's own bands. weights: every sample in one basis, the PCA of the
/// weighted mixture of their colour distributions, so the tables averaged are in the same
/// units; a constant component counts as a one-value distribution. The result's size is
/// sample 0's (the default output size); its channel names and alpha are the palette
/// sample's (weights: sample 0's). Requires samples.size() == opt.nsamples(), every
/// sample at least 16x16 with finite pixels and the same channels (count and alpha
/// position) as sample 0; sizes may differ. Fails (false, `error` names the sample by its
/// index) otherwise, if scales= is more than a sample allows, or if split= is more than the
/// common number of scales.
bool mix_statistics(const std::vector<const OIIO::ImageBuf*>& samples, const MixOptions& opt,
    TextureStatistics& out, std::string& error);

/// Texture mixture (Heeger & Bergen 1995 §5): match-texture from seeded noise towards
/// mix_statistics(samples, opt). Output: opt.synthesis.width x height (0x0: sample 0's
/// size), the channels of the palette sample (weights: sample 0), tiling seamlessly;
/// synth:method = "mix", synth:options = MixOptions::table() resolved. If `subbands` is
/// not null it receives the synthesis's subbands ("synth.<band>"). Fails as
/// mix_statistics and synthesize_from_statistics do.
bool mix_synthesize(OIIO::ImageBuf& dst, const std::vector<const OIIO::ImageBuf*>& samples,
    const MixOptions& opt, std::vector<NamedImage>* subbands = nullptr);
OIIO::ImageBuf mix_synthesize(const std::vector<const OIIO::ImageBuf*>& samples,
    const MixOptions& opt, std::vector<NamedImage>* subbands = nullptr);

/// Checks options for transfer_synthesize: opt.validate(), and no size (the image gives
/// the output's size). False with a message.
bool validate_transfer_options(const PyramidOptions& opt, std::string& error);

/// Texture transfer (§5, "apply match-texture to a second image rather than noise"):
/// analyses `sample` (scales 0 = the most the sample and `image` allow) and runs
/// match-texture starting from `image` decorrelated in the sample's colour basis, so the
/// result keeps the image's layout and takes the sample's statistics. Output: the image's
/// size, the sample's channels; synth:method = "transfer". The image need not tile, so
/// neither does the result. `subbands` as in pyramid_synthesize. Fails if the options
/// do not validate_transfer_options, the image has a different channel count from the
/// sample, or as pyramid_synthesize does.
bool transfer_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const OIIO::ImageBuf& image, const PyramidOptions& opt,
    std::vector<NamedImage>* subbands = nullptr);
OIIO::ImageBuf transfer_synthesize(const OIIO::ImageBuf& sample, const OIIO::ImageBuf& image,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands = nullptr);

/// texsyn's version string, e.g. "0.1.0".
const char* version();

} // namespace texsyn
