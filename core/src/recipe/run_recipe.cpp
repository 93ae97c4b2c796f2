// SPDX-License-Identifier: Apache-2.0
// Runs a recipe exactly as the `texsyn` tool runs the same command line.
#include <texsyn/recipe.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/color.h>
#include <texsyn/io.h>

#include "recipe_pvt.h"

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

// The synthesis of the recipe's sample (an image, or an analysis file), scene-linear.
bool synthesize_sample(const Recipe& recipe, const ColorConfig& colors, int nthreads,
    OIIO::ImageBuf& synth, std::vector<NamedImage>* subbands, std::string& error)
{
    if (!recipe.subbands)
        subbands = nullptr;
    if (is_analysis_filename(recipe.sample)) { // method pyramid (Recipe::validate)
        TextureStatistics stats;
        if (!read_statistics(recipe.sample, stats, error))
            return false;
        if (synthesize_from_statistics(synth, stats, recipe.pyramid, nullptr, subbands))
            return true;
        error = synth.geterror();
        return false;
    }
    OIIO::ImageBuf file;
    OIIO::ImageSpec native;
    if (!read_image(recipe.sample, file, error, &native))
        return false;
    const std::string from = recipe.iscolorspace.empty() ? colors.guess_colorspace(native)
                                                         : colors.resolve(recipe.iscolorspace);
    OIIO::ImageBuf sample;
    if (!colors.convert_image(file, from, colors.scene_linear(), false, sample, error, nthreads)) {
        error = recipe.sample + ": " + error;
        return false;
    }
    const bool ok = recipe.method == "neighborhood"
        ? neighborhood_synthesize(synth, sample, recipe.neighborhood)
        : recipe.method == "choosy" ? choosy_synthesize(synth, sample, recipe.choosy)
                                    : pyramid_synthesize(synth, sample, recipe.pyramid, subbands);
    if (ok)
        return true;
    error = synth.geterror();
    return false;
}

} // namespace

bool run_recipe(const Recipe& recipe, OIIO::ImageBuf& dst, std::vector<NamedImage>* subbands,
    std::string& error)
{
    DepthGuard depth;
    if (recipe_depth > max_recipe_depth) {
        error = recipe.sample + ": recipes nest more than " + std::to_string(max_recipe_depth)
            + " deep (does a recipe use itself as its sample?)";
        return false;
    }
    if (!recipe.validate(error))
        return false;
    int nthreads = 0;
    detail::visit_recipe_options(recipe, [&](const auto& opt) { nthreads = opt.nthreads; });
    auto colors = ColorConfig::load(recipe.colorconfig, error);
    if (!colors)
        return false;
    const std::string to = recipe.tocolorspace.empty() ? colors->scene_linear()
                                                       : colors->resolve(recipe.tocolorspace);
    for (auto [key, name] : { std::pair { "iscolorspace", &recipe.iscolorspace },
             std::pair { "tocolorspace", &recipe.tocolorspace } })
        if (!name->empty() && colors->resolve(*name).empty()) {
            error = std::string(key) + "=" + *name + ": unknown colour space (known: "
                + OIIO::Strutil::join(colors->colorspace_names(), ", ") + ")";
            return false;
        }
    OIIO::ImageBuf synth;
    if (!synthesize_sample(recipe, *colors, nthreads, synth, subbands, error))
        return false;
    if (!colors->convert_image(synth, colors->scene_linear(), to, true, dst, error, nthreads))
        return false;
    dst.specmod().attribute("synth:sample", OIIO::Filesystem::filename(recipe.sample));
    dst.specmod().attribute("synth:colorspace", to);
    dst.specmod().attribute("oiio:ColorSpace", to);
    return true;
}

} // namespace texsyn
