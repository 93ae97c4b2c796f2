// SPDX-License-Identifier: Apache-2.0
// The registry row of the patch method: one image in, its synthesis out, with the source
// map (map=) and a guide for the sample (guide=) as file options.
#include <texsyn/patch.h>

#include <cstdio>

#include "methods/method_helpers_pvt.h"
#include "methods/result_layout_pvt.h"

namespace texsyn::detail {

namespace {

// The patch options and the files they name.
struct PatchWithFiles {
    PatchOptions options;
    std::string map, guide;

    static const OptionTable<PatchWithFiles>& table()
    {
        using O = PatchWithFiles;
        return declared_table<O>([](OptionTable<O>& t) {
            t.include(&O::options, PatchOptions::table());
            t.file("map", &O::map, FileUse::Write, ".exr",
                "also write the source map: the float OpenEXR of the sample coordinate each "
                "output pixel was copied from (x, y; with isotropic=1 also t, the turn it was "
                "copied under), which --apply-map reuses");
            t.file("guide", &O::guide, FileUse::ReadData, "",
                "a one-channel image of the sample's size (read without colour conversion) "
                "used as its guidance channel instead of the automatic one: patches agree "
                "on it, so its features stay whole");
        });
    }
    bool validate(std::string& error) const
    {
        return table().check(*this, error) && options.validate(error);
    }
};

// "feature size 35 px; 4 levels: its features at most 8 px at the coarsest level, which
// keeps 16 px of the sample's side; used 83% of the sample; largest verbatim copy 1234 px
// (1.9% of the sample)".
std::string report_text(const PatchReport& r)
{
    char text[160];
    std::snprintf(text, sizeof(text),
        "; used %.0f%% of the sample; largest verbatim copy %zu px (%.1f%% of the sample)",
        100.0 * r.used_fraction, r.largest_copy, 100.0 * r.largest_copy_fraction);
    return describe_feature_scale(r.scale) + "; " + r.schedule + text;
}

// The sample's size (or size=) and channels; it tiles along the axes wrap= names.
bool patch_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string&)
{
    layout = layout_from_input(inputs[0], options);
    const PatchWrap wrap = options_of<PatchOptions>(options).wrap;
    layout.tiles_x = wrap == PatchWrap::Both || wrap == PatchWrap::X;
    layout.tiles_y = wrap == PatchWrap::Both || wrap == PatchWrap::Y;
    return true;
}

bool run_patch(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages& files, const RunSettings& settings, MethodResult& result,
    std::string& error)
{
    const PatchWithFiles& given = options_of<PatchWithFiles>(options);
    PatchOptions opt = given.options;
    apply_run_settings(settings, opt);
    const auto guide = files.find("guide");
    OIIO::ImageBuf map;
    PatchReport report;
    const bool want_map = !given.map.empty() || settings.source_map;
    if (!patch_synthesize(result.image, *inputs[0].image, opt, want_map ? &map : nullptr,
            guide == files.end() ? nullptr : &guide->second, &report)) {
        error = result.image.geterror();
        if (guide != files.end() && error.find("guide") != std::string::npos)
            error = option_error("guide", given.guide, error);
        return false;
    }
    if (want_map)
        result.files.emplace_back("map", std::move(map));
    result.notes = report_text(report);
    return true;
}

} // namespace

const Method& patch_method()
{
    static const Method m { "patch", MethodInputs::Image, MethodOutput::Image,
        [] { return MethodOptions(PatchWithFiles()); }, run_patch, "patch.md",
        "Kwatra et al. 2005 texture optimization with PatchMatch and Kaspar et al. 2015's "
        "histogram, repetition and guidance terms: structured textures, toroidal, with "
        "source maps",
        "Texture optimization of the current image (Kwatra et al. 2005, Kaspar et al. 2015): "
        "coarse to fine, PatchMatch search and robust voting of toroidal patches, histogram "
        "matched, repetition penalised; keeps bricks, tiles, weave and wood grain whole. Every "
        "output pixel is a sample pixel (map= writes where from).",
        "texsyn data/samples/bricks.png --patch:size=512x512 -o bricks_big.exr",
        "structured: bricks, tiles, weave, wood grain", false, {}, {}, {}, patch_layout, true };
    return m;
}

} // namespace texsyn::detail
