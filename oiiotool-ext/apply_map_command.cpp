// SPDX-License-Identifier: Apache-2.0
// --apply-map MAP IMAGE: one neighbourhood synthesis drives every map of a material.
#include "cli_error.h"
#include "command_line.h"
#include "commands.h"
#include "quiet_stderr.h"

#include <OpenImageIO/filesystem.h>

#include <texsyn/io.h>
#include <texsyn/source_map.h>

namespace texsyn::cli {

void run_apply_map(CliState& state, const std::string& command_arg, const std::string& map_file,
    const std::string& image_file)
{
    const std::string command = command_arg + " " + map_file + " " + image_file;
    ApplyMapOptions opt;
    opt.normal = apply_map_normal(command_arg);
    OIIO::ImageBuf map;
    std::string error;
    bool ok;
    {
        QuietStderr quiet(command);
        ok = read_image(map_file, map, error);
    }
    if (!ok)
        throw CliError(error);
    push_input(state, image_file);
    if (state.stack.top(command).kind != ItemKind::Image)
        throw CliError(command + " : " + image_file + " is an analysis, not an image");
    StackItem img = std::move(state.stack.pop(command, 1)[0]);
    OIIO::ImageBuf remapped;
    if (!apply_source_map(remapped, map, img.file_pixels, opt))
        throw CliError(command + " : " + remapped.geterror());
    // The image's own values, rearranged: it goes on as an input read in its colour space,
    // and is written in that space unless --tocolorspace says otherwise (so a height or
    // normal map keeps its numbers).
    img.file_pixels = std::move(remapped);
    img.file_pixels.specmod().attribute("synth:sample", OIIO::Filesystem::filename(image_file));
    img.name = "source map " + map_file + " applied to " + image_file;
    img.file.clear();
    img.no_recipe = "--apply-map has no recipe";
    if (img.output_colorspace.empty())
        img.output_colorspace = img.input_colorspace;
    const std::string space = img.input_colorspace;
    state.stack.push(std::move(img));
    reinterpret_input(state, space);
}

} // namespace texsyn::cli
