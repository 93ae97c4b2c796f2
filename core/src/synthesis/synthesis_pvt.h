// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the analysis and synthesis halves of the pyramid method.
#pragma once

#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <texsyn/synthesis.h>

namespace texsyn::detail {

/// Runs f() (returning bool) and turns a std::bad_alloc or other exception into false
/// with "<name>: out of memory" / "<name>: <what>" in `error`: nothing throws across the
/// public API.
template <class F>
bool guarded(std::string& error, const char* name, F&& f)
{
    try {
        return f();
    } catch (const std::bad_alloc&) {
        error = std::string(name) + ": out of memory";
    } catch (const std::exception& e) {
        error = std::string(name) + ": " + e.what();
    }
    return false;
}

/// The same for the ImageBuf forms: the message goes to dst.errorfmt().
template <class F>
bool guarded(OIIO::ImageBuf& dst, const char* name, F&& f)
{
    std::string error;
    if (guarded(error, name, std::forward<F>(f)))
        return true;
    if (!error.empty())
        dst.errorfmt("{}", error);
    return false;
}

/// The value form of an ImageBufAlgo-style function: calls f(dst) on a new ImageBuf and
/// guarantees has_error() if it returned false.
template <class F>
OIIO::ImageBuf value_form(const char* name, F&& f)
{
    OIIO::ImageBuf result;
    if (!f(result) && !result.has_error())
        result.errorfmt("{}() failed", name);
    return result;
}

/// The start of every synthesis from one sample: opt.validate(), then the sample's planes
/// (planes_from_imagebuf: a read error, NaN or Inf is refused). False with the message in
/// dst.
template <class Options>
bool validated_sample(
    OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const Options& opt, PlanarImage& in)
{
    std::string error;
    if (!opt.validate(error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    if (sample.has_error()) {
        dst.errorfmt("sample: {}", sample.geterror());
        return false;
    }
    if (!planes_from_imagebuf(sample, in, error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    return true;
}

/// Sets synth:version, synth:method, synth:seed and synth:options (the options' text).
void tag_synthesis(
    OIIO::ImageSpec& spec, const char* method, uint64_t seed, const std::string& options);

/// The end of a copying synthesis (neighbourhood, choosy): dst gets `channels` with the
/// sample's channel names, alpha and alpha association (`in` read from `sample`), and the
/// tags synth:version, synth:method, synth:seed and synth:options (`resolved`, the options
/// with the output size filled in); so does `source_map` if not null.
template <class Options>
void write_synthesis(OIIO::ImageBuf& dst, std::vector<Plane> channels, const PlanarImage& in,
    const OIIO::ImageBuf& sample, const char* method, const Options& resolved,
    OIIO::ImageBuf* source_map)
{
    const bool unassociated = sample.spec().get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
    PlanarImage result;
    result.channels = std::move(channels);
    result.channel_names = in.channel_names;
    result.alpha_channel = in.alpha_channel;
    imagebuf_from_planes(result, dst, !unassociated);
    const std::string options = Options::table().format(resolved);
    tag_synthesis(dst.specmod(), method, resolved.seed, options);
    if (source_map)
        tag_synthesis(source_map->specmod(), method, resolved.seed, options);
}

/// "1 channel", "3 channels".
std::string count_text(int n, const std::string& noun);

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

/// Where band `band` of a pyramid with `nbands` bands sits (band order as in pyramid.h):
/// its scale (0 finest; -1 for the steerable high-pass residual, the number of scales for
/// the low-pass) and orientation (0 for all but the steerable oriented bands).
struct BandPosition {
    int scale = 0;
    int orientation = 0;
};
BandPosition band_position(PyramidKind kind, int orientations, int band, int nbands);

/// False (with "split=S is out of range: the pyramid has N scales (split=1..N)") unless
/// 1 <= split <= scales.
bool check_split(int split, int scales, std::string& error);

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
