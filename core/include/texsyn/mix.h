// SPDX-License-Identifier: Apache-2.0
// Texture mixtures: Heeger & Bergen 1995 §5, the statistics of several samples combined
// (palette of one and pattern of another, low and high bands, averaged histograms).
//
// Same conventions as every method (synthesis.h): ImageBufAlgo-style two forms, errors in
// dst, scene-linear float in and out, bit-identical for a seed whatever nthreads is.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/options.h>
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/stats.h>
#include <texsyn/subbands.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

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

/// One sample of a mix: an image (scene-linear) or an analysis of one (stats.h; e.g. read
/// from an analysis file), so that `mix_synthesize({ &rust, &marble }, opt)` reads naturally.
struct MixSample {
    MixSample(const OIIO::ImageBuf* sample)
        : image(sample)
    { }
    MixSample(const TextureStatistics* sample)
        : analysis(sample)
    { }
    const OIIO::ImageBuf* image = nullptr;
    const TextureStatistics* analysis = nullptr;
};

/// The statistics of a texture mixture (§5): analyses every image sample with
/// analyze_texture at one common number of scales and combines the tables as the mode
/// says (MixOptions). An analysis among the samples is used as it is: it fixes the number
/// of scales (every analysis must have the same, and agree with opt's pyramid and
/// orientations); the weights mode (one colour basis fitted to every sample's pixels) and
/// flatten=1 need images.
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
bool mix_statistics(const std::vector<MixSample>& samples, const MixOptions& opt,
    TextureStatistics& out, std::string& error);

/// Texture mixture (Heeger & Bergen 1995 §5): match-texture from seeded noise towards
/// mix_statistics(samples, opt). Output: opt.synthesis.width x height (0x0: sample 0's
/// size), the channels of the palette sample (weights: sample 0), tiling seamlessly;
/// synth:method = "mix", synth:options = MixOptions::table() resolved. If `subbands` is
/// not null it receives the synthesis's subbands ("synth.<band>"). Fails as
/// mix_statistics and synthesize_from_statistics do.
bool mix_synthesize(OIIO::ImageBuf& dst, const std::vector<MixSample>& samples,
    const MixOptions& opt, std::vector<NamedImage>* subbands = nullptr);
OIIO::ImageBuf mix_synthesize(const std::vector<MixSample>& samples, const MixOptions& opt,
    std::vector<NamedImage>* subbands = nullptr);

} // namespace texsyn
#pragma GCC visibility pop
