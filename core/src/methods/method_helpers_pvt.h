// SPDX-License-Identifier: Apache-2.0
// What every method's implementation shares: the ImageBufAlgo-style error and value-form
// plumbing, sample validation, the synth:* tags, memory checks, seeded noise.
#pragma once

#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/fft.h>
#include <texsyn/homogeneity.h>
#include <texsyn/image.h>
#include <texsyn/memory.h>
#include <texsyn/methods.h>
#include <texsyn/options.h>
#include <texsyn/version.h>

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

/// Whether an options struct has a `flatten` member (the methods that take flatten=).
template <class T, class = void>
struct has_flatten : std::false_type { };
template <class T>
struct has_flatten<T, std::void_t<decltype(std::declval<const T&>().flatten)>> : std::true_type { };

/// Whether an options struct has a `scale` member (the copying methods' scale=).
template <class T, class = void>
struct has_scale : std::false_type { };
template <class T>
struct has_scale<T, std::void_t<decltype(std::declval<const T&>().scale)>> : std::true_type { };

/// `in` resampled by `k` (OIIO's default filter for the direction), each channel clamped to
/// the range it had, so that a copying method copies no value the sample does not hold:
/// the sample as it would have been scanned at k times the texel density. k = 1: unchanged.
void scale_sample(PlanarImage& in, float k, int nthreads);

/// The start of every synthesis from one sample: opt.validate(), then the sample's planes
/// (planes_from_imagebuf: a read error, NaN or Inf is refused), flattened
/// (flatten_illumination) if the options have flatten=1, and resampled (scale_sample) if
/// they have a scale. False with the message in dst.
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
    if constexpr (has_flatten<Options>::value)
        if (opt.flatten)
            flatten_illumination(in, opt.nthreads);
    if constexpr (has_scale<Options>::value)
        scale_sample(in, opt.scale, opt.nthreads);
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
    if constexpr (has_scale<Options>::value)
        if (source_map && resolved.scale != 1.0f) // source_map.h: apply_source_map resamples
            source_map->specmod().attribute("synth:sample_scale", resolved.scale);
}

/// The options struct of a registry row's options (a logic error, caught by run_method,
/// if they are another method's).
template <class Options>
const Options& options_of(const MethodOptions& options)
{
    const Options* o = options.get<Options>();
    if (!o)
        throw std::logic_error("the options are not the method's");
    return *o;
}

/// The front ends' run controls (seed, threads, progress, stop) in a method's options.
inline void apply_run_settings(const RunSettings& settings, RunControls& opt)
{
    opt = settings;
}

/// Throws std::runtime_error("stopped") if `stop` is set (stop.h): a method's check
/// between the steps of a run, on the calling thread; guarded() makes it the function's
/// "NAME: stopped".
void throw_if_stopped(const StopFlag* stop);

/// A step of a run done: throw_if_stopped(stop), then `progress(fraction)` if given.
void report_progress(
    const std::function<void(float)>& progress, const StopFlag* stop, float fraction);

/// False with "fft=fftw : not available …" unless `fft`'s backend is built in.
bool check_fft_backend(FftBackend fft, std::string& error);

/// "1 channel", "3 channels".
std::string count_text(int n, const std::string& noun);

using texsyn::check_memory; // texsyn/memory.h: refuses work beyond the memory limit
using texsyn::format_bytes;

/// Uniform noise in [0, 1), pixel i from random_uniform(seed, stream, i): the same at any
/// `nthreads` (0 = every core).
Plane seeded_noise(int width, int height, uint64_t seed, uint64_t stream, int nthreads);

} // namespace texsyn::detail
