// SPDX-License-Identifier: Apache-2.0
// Sample homogeneity: is a sample stationary enough for pyramid synthesis? Heeger & Bergen
// 1995 §6: "inhomogeneous" samples (a lighting gradient, perspective) give blotchy results,
// because match-texture imposes one histogram on the whole output.
//
// Rules for every function here:
//  - Inputs are PlanarImages (image.h) whose pixels are scene-linear float, colour channels
//    first, then alpha, then extra channels.
//  - Measurements use the luminance: Rec.709 weights (0.2126, 0.7152, 0.0722) of the first
//    three colour channels (the bundled config's scene_linear is linear Rec.709; in another
//    space the weights are an approximation, which is harmless for these relative
//    measures); the mean of the colour channels when there are two; the channel itself
//    when there is one. Alpha and extra channels are not measured.
//  - `nthreads` follows OIIO (0 = OIIO's default). Sums are taken per fixed block of rows
//    and combined in block order, so results are bit-identical at any thread count.
//  - Nothing throws and nothing fails: no memory the size of the image is allocated (the
//    luminance is computed a row at a time), an empty image gives a report with a
//    warning, and flatten_illumination leaves an image it cannot fit unchanged.
//  - Thresholds were calibrated on the bundled samples and the shared texture set, plain
//    and with added lighting gradients; the table is in docs/homogeneity.md.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <texsyn/image.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// Above this peak-to-peak relative amplitude of the fitted illumination the sample is poor.
inline constexpr double homogeneity_max_illumination_amplitude = 0.75;
/// Above this coefficient of variation of the tile means the sample is poor.
inline constexpr double homogeneity_max_local_mean_variation = 0.3;
/// Above this coefficient of variation of the tile contrasts the sample is poor.
inline constexpr double homogeneity_max_local_contrast_variation = 0.4;

/// The methods that copy patches (neighborhood, choosy, patch, fill, tileable) re-tile a
/// lighting ramp as light and dark blocks well below the pyramid's limit: above this
/// amplitude, for a ramp that explains at least homogeneity_min_lighting_share of how the
/// sample's regions differ, the sample is uneven for them (HomogeneityReport::
/// uneven_for_copying).
inline constexpr double homogeneity_max_lighting_for_copying = 0.3;
inline constexpr double homogeneity_min_lighting_share = 0.35;
/// Light scales a region's contrast with its mean, so with the lighting divided out the
/// relative contrast of a lit sample is even: above this variation of it between regions
/// (HomogeneityReport::lit_out_contrast_variation) the differences are the texture's own.
inline constexpr double homogeneity_max_contrast_variation_of_lighting = 0.2;

/// A report's score is below this exactly when one measure exceeds its threshold.
inline constexpr double homogeneity_poor_score = 0.5;

/// The fitted illumination: luminance ≈ sum of coefficients[i] * monomial i of the
/// normalised coordinates u = (2x+1)/width - 1, v = (2y+1)/height - 1 (both in (-1, 1),
/// v pointing down like image rows), monomials 1, u, v, u², uv, v² in that order. The
/// illumination is known up to a constant factor (the texture's mean reflectance).
struct IlluminationFit {
    std::array<double, 6> coefficients {}; ///< all zero = nothing to fit
    /// The polynomial at pixel (x, y) of a width x height image. Can be <= 0 where a
    /// strong fit extrapolates into a corner.
    double at(int x, int y, int width, int height) const;
};

/// What check_homogeneity measured.
struct HomogeneityReport {
    int width = 0, height = 0;

    /// (a) Low-order illumination: least-squares quadratic fit to the luminance.
    IlluminationFit illumination;
    /// (max - min) / mean of the fitted illumination over the sample's pixels: 1.0 for a
    /// multiplicative ramp from 0.5 to 1.5, 0 for a flat fit.
    double illumination_amplitude = 0.0;
    /// Direction in which the fitted illumination increases on average, in degrees
    /// counter-clockwise from +x with y up: 0 = brighter to the right, 90 = to the top.
    double illumination_direction = 0.0;
    /// Share (0..1) of the fitted illumination's range that its planar part explains:
    /// near 1 a ramp, near 0 a vignette (brighter or darker in the middle).
    double illumination_planar_fraction = 0.0;
    /// e.g. "brighter towards the right (0 deg)", "darker towards the edges (vignette)".
    std::string illumination_description;
    /// Share (0..1) of the variance of the means of 8x8 regions of the sample that the
    /// fitted illumination explains: near 1 when regions differ because of the light, near
    /// 0 when they differ because of the texture's own large features (which a quadratic
    /// fit also follows, but cannot explain). 0 if the sample is under 16 px on a side.
    double lighting_share = 0.0;
    /// Coefficient of variation of the relative contrast (std-dev / mean) of the same 8x8
    /// regions once the fitted illumination is divided out: low when only light made
    /// them differ. 0 if the sample is under 16 px on a side.
    double lit_out_contrast_variation = 0.0;
    /// A lighting ramp the copying methods would re-tile (homogeneity_max_lighting_for_
    /// copying): amplitude above the limit, mostly planar (a ramp, not a vignette that
    /// large features mimic), explaining the regions' differences, and leaving their
    /// relative contrast even once divided out (homogeneity_max_contrast_variation_of_
    /// lighting).
    bool uneven_for_copying = false;

    /// (b) Tile statistics of the luminance: square tiles of side max(8, min(w,h) / 4),
    /// as many as fit (4x4 on a square sample), centred; the leftover margin is unused.
    int tiles_x = 0, tiles_y = 0, tile_size = 0;
    /// Coefficient of variation (std-dev / mean) of the tiles' mean luminance.
    double local_mean_variation = 0.0;
    /// Coefficient of variation of the tiles' RMS contrast (std-dev / mean of the tile's
    /// luminance). Relative contrast, so that an illumination change, which (a) and the
    /// local mean already measure, is not counted again: this one sees changes of the
    /// texture itself (smooth here, rough there; scale changes under perspective).
    double local_contrast_variation = 0.0;

    /// (c) 1 = homogeneous. 2^(-b²), b = the largest of the three measures divided by its
    /// threshold (homogeneity_max_*), so score < homogeneity_poor_score (0.5) exactly
    /// when one exceeds its threshold.
    double score = 1.0;
    /// A measure exceeds its threshold: pyramid synthesis will probably look blotchy.
    bool poor = false;
    /// One human-readable line per measure over its threshold (and for an image too small
    /// or empty to measure), saying what to do about it.
    std::vector<std::string> warnings;
};

/// Measures how homogeneous `sample` is (Heeger & Bergen 1995 §6): (a) fits a low-order
/// illumination model, (b) compares mean and contrast across tiles, (c) combines them
/// into a score and `poor` flag with warnings. Images under 16 pixels on a side get no
/// tile measures (a warning says so); an empty image gives score 0, poor, and a warning.
HomogeneityReport check_homogeneity(const PlanarImage& sample, int nthreads = 0);

/// The report as the tool prints it (`texsyn SAMPLE --check`): a first line naming `name`
/// and the size, one line per measure with its limit, then one "warning: …" line per
/// warning; every line ends in a newline.
std::string format_homogeneity_report(const HomogeneityReport& report, const std::string& name);

/// Removes the low-order illumination that check_homogeneity fits: divides every colour
/// channel by the fitted illumination, scaled so that the mean luminance is unchanged.
/// The fit is clamped to at least 1/16 of its mean first, so a fit that extrapolates to
/// zero in a corner multiplies the pixels there by 16 at most. Alpha and extra channels
/// are untouched. An empty image, or one whose mean luminance is not positive, is left
/// unchanged. Used by pyramid synthesis with PyramidOptions::flatten = 1.
void flatten_illumination(PlanarImage& image, int nthreads = 0);

} // namespace texsyn
#pragma GCC visibility pop
