// SPDX-License-Identifier: Apache-2.0
// Feature scale: how large a sample's features are, in pixels. The copying methods (patch,
// fill, tileable, material sets) choose their pyramid levels, patch sizes and iterations
// from it, as Kaspar et al. 2015 ("Self Tuning Texture Optimization") choose theirs from a
// texel size: the coarsest level should shrink a feature to about one patch.
//
// Rules for every function here:
//  - The sample is a PlanarImage of scene-linear float pixels (image.h). What is measured is
//    its luminance (homogeneity.h's weights), encoded with a 1/2.2 power so that dark and
//    light structure weigh alike, after the sample's low-order illumination is divided out
//    (flatten_illumination): a lighting gradient is not a feature.
//  - A sample larger than 1024 pixels on its shorter side is measured on a copy reduced by
//    powers of two (Gaussian pyramid) and its figures scaled back, so the cost is bounded.
//  - Every figure is covariant with scale: the sample resized by k gives k times each
//    figure, up to what resampling adds or removes near the pixel size.
//  - Deterministic; nothing throws. An empty, single-pixel or constant sample gives a scale
//    with size 1 and no periods.
#pragma once

#include <string>

#include <texsyn/image.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// What estimate_feature_scale() measured.
struct FeatureScale {
    /// The repeat of the pattern along x and along y, in pixels: the shortest shift at which
    /// the autocorrelation peaks again as high as its strongest peak (within 80 %), with a
    /// rise of at least 0.2 above the low before it; 0 = no repeat along that axis (a
    /// stochastic texture). A checkerboard of 16-pixel squares repeats every 32; a running
    /// brick bond every brick along x and every two courses along y.
    double period_x = 0.0, period_y = 0.0;
    /// The normalised autocorrelation at the stronger of the two periods (0..1; 0 = none).
    double period_strength = 0.0;
    /// The largest wavelength, in pixels, at which the luminance has at least half the
    /// energy per octave of its strongest octave (a windowed power spectrum summed over
    /// octave-wide rings): the size of the largest structures that carry real contrast —
    /// blobs, stones, leaves, folds — whatever the fine grain on them. At most half the
    /// sample's shorter side… measured on bands up to the whole side; the size below is
    /// capped.
    double spectral_size = 0.0;
    /// The finest detail, in pixels: the shortest wavelength whose octave holds a tenth of
    /// the strongest octave's energy. About 2 for a sharp photograph; a sample enlarged k
    /// times has none finer than about 2k (a soft plate).
    double finest_size = 0.0;
    /// The characteristic feature size: the larger period if the pattern repeats, else the
    /// spectral size; at least 1, at most half the sample's shorter side.
    double size = 1.0;

    /// Whether the pattern repeats along some axis.
    bool periodic() const { return period_x > 0.0 || period_y > 0.0; }
};

/// Measures the feature scale of `sample` (its colour channels; alpha and extra channels are
/// not measured). `nthreads` follows OIIO (0 = OIIO's default) and never changes the result.
FeatureScale estimate_feature_scale(const PlanarImage& sample, int nthreads = 0);

/// "feature size 42 px (repeats every 42 x 18 px)" / "feature size 12 px": the scale as -v
/// prints it.
std::string describe_feature_scale(const FeatureScale& scale);

} // namespace texsyn
#pragma GCC visibility pop
