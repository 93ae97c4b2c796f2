// SPDX-License-Identifier: Apache-2.0
// Iterated nonlinear maps and convolution with a multiscale cascade
// ("iterated nonlinear maps and convolution" sketch): A(i+1) = p(N(A(i))) on a
// lattice, N a small circular convolution, p a pointwise map of [0, 1], a few iterations.
//
// Same conventions as synthesis.h: ImageBufAlgo-style two forms, errors in dst, float in
// and out, bit-identical for a seed whatever nthreads is.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/options.h>
#include <texsyn/run_controls.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// The pointwise maps p of [0, 1] into [0, 1]; r in [0, 4] sets the peak value r/4.
enum class CascadeMap {
    Logistic, ///< r x (1 - x)
    Sine,     ///< r/4 sin(pi x)
    Tent,     ///< r/4 (1 - |2x - 1|)
    Cubic,    ///< r (3 sqrt 3 / 8) x (1 - x^2): peak r/4 at x = 1/sqrt 3
    Curve,    ///< piecewise linear through the `curve` points (r unused)
};

/// The convolution kernels N (at most 7x7; normalised to sum 1).
enum class CascadeKernel {
    Box3,
    Box5,
    Box7, ///< uniform
    Gauss3,
    Gauss5,
    Gauss7, ///< Gaussian, sigma = size / 4
    Dog5,
    Dog7, ///< difference of Gaussians (Mexican hat): 2 G(size/6) - G(size/3)
    Aniso5,
    Aniso7, ///< Gaussian with sigmas size/3 and size/10 along `angle`
    Custom, ///< `weights`: ksize x ksize values, row by row
};

/// How an input image becomes the initial lattice (the paper's (D), texture transfer).
enum class CascadeTransfer {
    Luminance, ///< one lattice, the image's luminance (Rec. 709 weights), clamped to [0, 1]
    Channels,  ///< one lattice per channel, each clamped to [0, 1]
};

/// Options of the cascade. Per-level lists (iterations, map, r, kernel, angle, noise) run
/// coarsest level first (level 0 is the coarsest); levels missing from a list repeat its
/// last value.
struct CascadeOptions : RunControls {
    /// Output size (the finest level); 0x0 = the initial image's size, or 512x512 without one.
    int width = 0;
    int height = 0;
    int levels = 1; ///< cascade levels; level l is the output halved levels-1-l times
    std::vector<int> iterations = { 5 };                    ///< per level
    std::vector<CascadeMap> map = { CascadeMap::Logistic }; ///< per level
    std::vector<float> r = { 3.9f };                        ///< per level
    std::vector<float> curve; ///< map=curve: x0,y0,x1,y1,… with x increasing in [0, 1]
    std::vector<CascadeKernel> kernel = { CascadeKernel::Gauss5 }; ///< per level
    std::vector<float> angle = { 0.0f }; ///< per level, aniso kernels: degrees from x
    int ksize = 3;                       ///< kernel=custom: side (odd, 1..7)
    std::vector<float> weights;          ///< kernel=custom: ksize^2 weights, normalised
    std::vector<float> noise = { 0.0f }; ///< per level > 0: weight of fresh noise mixed in
    float dmin = 1.0f;                   ///< dilation at control value 0
    float dmax = 1.0f;                   ///< dilation at control value 1
    CascadeTransfer transfer = CascadeTransfer::Luminance;
    /// Feature size: the lattice runs at the output's size divided by
    /// scale x (reference ? min(width, height) / reference : 1), at most 4 times the output's
    /// side, and is resampled to the output's size before its last map (so features grow
    /// smoothly, with sharp contours). reference = 0: features are the kernel's size in
    /// output pixels; every preset sets 256, so that its look keeps its proportions at any
    /// size.
    float scale = 1.0f;
    int reference = 0;
    /// A colour ramp: r,g,b triples (scene-linear), evenly spaced stops from value 0 to 1;
    /// empty = the lattice itself, one channel "Y".
    std::vector<float> ramp;

    /// The table behind `--cascade:name=value`, synth:options and the docs.
    static const OptionTable<CascadeOptions>& table();

    /// Checks the options alone (ranges, list lengths, the curve, custom weights). False
    /// with a message.
    bool validate(std::string& error) const;
};

/// The cascade. Level 0 (the coarsest) starts as seeded uniform noise, or as `initial`
/// (resized to that level; see CascadeTransfer) when it is not null; every level then runs
/// its iterations of A <- p(N(A)) with circular convolution, so the output tiles; each
/// later level starts as the previous level upsampled (the (1,4,6,4,1) expand, circular)
/// mixed with fresh noise by its `noise` weight. With `dilation` (a one-channel control
/// image, resized to each level, values clamped to [0, 1]) the kernel's taps are spread by
/// dmin + c (dmax - dmin) pixels at each pixel, sampled bilinearly; dilation 1 everywhere
/// is exactly the undilated operator. With `rotation` (a one-channel control image, values
/// clamped to [0, 1]) the taps are also turned by c turns (c x 360 degrees) at each pixel.
/// The lattice runs at the size `scale` and `reference` give (see CascadeOptions::scale)
/// and its last N(A) is resampled to the output's size (circularly) before the last map.
/// The result is the last level, mapped through `palette` if given (an image, e.g. a
/// texture sample in scene-linear: value v takes the colour of the palette pixel of rank v
/// among its pixels sorted by luminance, so a procedural pattern wears the sample's
/// colours; it replaces `ramp`, e.g. a preset's), else through `ramp` if given.
/// Fails (false, message in dst) on invalid options, an input image with an error or
/// NaN/Inf, a control image with more than one channel, a ramp or palette with
/// transfer=channels of several channels, or an output that would need more memory than
/// the machine has (checked before the input is resized or anything else allocated).
bool cascade_synthesize(OIIO::ImageBuf& dst, const CascadeOptions& opt,
    const OIIO::ImageBuf* initial = nullptr, const OIIO::ImageBuf* dilation = nullptr,
    const OIIO::ImageBuf* rotation = nullptr, const OIIO::ImageBuf* palette = nullptr);
OIIO::ImageBuf cascade_synthesize(const CascadeOptions& opt,
    const OIIO::ImageBuf* initial = nullptr, const OIIO::ImageBuf* dilation = nullptr,
    const OIIO::ImageBuf* rotation = nullptr, const OIIO::ImageBuf* palette = nullptr);

} // namespace texsyn
#pragma GCC visibility pop
