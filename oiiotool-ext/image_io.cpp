// SPDX-License-Identifier: Apache-2.0
// Reading samples into scene-linear float and writing results in the policy's colour space
// (docs/colour.md), to temporary files that are committed only when the whole run succeeds.
#include "cli_state.h"
#include "output_format.h"
#include "quiet_stderr.h"

#include <filesystem>
#include <fstream>

#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>
#include <texsyn/subbands.h>

namespace texsyn::cli {

namespace {

void push_analysis(CliState& state, const std::string& filename)
{
    auto stats = std::make_shared<TextureStatistics>();
    std::string error;
    if (!read_statistics(filename, *stats, error))
        throw CliError(error);
    StackImage img;
    img.sources = { filename };
    img.from_file = true;
    img.input_colorspace = stats->colorspace;
    img.input_format
        = stats->sample_format.empty() ? OIIO::TypeFloat : OIIO::TypeDesc(stats->sample_format);
    img.output_colorspace = state.pending_tocolorspace;
    img.statistics = std::move(stats);
    if (!state.pending_iscolorspace.empty())
        throw CliError("--iscolorspace : " + filename
            + " is an analysis, its statistics are already scene-linear");
    state.stack.push_back(std::move(img));
}

void write_analysis(CliState& state, const StackImage& img, const std::string& filename)
{
    const std::string tmp = temporary_path_for(filename);
    state.pending_outputs.emplace_back(tmp, filename);
    std::string error;
    if (!write_statistics(tmp, *img.statistics, error))
        throw CliError("-o " + filename + " : could not write the analysis file");
}

} // namespace

void push_input(CliState& state, const std::string& filename)
{
    if (is_analysis_filename(filename))
        return push_analysis(state, filename);
    StackImage img;
    OIIO::ImageSpec native;
    std::string error;
    bool ok;
    {
        QuietStderr quiet;
        ok = read_image(filename, img.file_pixels, error, &native);
    }
    if (!ok)
        throw CliError(error);
    img.sources = { filename };
    img.from_file = true;
    img.input_format = native.format;
    img.output_colorspace = state.pending_tocolorspace;
    state.stack.push_back(std::move(img));
    std::string space = state.pending_iscolorspace.empty() ? state.colors().guess_colorspace(native)
                                                           : state.pending_iscolorspace;
    state.pending_iscolorspace.clear();
    reinterpret_input(state, space);
}

void reinterpret_input(CliState& state, const std::string& colorspace)
{
    StackImage& img = state.top("--iscolorspace");
    if (!img.file_pixels.initialized())
        throw CliError("--iscolorspace : the current image is not an input file "
                       "(put --iscolorspace right after the file name)");
    const ColorConfig& cc = state.colors();
    std::string space = cc.resolve(colorspace);
    if (space.empty())
        throw CliError("--iscolorspace : unknown colour space '" + colorspace + "'");
    std::string error;
    // Kept un-associated: colour under zero alpha must survive to the output.
    if (!cc.convert_image(
            img.file_pixels, space, cc.scene_linear(), false, img.buf, error, state.threads))
        throw CliError(img.sources[0] + ": " + error);
    img.input_colorspace = space;
}

void write_output(CliState& state, const std::string& filename)
{
    StackImage& img = state.top("-o");
    if (img.volume)
        return write_volume_output(state, filename);
    if (is_analysis_filename(filename) != bool(img.statistics))
        throw CliError("-o " + filename
            + (img.statistics ? " : the current item is an analysis; write it as *.tsa, or "
                                "synthesize from it first (--pyramid)"
                              : " : analysis files are made by --analyze (the current item is "
                                "an image)"));
    if (img.statistics)
        return write_analysis(state, img, filename);
    const ColorConfig& cc = state.colors();
    const OIIO::TypeDesc type = output_pixel_type(filename, state.data_format, img.input_format);
    std::string space = img.output_colorspace;
    if (space.empty())
        space = is_linear_type(type) ? cc.scene_linear() : img.input_colorspace;
    if (cc.resolve(space).empty())
        throw CliError("--tocolorspace : unknown colour space '" + space + "'");
    space = cc.resolve(space);

    std::string error;
    OIIO::ImageBuf out;
    if (!cc.convert_image(img.buf, cc.scene_linear(), space, stores_associated_alpha(filename), out,
            error, state.threads))
        throw CliError("-o " + filename + " : " + error);
    OIIO::ImageSpec& spec = out.specmod();
    spec.attribute("synth:sample", sample_names(img));
    spec.attribute("synth:colorspace", space);
    spec.attribute("synth:commandline", state.command_line);
    spec.attribute("oiio:ColorSpace", space);
    // Formats that drop unknown attributes (TIFF, JPEG) still keep the description.
    spec.attribute("ImageDescription",
        "texsyn " + std::string(version()) + " --"
            + std::string(spec.get_string_attribute("synth:method")) + ":"
            + std::string(spec.get_string_attribute("synth:options")) + " seed "
            + std::to_string(spec.get_int_attribute("synth:seed")) + ", sample " + sample_names(img)
            + ", " + space);

    // Written to a temporary file now, renamed into place when the whole run succeeded.
    const std::string tmp = temporary_path_for(filename);
    state.pending_outputs.emplace_back(tmp, filename);
    bool ok;
    {
        QuietStderr quiet;
        ok = state.subbands ? write_subband_exr(tmp, out, img.subbands, error)
                            : write_image_atomic(out, tmp, type, error);
    }
    if (!ok)
        throw CliError("-o " + filename + " : "
            + error.substr(error.find(": ") == std::string::npos ? 0 : error.find(": ") + 2));
}

void write_recipe(CliState& state, const std::string& filename)
{
    StackImage& img = state.top("--recipe");
    if (!img.has_recipe)
        throw CliError("--recipe " + filename
            + " : the current image is not a --pyramid, --neighborhood or --choosy synthesis "
              "of a sample file (recipes describe only those)");
    Recipe recipe = img.recipe;
    recipe.tocolorspace = img.output_colorspace;
    const std::string dir = std::filesystem::path(filename).parent_path().string();
    const std::string tmp = temporary_path_for(filename);
    state.pending_outputs.emplace_back(tmp, filename);
    std::ofstream out(tmp, std::ios::binary);
    out << recipe_to_json(recipe, dir.empty() ? "." : dir);
    if (!out.flush())
        throw CliError("--recipe " + filename + " : cannot write");
}

void CliState::commit_outputs()
{
    std::string error;
    for (auto& [tmp, final] : pending_outputs)
        if (!commit_file(tmp, final, error))
            throw CliError(error);
    pending_outputs.clear();
}

void CliState::discard_outputs()
{
    std::error_code ec;
    for (auto& [tmp, final] : pending_outputs)
        std::filesystem::remove(tmp, ec);
    pending_outputs.clear();
}

} // namespace texsyn::cli
