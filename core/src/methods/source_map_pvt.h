// SPDX-License-Identifier: Apache-2.0
// Writing source-coordinate maps (neighborhood.h, choosy.h): shared by every method that
// copies sample pixels.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/methods.h>
#include <texsyn/options.h>

#include "method_helpers_pvt.h"

namespace texsyn::detail {

/// `map` becomes a width x height float image with the channels "x", "y": pixel i holds the
/// coordinates of source[i], an index y * source_width + x into the sample, and
/// "synth:sample_size" = "<sample_width>x<sample_height>" (what apply_source_map checks);
/// with `transforms` (per pixel, 0..7: source_map.h's M_t) a third channel "t" holds them,
/// and with `blend` (a plane of the map's size, clamped to 0..1) a last channel "m" (a
/// fill's mask: apply_source_map blends the copy over the image's own pixel by it).
void write_source_map(OIIO::ImageBuf& map, const std::vector<uint32_t>& source, int width,
    int height, int source_width, int sample_width, int sample_height,
    const std::vector<uint8_t>* transforms = nullptr, const Plane* blend = nullptr);

/// The options of a method that copies sample pixels (neighbourhood, choosy) with the
/// source map it writes: map=FILE.exr, a file name, so not one of the method's options.
template <class Options>
struct WithSourceMap {
    Options options;
    std::string map;

    static const OptionTable<WithSourceMap>& table()
    {
        return declared_table<WithSourceMap>([](OptionTable<WithSourceMap>& t) {
            t.include(&WithSourceMap::options, Options::table());
            t.file("map", &WithSourceMap::map, FileUse::Write, ".exr",
                "also write the source map: the float OpenEXR of the sample coordinate each "
                "output pixel was copied from (x, y; with isotropic=1 also t, the turn it was "
                "copied under), which --apply-map reuses");
        });
    }
    bool validate(std::string& error) const
    {
        return table().check(*this, error) && options.validate(error);
    }
};

/// The run of a registry row for a method that copies sample pixels: `synthesize` (e.g.
/// choosy_synthesize) from the one image input, with the source map when map= names a
/// file or RunSettings::source_map asks for it (MethodResult::files["map"]).
template <class Options>
bool run_copying_method(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const RunSettings& settings, MethodResult& result, std::string& error,
    bool (*synthesize)(OIIO::ImageBuf&, const OIIO::ImageBuf&, const Options&, OIIO::ImageBuf*))
{
    const WithSourceMap<Options>& given = options_of<WithSourceMap<Options>>(options);
    Options opt = given.options;
    apply_run_settings(settings, opt);
    OIIO::ImageBuf map;
    const bool want_map = !given.map.empty() || settings.source_map;
    if (!synthesize(result.image, *inputs[0].image, opt, want_map ? &map : nullptr)) {
        error = result.image.geterror();
        return false;
    }
    if (want_map)
        result.files.emplace_back("map", std::move(map));
    return true;
}

/// The registry row of a method that copies sample pixels: one image in, its synthesis by
/// `synthesize` out, options WithSourceMap<Options>, its result's layout by `layout`
/// (a MethodLayout for the method's own options and the one sample).
template <class Options>
Method copying_method(const char* name, const char* doc, const char* summary, const char* help,
    const char* example, const char* suits,
    bool (*synthesize)(OIIO::ImageBuf&, const OIIO::ImageBuf&, const Options&, OIIO::ImageBuf*),
    bool (*layout)(
        const Options&, const InputLayout&, const MethodOptions&, ResultLayout&, std::string&))
{
    Method m { name, MethodInputs::Image, MethodOutput::Image,
        [] { return MethodOptions(WithSourceMap<Options>()); },
        [synthesize](const MethodOptions& options, const std::vector<MethodInput>& inputs,
            const OptionImages&, const RunSettings& settings, MethodResult& result,
            std::string& error) {
            return run_copying_method<Options>(
                options, inputs, settings, result, error, synthesize);
        },
        doc, summary, help, example, suits };
    m.copies_pixels = true;
    m.layout = [layout](const MethodOptions& options, const std::vector<InputLayout>& inputs,
                   ResultLayout& result, std::string& error) {
        return layout(
            options_of<WithSourceMap<Options>>(options).options, inputs[0], options, result, error);
    };
    return m;
}

} // namespace texsyn::detail
