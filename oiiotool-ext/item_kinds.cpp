// SPDX-License-Identifier: Apache-2.0
#include "item_kinds.h"

#include <algorithm>
#include <filesystem>

#include <OpenImageIO/strutil.h>

#include "cli_error.h"
#include "commands.h"

namespace texsyn::cli {

namespace {

// "--solid": the commands whose results are of `kind`.
std::string makers(ItemKind kind)
{
    return command_list([kind](const Method& m) { return item_kind(m.output) == kind; });
}

// A 2-D image: every command takes it.
void any_command(const std::string&, const Method&, int, int, const std::string&, bool)
{ }

// A solid texture or a textured mesh: no command takes it.
template <ItemKind kind>
void no_command(const std::string& command, const Method&, int, int, const std::string&, bool)
{
    throw CliError(command + " : the current image is " + item_kind_text(kind) + " (from "
        + makers(kind) + "); it needs a 2-D image");
}

// "--pyramid, --mix and --transfer": the commands that take analyses.
std::string analysis_commands()
{
    return command_list(
        [](const Method& m) { return m.accepts_analysis(0) || m.accepts_analysis(1); });
}

void analysis_takers(
    const std::string& command, const Method& m, int index, int, const std::string& name, bool made)
{
    if (!m.accepts_analysis(index))
        throw CliError(command + " : needs an image, not an analysis (" + (made ? "the " : "")
            + name + "; only " + analysis_commands() + " take analyses)");
}

void copying_commands(
    const std::string& command, const Method& m, int, int count, const std::string&, bool)
{
    if (!m.copies_pixels || count != 1)
        throw CliError(command + " : the current item is " + item_kind_text(ItemKind::Material)
            + " (from " + makers(ItemKind::Material) + "); " + command_list(&Method::copies_pixels)
            + " synthesize one");
}

std::string extension_of(const std::string& out)
{
    return std::filesystem::path(out).extension().string();
}

// An image, a textured mesh (its UV bake) or an analysis (its own files): one file.
std::vector<std::string> one_file(const std::string& out, const std::vector<std::string>&)
{
    return { out };
}

std::vector<std::string> volume_files(const std::string& out, const std::vector<std::string>&)
{
    const ItemKindRules& volume = kind_rules(ItemKind::Volume);
    if (!OIIO::Strutil::iends_with(out, volume.own_extension)
        && !OIIO::Strutil::iends_with(out, ".exr"))
        throw CliError("-o " + out + " : " + item_kind_text(ItemKind::Volume)
            + " is written as .vdb (OpenVDB) or .exr (one part per z slice), not '"
            + extension_of(out) + "'");
    return { out };
}

std::vector<std::string> analysis_files(const std::string& out, const std::vector<std::string>&)
{
    if (!is_analysis_filename(out))
        throw CliError("-o " + out + " : the current item is an analysis; write it as *"
            + kind_rules(ItemKind::Analysis).own_extension + ", or synthesize from it first ("
            + analysis_commands() + " take analyses)");
    return { out };
}

// A material set: one file per map, {map} in the name replaced by the map's name.
std::vector<std::string> material_files(
    const std::string& out, const std::vector<std::string>& maps)
{
    if (out.find("{map}") == std::string::npos)
        throw CliError("-o " + out + " : the current item is " + item_kind_text(ItemKind::Material)
            + " (" + OIIO::Strutil::join(maps, ", ")
            + "); put {map} in the name, e.g. out_{map}.exr");
    std::vector<std::string> files;
    for (const std::string& map : maps)
        files.push_back(material_map_filename(out, map));
    return files;
}

const std::vector<ItemKindRules>& kinds()
{
    static const std::vector<ItemKindRules> rules = {
        { ItemKind::Image, MethodOutput::Image, "an image", "", "", "", true, any_command, one_file,
            write_image_output },
        { ItemKind::Analysis, MethodOutput::Analysis, "an analysis", "analysis", ".tsa", "analyses",
            false, analysis_takers, analysis_files, write_analysis_output },
        { ItemKind::Volume, MethodOutput::Volume, "a solid texture", "", ".vdb", "solid textures",
            true, no_command<ItemKind::Volume>, volume_files, write_volume_output },
        { ItemKind::Mesh, MethodOutput::Mesh, "a textured mesh", "", ".ply", "textured meshes",
            true, no_command<ItemKind::Mesh>, one_file, write_mesh_output },
        { ItemKind::Material, MethodOutput::Material, "a material set", "material set", "", "",
            false, copying_commands, material_files, write_material_output },
    };
    return rules;
}

} // namespace

const ItemKindRules& kind_rules(ItemKind kind)
{
    return *std::find_if(
        kinds().begin(), kinds().end(), [kind](const ItemKindRules& r) { return r.kind == kind; });
}

ItemKind item_kind(MethodOutput output)
{
    for (const ItemKindRules& r : kinds())
        if (r.made_by == output)
            return r.kind;
    return ItemKind::Image;
}

const char* item_kind_text(ItemKind kind)
{
    return kind_rules(kind).text;
}

std::string result_name(const Method& m, const std::vector<std::string>& inputs)
{
    std::string names;
    for (const std::string& input : inputs)
        names += (names.empty() ? "" : ", ") + input;
    const std::string noun = kind_rules(item_kind(m.output)).result_noun;
    const std::string what = noun.empty() ? m.name + " synthesis" : noun;
    return names.empty() ? what : what + " of " + names;
}

std::vector<std::string> output_files(
    const std::string& out, ItemKind kind, const std::vector<std::string>& parts)
{
    for (const ItemKindRules& other : kinds())
        if (other.kind != kind && *other.own_extension
            && OIIO::Strutil::iends_with(out, other.own_extension))
            throw CliError("-o " + out + " : " + other.own_extension + " holds " + other.own_files
                + " (from " + makers(other.kind) + "); the current item is "
                + item_kind_text(kind));
    return kind_rules(kind).output_files(out, parts);
}

} // namespace texsyn::cli
