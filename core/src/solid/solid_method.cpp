// SPDX-License-Identifier: Apache-2.0
// The registry row of the solid method: a sample in, a volume out.
#include <texsyn/methods.h>
#include <texsyn/solid.h>

#include <algorithm>

#include "methods/method_helpers_pvt.h"
#include "methods/result_layout_pvt.h"

namespace texsyn::detail {

namespace {

bool run_solid(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages&, const RunSettings& settings, MethodResult& result, std::string& error)
{
    SolidOptions opt = options_of<SolidOptions>(options);
    apply_run_settings(settings, opt);
    if (solid_synthesize(result.image, *inputs[0].image, opt))
        return true;
    error = result.image.geterror();
    return false;
}

// size=WxHxD; without it the sample's width and height, and the smaller of them as depth.
bool solid_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string&)
{
    layout = layout_from_input(inputs[0], options);
    if (!options_of<SolidOptions>(options).depth)
        layout.depth = std::min(inputs[0].width, inputs[0].height);
    return true;
}

} // namespace

const Method& solid_method()
{
    static const Method m { "solid", MethodInputs::Image, MethodOutput::Volume,
        [] { return MethodOptions(SolidOptions()); }, run_solid, "solid.md",
        "Heeger & Bergen 1995 section 4: solid textures (3-D blocks) from a 2-D sample, "
        "seamless",
        "Heeger & Bergen 1995 section 4 solid texture of the current image: a 3-D block whose "
        "slices look like it. Write it with -o FILE.vdb (OpenVDB: grids Cd and density) or -o "
        "FILE.exr (one part per z slice).",
        "texsyn data/samples/marble_pink.png --solid:size=32x32x32:iterations=1 -o marble.vdb",
        "a 3-D block whose slices look like the sample", false, {}, {}, {}, solid_layout };
    return m;
}

} // namespace texsyn::detail
