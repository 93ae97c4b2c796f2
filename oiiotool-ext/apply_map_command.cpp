// SPDX-License-Identifier: Apache-2.0
// --apply-map MAP IMAGE: one neighbourhood synthesis drives every map of a material.
#include "cli_state.h"
#include "quiet_stderr.h"

#include <texsyn/io.h>

namespace texsyn::cli {

void run_apply_map(CliState& state, const std::string& map_file, const std::string& image_file)
{
    const std::string command = "--apply-map " + map_file + " " + image_file;
    OIIO::ImageBuf map;
    std::string error;
    bool ok;
    {
        QuietStderr quiet;
        ok = read_image(map_file, map, error);
    }
    if (!ok)
        throw CliError(error);
    push_input(state, image_file);
    StackImage img = state.pop(command);
    OIIO::ImageBuf remapped;
    if (!apply_source_map(remapped, map, img.file_pixels))
        throw CliError(command + " : " + remapped.geterror());
    // The image's own values, rearranged: it goes on as an input read in its colour space,
    // and is written in that space unless --tocolorspace says otherwise (so a height or
    // normal map keeps its numbers).
    img.file_pixels = std::move(remapped);
    img.from_file = false;
    if (img.output_colorspace.empty())
        img.output_colorspace = img.input_colorspace;
    const std::string space = img.input_colorspace;
    state.stack.push_back(std::move(img));
    reinterpret_input(state, space);
}

} // namespace texsyn::cli
