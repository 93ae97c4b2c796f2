// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the analysis and synthesis halves of the pyramid method.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <texsyn/synthesis.h>

namespace texsyn::detail {

/// "1.5 GB" style.
std::string format_bytes(double bytes);

/// False (with "size=WxH would need about … of memory (this machine has …)") if `need`
/// bytes exceed the machine's physical memory.
bool check_memory(size_t need, const std::string& what, std::string& error);

/// The pyramid of opt.pyramid for one image size; nullptr and `error` on failure.
std::unique_ptr<Pyramid> make_pyramid(const PyramidOptions& opt, int width, int height, int scales,
    Boundary boundary, std::string& error);

/// Uniform noise in [0, 1), pixel i from random_uniform(seed, stream, i).
Plane seeded_noise(int width, int height, uint64_t seed, uint64_t stream);

/// All values equal.
bool is_constant(const Plane& p);

/// Mean in double precision, fixed order.
float plane_mean(const Plane& p);

/// Collects band `b` of every component into one NamedImage "<prefix>.<band name>".
void append_subbands(const std::string& prefix, const std::vector<std::string>& band_names,
    const std::vector<std::vector<Plane>>& per_component,
    const std::vector<std::string>& component_names, std::vector<NamedImage>& out);

} // namespace texsyn::detail

namespace texsyn::detail {

/// The factor opt.gain and opt.balance give band `band` of a pyramid with
/// `nbands` bands (band order as in pyramid.h; the low-pass gets 1).
float band_gain(const PyramidOptions& opt, int band, int nbands);

/// False (with a message) if opt.gain or opt.balance lists more scales than `scales`.
bool check_band_adjustments(const PyramidOptions& opt, int scales, std::string& error);

} // namespace texsyn::detail

namespace texsyn::detail {

/// The option-table entries the pyramid and solid methods share, declared once: T has
/// `iterations`, `histogram` and `fft` members.
template <class T>
void add_iterations_option(OptionTable<T>& t)
{
    t.integer("iterations", &T::iterations, 0, 100,
        "match-texture iterations (Heeger & Bergen §3.3: about 5)");
}
template <class T>
void add_matching_options(OptionTable<T>& t)
{
    t.choice("histogram", &T::histogram,
        { { "exact", HistogramMode::Exact }, { "bins256", HistogramMode::Bins256 } },
        "histogram matching: exact quantiles, or the paper's 256-bin cdf");
    t.choice("fft", &T::fft, { { "kiss", FftBackend::Kiss }, { "fftw", FftBackend::Fftw } },
        "FFT backend: kiss (built in) or fftw (only in -DTEXSYN_WITH_FFTW=ON builds)");
}

} // namespace texsyn::detail
