// SPDX-License-Identifier: Apache-2.0
// A material set synthesized by a copying method: its search image synthesized, every map
// moved by the source map.
#include "material_run_pvt.h"

#include <algorithm>
#include <memory>

#include <texsyn/homogeneity.h>
#include <texsyn/image.h>
#include <texsyn/material.h>

namespace texsyn::detail {

bool run_on_material(const Method& method, const MethodOptions& options, const MethodInput& input,
    const OptionImages& files, RunSettings settings, MethodResult& result, std::string& error)
{
    const Material& material = *input.material;
    // flatten=1 divides the lighting out of the albedo alone (the other maps hold numbers,
    // not light): the set is flattened here, and the run searches and copies it as it is.
    Material flattened;
    const bool flatten = options.table().find("flatten") && options.value("flatten") == "1";
    MethodOptions run_options = options;
    if (flatten) {
        flattened = material;
        PlanarImage albedo;
        if (!planes_from_imagebuf(flattened.maps[0].image, albedo, error))
            return false;
        flatten_illumination(albedo, settings.nthreads);
        OIIO::ImageBuf image;
        imagebuf_from_planes(albedo, image);
        flattened.maps[0].image = std::move(image);
        if (!run_options.set("flatten", "0", error))
            return false;
    }
    const Material& set_in = flatten ? flattened : material;
    OIIO::ImageBuf search;
    if (!material_search_image(set_in, search, error))
        return false;
    settings.source_map = true;
    if (!run_method(method, run_options, { { &search, nullptr, input.name } }, files, settings,
            result, error))
        return false;
    const auto map = std::find_if(
        result.files.begin(), result.files.end(), [](const auto& f) { return f.first == "map"; });
    if (map == result.files.end()) {
        error = method.name + " gave no source map";
        return false;
    }
    auto set = std::make_shared<Material>();
    if (!apply_material(map->second, set_in, *set, error))
        return false;
    // Every map tiles as the run's result does (its wrapmodes, for .tx outputs and
    // renderers).
    const std::string wrapmodes = result.image.spec().get_string_attribute("wrapmodes");
    for (MaterialMap& m : set->maps) {
        if (wrapmodes.empty())
            m.image.specmod().erase_attribute("wrapmodes");
        else
            m.image.specmod().attribute("wrapmodes", wrapmodes);
    }
    result.image = set->maps[0].image;
    result.material = std::move(set);
    return true;
}

} // namespace texsyn::detail
