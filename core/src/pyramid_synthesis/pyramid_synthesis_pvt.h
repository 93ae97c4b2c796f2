// SPDX-License-Identifier: Apache-2.0
// Helpers of the pyramid method shared by its analysis and synthesis halves and by the
// methods built on them (solid, mix, transfer).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <texsyn/pyramid_synthesis.h>

#include "methods/method_helpers_pvt.h"

namespace texsyn::detail {

/// The pyramid of opt.pyramid for one image size; nullptr and `error` on failure.
std::unique_ptr<Pyramid> make_pyramid(const PyramidOptions& opt, int width, int height, int scales,
    Boundary boundary, std::string& error);

/// All values equal.
bool is_constant(const Plane& p);

/// Mean in double precision, fixed order.
float plane_mean(const Plane& p);

/// Collects band `b` of every component into one NamedImage "<prefix>.<band name>".
void append_subbands(const std::string& prefix, const std::vector<std::string>& band_names,
    const std::vector<std::vector<Plane>>& per_component,
    const std::vector<std::string>& component_names, std::vector<NamedImage>& out);

/// "flatten=1 : needs a sample, and <name> is an analysis (…)": an analysis keeps no pixels
/// to divide a lighting gradient out of.
std::string flatten_of_analysis_error(const std::string& name);

/// False (with "<option>=… : differs from the analysis (…)") unless opt's pyramid, scales
/// (0 = any) and orientations agree with the analysis `stats`, and its gain and balance
/// lists fit its scales.
bool check_against_analysis(
    const TextureStatistics& stats, const PyramidOptions& opt, std::string& error);

/// Where band `band` of a pyramid with `nbands` bands sits (band order as in pyramid.h):
/// its scale (0 finest; -1 for the steerable high-pass residual, the number of scales for
/// the low-pass) and orientation (0 for all but the steerable oriented bands).
struct BandPosition {
    int scale = 0;
    int orientation = 0;
};
BandPosition band_position(PyramidKind kind, int orientations, int band, int nbands);

/// False (with "split=S : out of range 1..N: the pyramid has N scales") unless
/// 1 <= split <= scales.
bool check_split(int split, int scales, std::string& error);

/// The factor opt.gain and opt.balance give band `band` of a pyramid with
/// `nbands` bands (band order as in pyramid.h; the low-pass gets 1).
float band_gain(const PyramidOptions& opt, int band, int nbands);

/// False (with a message) if opt.gain or opt.balance lists more scales than `scales`.
bool check_band_adjustments(const PyramidOptions& opt, int scales, std::string& error);

/// The option-table entries the pyramid and solid methods share, declared once: T has
/// `iterations`, `histogram` and `fft` members.
template <class T>
void add_iterations_option(OptionTable<T>& t)
{
    t.integer("iterations", &T::iterations, 0, 100,
         "match-texture iterations (Heeger & Bergen §3.3: about 5)")
        .shared();
}
/// "scales" (0 = automatic) and "orientations": T has int members scales and orientations.
template <class T>
void add_scale_options(OptionTable<T>& t, const char* scales_help, const char* orientations_help)
{
    t.integer("scales", &T::scales, 0, 16, scales_help).shared();
    t.integer("orientations", &T::orientations, 1, 8, orientations_help).shared();
}
template <class T>
void add_matching_options(OptionTable<T>& t)
{
    t.choice("histogram", &T::histogram,
         { { "exact", HistogramMode::Exact }, { "bins256", HistogramMode::Bins256 } },
         "histogram matching: exact quantiles, or the paper's 256-bin cdf")
        .shared();
    t.choice("fft", &T::fft, { { "kiss", FftBackend::Kiss }, { "fftw", FftBackend::Fftw } },
         "FFT backend: kiss (built in) or fftw (only in -DTEXSYN_WITH_FFTW=ON builds)")
        .shared();
}

} // namespace texsyn::detail
