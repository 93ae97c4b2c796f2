// SPDX-License-Identifier: Apache-2.0
// Material sets: a sample's albedo with its other maps (normal, height, roughness…),
// synthesized together. One copying synthesis (neighborhood, choosy, patch) runs on the
// maps the search weighs and gives one source map; every map of the material is that
// source map applied to it (source_map.h), so the maps stay aligned pixel for pixel and a
// normal map turns with the copy. run_method (methods.h) does this for a set given as its
// input (MethodInput::material) to any row that copies_pixels.
#pragma once

#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/methods.h>
#include <texsyn/options.h>
#include <texsyn/source_map.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// What a map of a material holds.
enum class MapKind {
    Colour, ///< the albedo: colour managed like any input (scene-linear in memory)
    Data,   ///< height, roughness, metallic…: the stored numbers, never colour converted
    Normal, ///< a tangent-space normal map (numbers, encoded 0.5 + 0.5 n): turned with copies
};

/// One map of a material.
struct MaterialMap {
    std::string name; ///< "albedo", "normal", "height"…: the {map} of output file names
    MapKind kind = MapKind::Data;
    /// Its weight in the search (0: carried along, not searched). The search sees each
    /// searched map scaled to the albedo's spread x its weight.
    float weight = 0.0f;
    OIIO::ImageBuf image; ///< float
};

/// A material: its maps, the albedo first. Searched maps have the albedo's size; the others
/// may be a whole multiple or fraction of it (a 2K normal map for a 1K albedo).
struct Material {
    std::vector<MaterialMap> maps;
    NormalMap normals = NormalMap::OpenGL; ///< how its normal maps point
};

/// The image a copying method synthesizes for `material`: the channels of every map with
/// a weight above 0, in order (channel names "<map>.<channel>"), each map scaled so that its
/// channels' mean standard deviation is the first map's x its weight (a constant map is
/// left as it is). False with a message naming the map if a searched map's size differs
/// from the first's.
bool material_search_image(const Material& material, OIIO::ImageBuf& dst, std::string& error);

/// Every map of `material` re-applied by `source_map` (apply_source_map, normal maps turned
/// by material.normals), into `out` (same names, kinds and weights). False with a message
/// naming the map otherwise.
bool apply_material(
    const OIIO::ImageBuf& source_map, const Material& material, Material& out, std::string& error);

} // namespace texsyn
#pragma GCC visibility pop
