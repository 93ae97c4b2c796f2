// SPDX-License-Identifier: Apache-2.0
// The solid method: Heeger & Bergen 1995 §4, 3-D solid textures from a 2-D sample.
//
// Same conventions as every method (synthesis.h): ImageBufAlgo-style two forms, errors in
// dst, scene-linear float in and out, bit-identical for a seed whatever nthreads is.
// The result is a 3-D ImageBuf (spec.depth voxels deep).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/fft.h>
#include <texsyn/histogram.h>
#include <texsyn/options.h>
#include <texsyn/run_controls.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

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
struct SolidOptions : RunControls {
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
    /// 1: the sample's low-order lighting is divided out before analysis
    /// (flatten_illumination, homogeneity.h; Heeger & Bergen 1995 §6).
    int flatten = 0;

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
/// `dst` receives a 3-D float image of opt.width x opt.height x opt.depth voxels
/// (spec.depth = opt.depth, origin (0,0,0)) with the sample's channels and channel names,
/// scene-linear, colour un-associated from alpha (flagged "oiio:UnassociatedAlpha", as the
/// volume files keep it; volume.h converts it to a PlanarVolume and writes it), and
/// attributes synth:version, synth:method ("solid"), synth:seed, synth:options. Same
/// input rules as every method (a scene-linear sample; deterministic at any opt.nthreads).
/// Fails (false, message in dst) if the options are invalid, the sample has an error,
/// NaN/Inf pixels or is too small for the pyramid (the message gives the largest `scales`
/// it allows), the block's smallest side is under 2^scales, or the block would need more
/// memory than the machine has (checked before allocating; the message gives the amount).
bool solid_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const SolidOptions& opt);
OIIO::ImageBuf solid_synthesize(const OIIO::ImageBuf& sample, const SolidOptions& opt);

} // namespace texsyn
#pragma GCC visibility pop
