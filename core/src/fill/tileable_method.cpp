// SPDX-License-Identifier: Apache-2.0
// The registry row of make-tileable: the image on the stack, tiling at its own size.
#include <texsyn/fill.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "methods/method_helpers_pvt.h"
#include "methods/result_layout_pvt.h"

namespace texsyn::detail {

namespace {

bool run_tileable(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages&, const RunSettings& settings, MethodResult& result, std::string& error)
{
    TileableOptions opt = options_of<TileableOptions>(options);
    apply_run_settings(settings, opt.options);
    TileableReport report;
    if (!make_tileable(result.image, *inputs[0].image, opt, &report)) {
        error = result.image.geterror();
        return false;
    }
    char text[120];
    std::snprintf(text, sizeof(text),
        "; re-synthesized a %d px band across the seams; changed %.1f%% of the pixels", report.band,
        100.0 * report.changed_fraction);
    result.notes = describe_feature_scale(report.scale) + text;
    if (report.band_too_narrow) {
        const int side = std::min(inputs[0].image->spec().width, inputs[0].image->spec().height);
        const int wanted = int(std::lround(report.scale.size / 2.0));
        result.warnings.push_back({ "band",
            "its features (" + std::to_string(int(std::lround(report.scale.size)))
                + " px) are more than twice as wide as the " + std::to_string(report.band)
                + " px band across the seams: features there come out cut short or smeared; "
                + (wanted <= side / 3 ? "give band=" + std::to_string(wanted) + " (at most "
                            + std::to_string(side / 3) + "), or "
                                      : std::string())
                + "scan an area at least " + std::to_string(int(std::lround(6.0 * wanted)))
                + " px on a side" });
    }
    return true;
}

// The image's size and channels; it tiles along the axes axis= names.
bool tileable_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string&)
{
    layout = layout_from_input(inputs[0], options);
    const TileAxes axis = options_of<TileableOptions>(options).axis;
    layout.tiles_x = axis != TileAxes::Y;
    layout.tiles_y = axis != TileAxes::X;
    return true;
}

} // namespace

const Method& tileable_method()
{
    static const Method m { "tileable", MethodInputs::Image, MethodOutput::Image,
        [] { return MethodOptions(TileableOptions()); }, run_tileable, "fill.md",
        "makes an image tile at its own size: a band across its wrap-around seams is filled "
        "from the rest of it; everything else is kept",
        "Make tileable: pops an image and re-synthesizes a band (band=) across its "
        "wrap-around seams with the fill, from the rest of the image, so that it tiles at "
        "its own size; pixels outside the band stay bit-identical (-v reports the changed "
        "fraction).",
        "texsyn data/samples/bricks.png --tileable -o bricks_tile.png",
        "a scan that must tile at its own size", false, {}, {}, {}, tileable_layout };
    return m;
}

} // namespace texsyn::detail
