// SPDX-License-Identifier: Apache-2.0
// Runs a recipe exactly as the `texsyn` tool runs the same command line.
#include <texsyn/recipe.h>

#include <OpenImageIO/filesystem.h>

#include <texsyn/color.h>
#include <texsyn/io.h>

namespace texsyn {

bool run_recipe(const Recipe& recipe, OIIO::ImageBuf& dst, std::vector<NamedImage>* subbands,
    std::string& error)
{
    auto colors = ColorConfig::load(recipe.colorconfig, error);
    if (!colors)
        return false;
    OIIO::ImageBuf file;
    OIIO::ImageSpec native;
    if (!read_image(recipe.sample, file, error, &native))
        return false;
    const std::string from = recipe.iscolorspace.empty() ? colors->guess_colorspace(native)
                                                         : colors->resolve(recipe.iscolorspace);
    const std::string to = recipe.tocolorspace.empty() ? colors->scene_linear()
                                                       : colors->resolve(recipe.tocolorspace);
    for (const std::string* name : { &recipe.iscolorspace, &recipe.tocolorspace })
        if (!name->empty() && colors->resolve(*name).empty()) {
            error = "unknown colour space '" + *name + "'";
            return false;
        }
    OIIO::ImageBuf sample, synth;
    if (!colors->convert_image(
            file, from, colors->scene_linear(), false, sample, error, recipe.pyramid.nthreads)) {
        error = recipe.sample + ": " + error;
        return false;
    }
    if (!pyramid_synthesize(synth, sample, recipe.pyramid, recipe.subbands ? subbands : nullptr)) {
        error = synth.geterror();
        return false;
    }
    if (!colors->convert_image(
            synth, colors->scene_linear(), to, true, dst, error, recipe.pyramid.nthreads))
        return false;
    dst.specmod().attribute("synth:sample", OIIO::Filesystem::filename(recipe.sample));
    dst.specmod().attribute("synth:colorspace", to);
    dst.specmod().attribute("oiio:ColorSpace", to);
    return true;
}

} // namespace texsyn
