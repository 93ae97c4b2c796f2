// SPDX-License-Identifier: Apache-2.0
// The pyramid method: Heeger & Bergen 1995 "Pyramid-Based Texture Analysis/Synthesis"
// (§3: match-texture with steerable or Laplacian pyramids, §3.5 PCA colour, §6 sliders),
// and its two halves, analysis and synthesis from statistics (analysis files, stats.h).
//
// Same conventions as every method (synthesis.h): ImageBufAlgo-style two forms, errors in
// dst, scene-linear float in and out, bit-identical for a seed whatever nthreads is.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/fft.h>
#include <texsyn/histogram.h>
#include <texsyn/options.h>
#include <texsyn/pyramid.h>
#include <texsyn/run_controls.h>
#include <texsyn/stats.h>
#include <texsyn/subbands.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// Options of the pyramid method. Defaults are Heeger & Bergen's.
struct PyramidOptions : RunControls {
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

    /// The table behind `--pyramid:name=value`, recipes, synth:options and the docs.
    static const OptionTable<PyramidOptions>& table();

    /// Checks the options alone (ranges, backend availability). False with a message.
    bool validate(std::string& error) const;
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

/// Bytes of memory the analysis of a `width` x `height` sample needs (analyze_texture
/// refuses a sample whose estimate exceeds memory_available(), before allocating).
size_t pyramid_analysis_memory_estimate(
    int width, int height, int nchannels, const PyramidOptions& opt);

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

} // namespace texsyn
#pragma GCC visibility pop
