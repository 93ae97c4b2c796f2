// SPDX-License-Identifier: Apache-2.0
// Runs a recipe exactly as the `texsyn` tool runs the same command line.
#include <texsyn/recipe.h>

#include <memory>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/color.h>
#include <texsyn/inputs.h>
#include <texsyn/io.h>
#include <texsyn/stats.h>
#include <texsyn/version.h>
#include <texsyn/volume.h>

#include "recipe_limits_pvt.h"

namespace texsyn {

namespace {

// A recipe's sample may itself be a recipe (read through the OIIO plugin, on this thread).
// The outermost recipe's nesting is checked before anything runs (check_recipe_work);
// this count bounds it again as the recipes run, in case a nested file changed since.
thread_local int recipe_depth = 0;

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
    return convert_volume_colours(colors, image, colors.scene_linear(), to, dst, error);
}

// What run_recipe() and recipe_spec() both start from: the nesting
// checked, the recipe validated, its method and options, its config,
// its output space `to` and each sample's colour space ("" = from the file).
struct Prepared {
    DepthGuard depth; ///< one level of recipe nesting while it lives
    const Method* method = nullptr;
    MethodOptions options; ///< the recipe's, or the method's defaults
    std::unique_ptr<ColorConfig> colors;
    std::string to;
    std::vector<std::string> spaces;
};

bool prepare(const Recipe& recipe, Prepared& p, std::string& error)
{
    int max_depth = 0;
    if (!detail::max_recipe_depth(max_depth, error))
        return false;
    if (recipe_depth > max_depth + 1) {
        error = (recipe.samples.empty() ? std::string("recipe") : recipe.samples[0])
            + ": recipes nest more than " + std::to_string(max_depth)
            + " deep (does a recipe use itself as its sample?)";
        return false;
    }
    if (recipe_depth == 1 && !check_recipe_work(recipe, error))
        return false;
    if (!recipe.validate(error))
        return false;
    p.method = recipe.row();
    p.options = recipe.options ? recipe.options : p.method->defaults();
    p.colors = ColorConfig::load(recipe.colorconfig, error);
    if (!p.colors)
        return false;
    p.to = recipe.tocolorspace.empty() ? p.colors->scene_linear()
                                       : p.colors->resolve(recipe.tocolorspace);
    p.spaces = recipe.iscolorspace;
    p.spaces.resize(recipe.samples.size(), p.spaces.size() == 1 ? p.spaces[0] : "");
    std::vector<std::pair<const char*, std::string>> named
        = { { "tocolorspace", recipe.tocolorspace } };
    for (const std::string& space : p.spaces)
        named.emplace_back("iscolorspace", space);
    for (const auto& [key, space] : named)
        if (!space.empty() && p.colors->resolve(space).empty()) {
            error = option_error(key, space, p.colors->unknown_colorspace(space));
            return false;
        }
    return true;
}

} // namespace

bool run_recipe(const Recipe& recipe, OIIO::ImageBuf& dst, std::vector<NamedImage>* subbands,
    std::string& error, const RunSettings& control)
{
    Prepared p;
    if (!prepare(recipe, p, error))
        return false;
    const Method& method = *p.method;
    const MethodOptions& options = p.options;
    std::vector<Sample> samples(recipe.samples.size());
    std::vector<MethodInput> inputs;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (!read_sample(
                recipe.samples[i], *p.colors, p.spaces[i], samples[i], error, control.nthreads))
            return false;
        inputs.push_back({ samples[i].analysis ? nullptr : &samples[i].pixels,
            samples[i].analysis.get(), recipe.samples[i] });
    }
    OptionImages files;
    if (!read_option_files(options, *p.colors, files, error, control.nthreads))
        return false;
    RunSettings settings;
    settings.nthreads = control.nthreads;
    settings.progress = control.progress;
    settings.stop = control.stop;
    settings.seed = recipe.seed;
    settings.subbands = recipe.subbands && subbands;
    MethodResult result;
    if (!run_method(method, options, inputs, files, settings, result, error))
        return false;
    if (!convert_result(
            *p.colors, result.image, p.to, method.output == MethodOutput::Volume, dst, error))
        return false;
    p.colors->tag_colorspace(dst.specmod(), p.to);
    if (settings.subbands)
        *subbands = std::move(result.subbands);
    return true;
}

bool recipe_spec(const Recipe& recipe, OIIO::ImageSpec& spec, std::string& error)
{
    Prepared p;
    if (!prepare(recipe, p, error))
        return false;
    const Method& method = *p.method;
    const MethodOptions& options = p.options;
    std::vector<InputLayout> inputs;
    std::string names;
    for (const std::string& file : recipe.samples) {
        InputLayout in;
        if (is_analysis_filename(file)) {
            TextureStatistics stats;
            if (!read_statistics(file, stats, error))
                return false;
            in = { stats.sample_width, stats.sample_height, stats.channel_names };
        } else {
            OIIO::ImageSpec header;
            if (!read_image_spec(file, header, error, sample_read_copies))
                return false;
            in = { header.width, header.height, header.channelnames };
        }
        inputs.push_back(in);
    }
    for (const OptionField& f : options.table().fields())
        if (const std::string file = options.value(f.name);
            f.type == OptionType::InputFile && !file.empty() && !check_option_file(f, file, error))
            return false;
    ResultLayout layout;
    if (!result_layout(method, options, inputs, layout, error))
        return false;
    spec = OIIO::ImageSpec(
        layout.width, layout.height, int(layout.channelnames.size()), OIIO::TypeFloat);
    spec.depth = spec.full_depth = layout.depth;
    if (layout.depth > 1) // a volume stays un-associated, as its files keep it
        spec.attribute("oiio:UnassociatedAlpha", 1);
    spec.channelnames = layout.channelnames;
    spec.alpha_channel = -1;
    for (size_t c = 0; c < layout.channelnames.size(); ++c)
        if (OIIO::Strutil::iequals(layout.channelnames[c], "A")
            || OIIO::Strutil::iequals(layout.channelnames[c], "Alpha"))
            spec.alpha_channel = int(c);
    spec.attribute("synth:version", version());
    spec.attribute("synth:method", method.name);
    spec.attribute("synth:seed", int(recipe.seed));
    spec.attribute("synth:options", options.format());
    for (size_t i = 0; i < recipe.samples.size(); ++i) {
        const std::string name = OIIO::Filesystem::filename(recipe.samples[i]);
        if (method.inputs == MethodInputs::ImageAndSample && i == 0)
            spec.attribute("synth:image", name);
        else
            names += (names.empty() ? "" : ",") + name;
    }
    if (!names.empty())
        spec.attribute("synth:sample", names);
    if (!layout.wrapmodes().empty())
        spec.attribute("wrapmodes", layout.wrapmodes());
    p.colors->tag_colorspace(spec, p.to);
    return true;
}

} // namespace texsyn
