// SPDX-License-Identifier: Apache-2.0
// Runs a recipe exactly as the `texsyn` tool runs the same command line.
#include <texsyn/recipe.h>

#include <OpenImageIO/strutil.h>

#include <texsyn/color.h>
#include <texsyn/inputs.h>
#include <texsyn/volume.h>

namespace texsyn {

namespace {

// A recipe's sample may itself be a recipe (read through the OIIO plugin, on this thread);
// this bounds the nesting so that a recipe that refers to itself fails instead of
// recursing until the stack overflows.
thread_local int recipe_depth = 0;
constexpr int max_recipe_depth = 8;

struct DepthGuard {
    DepthGuard() { ++recipe_depth; }
    ~DepthGuard() { --recipe_depth; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;
};

// `image` (scene-linear) in colour space `to`: associated with alpha for an image, a
// volume kept un-associated as its files keep it.
bool convert_result(const ColorConfig& colors, const OIIO::ImageBuf& image, const std::string& to,
    bool volume, OIIO::ImageBuf& dst, std::string& error)
{
    if (!volume)
        return colors.convert_image(image, colors.scene_linear(), to, true, dst, error);
    PlanarVolume v;
    if (!volume_from_imagebuf(image, v, error))
        return false;
    PlanarImage planes;
    swap_voxel_planes(v, planes);
    const bool ok = colors.convert(planes, colors.scene_linear(), to, error);
    swap_voxel_planes(v, planes);
    if (ok)
        imagebuf_from_volume(v, dst);
    return ok;
}

} // namespace

bool run_recipe(const Recipe& recipe, OIIO::ImageBuf& dst, std::vector<NamedImage>* subbands,
    std::string& error)
{
    DepthGuard depth;
    if (recipe_depth > max_recipe_depth) {
        error = (recipe.samples.empty() ? std::string("recipe") : recipe.samples[0])
            + ": recipes nest more than " + std::to_string(max_recipe_depth)
            + " deep (does a recipe use itself as its sample?)";
        return false;
    }
    if (!recipe.validate(error))
        return false;
    const Method& method = *recipe.row();
    const MethodOptions options = recipe.options ? recipe.options : method.defaults();
    auto colors = ColorConfig::load(recipe.colorconfig, error);
    if (!colors)
        return false;
    const std::string to = recipe.tocolorspace.empty() ? colors->scene_linear()
                                                       : colors->resolve(recipe.tocolorspace);
    std::vector<std::string> spaces = recipe.iscolorspace;
    spaces.resize(recipe.samples.size(), spaces.size() == 1 ? spaces[0] : "");
    std::vector<std::pair<const char*, std::string>> named
        = { { "tocolorspace", recipe.tocolorspace } };
    for (const std::string& space : spaces)
        named.emplace_back("iscolorspace", space);
    for (const auto& [key, space] : named)
        if (!space.empty() && colors->resolve(space).empty()) {
            error = option_error(key, space,
                "unknown colour space (known: "
                    + OIIO::Strutil::join(colors->colorspace_names(), ", ") + ")");
            return false;
        }

    std::vector<Sample> samples(recipe.samples.size());
    std::vector<MethodInput> inputs;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (!read_sample(recipe.samples[i], *colors, spaces[i], samples[i], error))
            return false;
        inputs.push_back({ samples[i].analysis ? nullptr : &samples[i].pixels,
            samples[i].analysis.get(), recipe.samples[i] });
    }
    OptionImages files;
    if (!read_option_files(options, *colors, files, error))
        return false;
    RunSettings settings;
    settings.seed = recipe.seed;
    settings.subbands = recipe.subbands && subbands;
    MethodResult result;
    if (!run_method(method, options, inputs, files, settings, result, error))
        return false;
    if (!convert_result(
            *colors, result.image, to, method.output == MethodOutput::Volume, dst, error))
        return false;
    dst.specmod().attribute("synth:colorspace", to);
    dst.specmod().attribute("oiio:ColorSpace", to);
    if (settings.subbands)
        *subbands = std::move(result.subbands);
    return true;
}

} // namespace texsyn
