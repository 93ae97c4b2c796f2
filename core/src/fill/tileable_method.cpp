// SPDX-License-Identifier: Apache-2.0
// The registry row of make-tileable: the image on the stack, tiling at its own size.
#include <texsyn/fill.h>

#include <cstdio>

#include "methods/method_helpers_pvt.h"

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
        "re-synthesized a %d px band across the seams; changed %.1f%% "
        "of the pixels",
        report.band, 100.0 * report.changed_fraction);
    result.notes = text;
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
        "a scan that must tile at its own size" };
    return m;
}

} // namespace texsyn::detail
