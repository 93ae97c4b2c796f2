// SPDX-License-Identifier: Apache-2.0
// -o and --recipe: results written in the policy's colour space and pixel type
// (docs/colour.md) to temporary files committed only when the whole run succeeds.
#include "cli_error.h"
#include "commands.h"
#include "output_format.h"
#include "quiet_stderr.h"

#include <filesystem>
#include <stdexcept>

#include <OpenImageIO/filesystem.h>

#include <texsyn/io.h>
#include <texsyn/subbands.h>
#include <texsyn/version.h>

namespace texsyn::cli {

namespace {

// "sample.png: reason" -> "reason": the option names the file already.
std::string without_file(const std::string& error)
{
    const size_t colon = error.find(": ");
    return colon == std::string::npos ? error : error.substr(colon + 2);
}

void write_analysis(CliState& state, StackItem& item, const std::string& filename)
{
    std::string error;
    if (!write_statistics(state.outputs.add(filename), *item.analysis, error))
        throw CliError("-o " + filename + " : " + state.outputs.final_names(without_file(error)));
    item.file = filename; // once committed, the analysis is that file (for --recipe)
}

void write_image(CliState& state, const StackItem& item, const std::string& filename)
{
    const ColorConfig& cc = state.colors();
    const OIIO::TypeDesc type = output_pixel_type(filename, state.data_format, item.input_format);
    std::string space = item.output_colorspace;
    if (space.empty())
        space = is_linear_type(type) ? cc.scene_linear() : item.input_colorspace;
    if (cc.resolve(space).empty())
        throw CliError("--tocolorspace : " + cc.unknown_colorspace(space));
    space = cc.resolve(space);

    std::string error;
    OIIO::ImageBuf out;
    if (!cc.convert_image(item.buf, cc.scene_linear(), space, stores_associated_alpha(filename),
            out, error, state.threads))
        throw CliError("-o " + filename + " : " + error);
    OIIO::ImageSpec& spec = out.specmod();
    std::string sample = std::string(spec.get_string_attribute("synth:sample"));
    if (sample.empty() && !item.file.empty()) // an input written as it is
        sample = OIIO::Filesystem::filename(item.file);
    if (!sample.empty())
        spec.attribute("synth:sample", sample);
    cc.tag_colorspace(spec, space);
    spec.attribute("synth:commandline", state.command_line);
    // Formats that drop unknown attributes (TIFF, JPEG) still keep the description.
    spec.attribute("ImageDescription",
        "texsyn " + std::string(version()) + " --"
            + std::string(spec.get_string_attribute("synth:method")) + ":"
            + std::string(spec.get_string_attribute("synth:options")) + " seed "
            + std::to_string(spec.get_int_attribute("synth:seed"))
            + (sample.empty() ? "" : ", sample " + sample) + ", colorspace " + space);

    const std::string tmp = state.outputs.add(filename);
    bool ok;
    {
        QuietStderr quiet("-o " + filename);
        ok = state.subbands ? write_subband_exr(tmp, out, item.subbands, error)
                            : write_image_verified(out, tmp, type, error);
    }
    if (!ok)
        throw CliError("-o " + filename + " : " + state.outputs.final_names(without_file(error)));
}

} // namespace

void write_output(CliState& state, const std::string& filename)
{
    StackItem& item = state.stack.top("-o");
    if (item.kind == ItemKind::Volume)
        return write_volume_output(state, filename);
    if (item.kind == ItemKind::Analysis)
        return write_analysis(state, item, filename);
    write_image(state, item, filename);
}

void write_recipe(CliState& state, const std::string& filename)
{
    StackItem& item = state.stack.top("--recipe");
    if (!item.recipe)
        throw CliError("--recipe " + filename + " : the current item, the " + item.name
            + ", has no recipe: "
            + (item.no_recipe.empty() ? "it was read from a file, not made by a method"
                                      : item.no_recipe));
    Recipe recipe = *item.recipe;
    recipe.tocolorspace = item.output_colorspace;
    const std::string dir = std::filesystem::path(filename).parent_path().string();
    std::string json;
    try {
        json = recipe_to_json(recipe, dir.empty() ? "." : dir);
    } catch (const std::invalid_argument& e) {
        throw CliError("--recipe " + filename + " : " + e.what());
    }
    std::string reason;
    if (!write_bytes(state.outputs.add(filename), json, reason))
        throw CliError("--recipe " + filename + " : cannot write (" + reason + ")");
}

} // namespace texsyn::cli
