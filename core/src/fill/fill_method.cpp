// SPDX-License-Identifier: Apache-2.0
// The registry row of the fill: the image on the stack, its mask (mask=), and optionally
// regions to leave out of the sources (exclude=) and another image to fill from (sample=)
// as file options.
#include <texsyn/fill.h>

#include <cstdio>

#include "methods/method_helpers_pvt.h"
#include "methods/result_layout_pvt.h"

namespace texsyn::detail {

namespace {

// The fill options and the files they name.
struct FillWithFiles {
    FillOptions options;
    std::string mask, exclude, sample, map;

    static const OptionTable<FillWithFiles>& table()
    {
        using O = FillWithFiles;
        return declared_table<O>([](OptionTable<O>& t) {
            t.include(&O::options, FillOptions::table());
            t.file("mask", &O::mask, FileUse::ReadData, "",
                "the hole: a one-channel image of the image's size, read as its numbers; "
                "pixels above 0 are filled (values between 0 and 1 blend the fill over the "
                "image), pixels at 0 are kept bit for bit; values outside 0..1 are refused. "
                "Required");
            t.file("exclude", &O::exclude, FileUse::ReadData, "",
                "a one-channel image of the image's size: no patch the fill copies touches "
                "a pixel above 0 (other markers, a logo, the edge of a set)");
            t.file("sample", &O::sample, FileUse::ReadImage, "",
                "fill from this image (the image's channels) instead of the image's own "
                "unmasked pixels; needed when the mask covers the whole image");
            t.file("map", &O::map, FileUse::Write, ".exr",
                "also write the source map: the float OpenEXR of the pixel each pixel was "
                "copied from (x, y; its own where the mask is 0) and the mask (m), which "
                "--apply-map reuses on a map aligned with the image (a fill from the image "
                "itself, not from sample=)");
        });
    }
    bool validate(std::string& error) const
    {
        if (!table().check(*this, error) || !options.validate(error))
            return false;
        if (mask.empty()) {
            error = "mask= : give the mask image (pixels above 0 are filled)";
            return false;
        }
        return true;
    }
};

// "filled 65536 px in 1 hole; 4 levels, iterations 4,6,8,8 (finest first); worked on
// 614656 px": the schedule that ran, where the options say "auto".
std::string report_text(const FillReport& r, const FillOptions& opt)
{
    std::string iterations;
    for (int l = 0; l < r.levels; ++l)
        iterations += (l ? "," : "") + std::to_string(opt.iterations_at(l));
    char text[200];
    std::snprintf(text, sizeof(text),
        "filled %zu px in %d hole%s; %d levels, iterations %s (finest first); worked on %zu px",
        r.filled, r.holes, r.holes == 1 ? "" : "s", r.levels, iterations.c_str(), r.work_pixels);
    return text;
}

bool run_fill(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages& files, const RunSettings& settings, MethodResult& result,
    std::string& error)
{
    const FillWithFiles& given = options_of<FillWithFiles>(options);
    FillOptions opt = given.options;
    apply_run_settings(settings, opt);
    auto file = [&](const char* name) {
        const auto it = files.find(name);
        return it == files.end() ? nullptr : &it->second;
    };
    FillReport report;
    OIIO::ImageBuf map;
    // A fill from sample= copies from two images and has no source map; a front end that
    // takes one whenever there is (settings.source_map) gets none rather than an error.
    const bool want_map = !given.map.empty() || (settings.source_map && !file("sample"));
    if (!texture_fill(result.image, *inputs[0].image, *file("mask"), opt, file("sample"),
            file("exclude"), &report, want_map ? &map : nullptr)) {
        error = result.image.geterror();
        for (const char* name : { "mask", "exclude", "sample", "map" })
            if (error.rfind(std::string(name) + ":", 0) == 0
                || error.find(std::string("the ") + name) == 0)
                error = option_error(name, options.value(name), error);
        return false;
    }
    if (want_map)
        result.files.emplace_back("map", std::move(map));
    result.notes = report_text(report, opt);
    return true;
}

// The image's size and channels; it tiles only if the image did, which is not known.
bool fill_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string&)
{
    layout = layout_from_input(inputs[0], options);
    layout.set_tiles(false);
    return true;
}

} // namespace

const Method& fill_method()
{
    static const Method m { "fill", MethodInputs::Image, MethodOutput::Image,
        [] { return MethodOptions(FillWithFiles()); }, run_fill, "fill.md",
        "fills a masked hole in an image (a marker, a rig, a logo) with texture from around "
        "it: texture optimization with the known pixels fixed",
        "Fill: pops an image and replaces its pixels where mask= is above 0 with texture "
        "synthesized from the rest of it (or from sample=), coarse to fine, continuous across "
        "the mask's edge; every filled pixel is copied from a known one, and pixels outside "
        "the mask stay bit-identical. The cost follows the holes, not the image.",
        "texsyn data/samples/bricks.png --fill:mask=data/masks/bricks_hole.png -o "
        "bricks_filled.png",
        "", false, {}, {}, {}, fill_layout, true };
    return m;
}

} // namespace texsyn::detail
