// SPDX-License-Identifier: Apache-2.0
// -o and --recipe: results written in the policy's colour space and pixel type
// (docs/colour.md) to temporary files committed only when the whole run succeeds.
#include "cli_error.h"
#include "commands.h"
#include "item_kinds.h"
#include "output_format.h"
#include "quiet_stderr.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <OpenImageIO/filesystem.h>

#include <texsyn/io.h>
#include <texsyn/subbands.h>
#include <texsyn/surface.h>
#include <texsyn/version.h>

namespace texsyn::cli {

namespace {

// "sample.png: reason" -> "reason": the option names the file already.
std::string without_file(const std::string& error)
{
    const size_t colon = error.find(": ");
    return colon == std::string::npos ? error : error.substr(colon + 2);
}

// `image` converted from scene-linear to `space` for writing. Where that changes no value
// (`space` is scene-linear or data) and the pixels need no alpha handling (finite packed
// float without alpha, which ColorConfig::convert_image would copy as they are), a view of
// `image`'s own pixels instead of a copy: a 1024x1024 RGB result is 12 MB not copied. The
// caller may change the view's spec, never its pixels, and must not outlive `image`.
OIIO::ImageBuf output_pixels(const ColorConfig& cc, const OIIO::ImageBuf& image,
    const std::string& space, bool associate, const std::string& filename, int threads)
{
    const OIIO::ImageSpec& spec = image.spec();
    const auto* pixels = static_cast<const float*>(image.localpixels());
    const bool unchanged = space == cc.resolve(cc.scene_linear()) || cc.is_data(space);
    if (unchanged && pixels && spec.alpha_channel < 0 && spec.format == OIIO::TypeFloat
        && spec.channelformats.empty() && spec.depth <= 1
        && image.pixel_stride() == OIIO::stride_t(spec.pixel_bytes())
        && image.scanline_stride() == OIIO::stride_t(spec.scanline_bytes())
        && std::all_of(pixels, pixels + spec.image_pixels() * size_t(spec.nchannels),
            [](float v) { return std::isfinite(v); })) {
        // The spec convert_image gives: the same pixels and metadata, at the origin.
        OIIO::ImageSpec view(spec.width, spec.height, spec.nchannels, OIIO::TypeFloat);
        view.channelnames = spec.channelnames;
        for (const OIIO::ParamValue& p : spec.extra_attribs)
            if (p.name() != "oiio:UnassociatedAlpha")
                view.attribute(p.name(), p.type(), p.data());
        return OIIO::ImageBuf(view, const_cast<float*>(pixels));
    }
    OIIO::ImageBuf out;
    std::string error;
    if (!cc.convert_image(image, cc.scene_linear(), space, associate, out, error, threads))
        throw CliError("-o " + filename + " : " + error);
    return out;
}

// Writes `image`, the pixels of `item` (its own, or one UDIM tile of its bake, or a map).
void write_pixels(CliState& state, const StackItem& item, const OIIO::ImageBuf& image,
    const std::string& filename)
{
    const ColorConfig& cc = state.colors();
    OIIO::TypeDesc type = output_pixel_type(filename, state.data_format, item.input_format);
    std::string space = item.output_colorspace;
    if (space.empty())
        space = is_linear_type(type) ? cc.scene_linear() : item.input_colorspace;
    if (cc.resolve(space).empty())
        throw CliError("--tocolorspace : " + cc.unknown_colorspace(space));
    space = cc.resolve(space);

    OIIO::ImageBuf out = output_pixels(
        cc, image, space, stores_associated_alpha(filename), filename, state.threads);
    std::string error;
    // Floating-point files hold every value: half only up to 65504 (a float EXR instead).
    if (type == OIIO::TypeHalf)
        type = type_holding(value_range(out, state.threads), type, state.data_format, filename);
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

// "torus_<UDIM>.exr" with the tile's number; `filename` as it is if it has no <UDIM>.
std::string udim_filename(const std::string& filename, int udim)
{
    const size_t at = filename.find("<UDIM>");
    return at == std::string::npos
        ? filename
        : filename.substr(0, at) + std::to_string(udim) + filename.substr(at + 6);
}

} // namespace

void write_analysis_output(CliState& state, StackItem& item, const std::string& filename)
{
    std::string error;
    if (!write_statistics(state.outputs.add(filename), *item.analysis, error))
        throw CliError("-o " + filename + " : " + state.outputs.final_names(without_file(error)));
    item.file = filename; // once committed, the analysis is that file (for --recipe)
}

void write_image_output(CliState& state, StackItem& item, const std::string& filename)
{
    write_pixels(state, item, item.buf, filename);
}

void write_mesh_output(CliState& state, StackItem& item, const std::string& filename)
{
    const SurfaceTexture& texture = *item.surface;
    std::string error;
    if (OIIO::Strutil::iends_with(filename, ".ply")) {
        std::vector<std::array<uint8_t, 3>> rgb;
        if (!surface_display_rgb(texture, state.colors(), rgb, error, state.threads))
            throw CliError("-o " + filename + " : display colours: " + error);
        if (!write_surface_ply(state.outputs.add(filename), texture, &rgb, error))
            throw CliError(
                "-o " + filename + " : " + state.outputs.final_names(without_file(error)));
        return;
    }
    if (texture.bake.empty())
        throw CliError("-o " + filename + " : the " + item.name
            + " has no UV bake (its mesh has no UVs, or bake=0x0); write it as .ply");
    if (texture.bake.size() > 1 && filename.find("<UDIM>") == std::string::npos) {
        std::string tiles;
        for (const auto& tile : texture.bake)
            tiles += (tiles.empty() ? "" : ", ") + std::to_string(tile.first);
        throw CliError("-o " + filename + " : the mesh's UVs span UDIM tiles " + tiles
            + "; put <UDIM> in the name (e.g. texture_<UDIM>.exr) for one file per tile");
    }
    for (const auto& [udim, image] : texture.bake)
        write_pixels(state, item, image, udim_filename(filename, udim));
}

std::string material_map_filename(const std::string& pattern, const std::string& map)
{
    std::string name = pattern;
    for (size_t at = name.find("{map}"); at != std::string::npos; at = name.find("{map}", at))
        name.replace(at, 5, map);
    return name;
}

void write_material_output(CliState& state, StackItem& item, const std::string& pattern)
{
    for (const MaterialMap& map : item.material->maps) {
        const std::string name = material_map_filename(pattern, map.name);
        if (map.kind == MapKind::Colour) {
            write_pixels(state, item, map.image, name);
            continue;
        }
        // A data map's numbers are what it means: an integer file, which holds 0..1, must
        // not clip them.
        const OIIO::TypeDesc type = output_pixel_type(name, state.data_format, item.input_format);
        if (!type.is_floating_point()) {
            const ValueRange range = value_range(map.image, state.threads);
            if (range.low < -1e-5f || range.high > 1.0f + 1e-5f) // beyond rounding
                throw CliError("-o " + name + " : the " + map.name + " map's values span "
                    + OIIO::Strutil::fmt::format("{:g}..{:g}", range.low, range.high) + "; a "
                    + std::string(type.c_str())
                    + " file holds 0..1: write it as .exr (or .tif with -d float)");
        }
        StackItem data;
        data.input_format = item.input_format;
        data.input_colorspace = data.output_colorspace = "Raw";
        write_pixels(state, data, map.image, name);
    }
}

void write_output(CliState& state, const std::string& filename)
{
    StackItem& item = state.stack.top("-o");
    kind_rules(item.kind).write(state, item, filename);
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
    std::string json, reason;
    if (!recipe_to_json(recipe, dir.empty() ? "." : dir, json, reason))
        throw CliError("--recipe " + filename + " : " + reason);
    if (!write_bytes(state.outputs.add(filename), json, reason))
        throw CliError("--recipe " + filename + " : cannot write (" + reason + ")");
}

} // namespace texsyn::cli
