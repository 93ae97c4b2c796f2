// SPDX-License-Identifier: Apache-2.0
// The registry row of --material: the image on the stack becomes a material's albedo, and
// the maps its options name join it. A copying method then synthesizes the whole material.
#include <texsyn/material.h>

#include <OpenImageIO/filesystem.h>

#include "methods/method_helpers_pvt.h"

namespace texsyn::detail {

namespace {

// The maps a material may have besides its albedo, in output order.
enum class MapName { Albedo, Normal, Height, Roughness, Metallic, Ao, Specular, Opacity };

const std::vector<std::pair<std::string, MapName>>& map_names()
{
    static const std::vector<std::pair<std::string, MapName>> names
        = { { "albedo", MapName::Albedo }, { "normal", MapName::Normal },
              { "height", MapName::Height }, { "roughness", MapName::Roughness },
              { "metallic", MapName::Metallic }, { "ao", MapName::Ao },
              { "specular", MapName::Specular }, { "opacity", MapName::Opacity } };
    return names;
}

struct MaterialOptions {
    std::string normal, height, roughness, metallic, ao, specular, opacity;
    std::vector<MapName> search = { MapName::Albedo, MapName::Height };
    std::vector<float> weights;
    NormalMap normals = NormalMap::OpenGL;

    static const OptionTable<MaterialOptions>& table()
    {
        using O = MaterialOptions;
        return declared_table<O>([](OptionTable<O>& t) {
            t.file("normal", &O::normal, FileUse::ReadData, "",
                "the tangent-space normal map (encoded 0.5 + 0.5 n, read as its numbers): "
                "re-applied with its vectors turned where a copy is turned");
            for (const auto& [name, member] :
                std::vector<std::pair<const char*, std::string O::*>> { { "height", &O::height },
                    { "roughness", &O::roughness }, { "metallic", &O::metallic }, { "ao", &O::ao },
                    { "specular", &O::specular }, { "opacity", &O::opacity } })
                t.file(name, member, FileUse::ReadData, "",
                    "a data map of the material, read and written as its numbers (no colour "
                    "conversion)");
            t.choices("search", &O::search, map_names(), 8,
                "the maps the synthesis matches, besides carrying every map along (a map "
                "listed but not given is skipped); each is scaled to the albedo's spread");
            t.numbers("weights", &O::weights, 0.0f, 100.0f, 8, "1",
                "weight of each map of search=, in its order (missing ones: 1)");
            t.choice("normals", &O::normals,
                { { "opengl", NormalMap::OpenGL }, { "directx", NormalMap::DirectX } },
                "which way the normal map's green channel points: opengl (up the image: "
                "Blender, Maya, MaterialX, glTF) or directx (down: Unreal, 3ds Max)");
        });
    }
    bool validate(std::string& error) const
    {
        if (!table().check(*this, error))
            return false;
        if (weights.size() > search.size()) {
            std::string text;
            for (float w : weights)
                text += (text.empty() ? "" : ",") + std::to_string(w);
            error = option_error("weights", text,
                "more weights than maps in search= (" + std::to_string(search.size()) + ")");
            return false;
        }
        return true;
    }
    const std::string* file_of(MapName m) const
    {
        switch (m) {
        case MapName::Albedo:
            return nullptr;
        case MapName::Normal:
            return &normal;
        case MapName::Height:
            return &height;
        case MapName::Roughness:
            return &roughness;
        case MapName::Metallic:
            return &metallic;
        case MapName::Ao:
            return &ao;
        case MapName::Specular:
            return &specular;
        case MapName::Opacity:
            return &opacity;
        }
        return nullptr;
    }
};

bool run_material(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages& files, const RunSettings&, MethodResult& result, std::string& error)
{
    const MaterialOptions& opt = options_of<MaterialOptions>(options);
    auto material = std::make_shared<Material>();
    material->normals = opt.normals;
    auto weight_of = [&](MapName m) {
        for (size_t i = 0; i < opt.search.size(); ++i)
            if (opt.search[i] == m)
                return i < opt.weights.size() ? opt.weights[i] : 1.0f;
        return 0.0f;
    };
    // -v: how every map was read (the albedo as a sample: its colour space the tool
    // reports; the others as their numbers) and what the search weighs.
    std::string read;
    auto describe = [&](const std::string& name, const std::string& file,
                        const OIIO::ImageBuf& image, const std::string& how, float weight) {
        const OIIO::ImageSpec& s = image.spec();
        read += (read.empty() ? "" : "; ") + name + " " + OIIO::Filesystem::filename(file) + " ("
            + std::to_string(s.width) + "x" + std::to_string(s.height) + ", "
            + count_text(s.nchannels, "channel") + ") " + how + ", "
            + (weight > 0.0f ? "searched" : "carried along");
    };
    for (const auto& [name, which] : map_names()) {
        MaterialMap map;
        map.name = name;
        map.weight = weight_of(which);
        if (which == MapName::Albedo) {
            map.kind = MapKind::Colour;
            map.image.copy(*inputs[0].image, OIIO::TypeFloat);
            describe(name, inputs[0].name, *inputs[0].image, "colour managed to scene-linear",
                map.weight);
        } else {
            const auto it = files.find(name);
            if (it == files.end())
                continue;
            map.kind = which == MapName::Normal ? MapKind::Normal : MapKind::Data;
            describe(name, *opt.file_of(which), it->second,
                map.kind != MapKind::Normal             ? "read as its numbers"
                    : opt.normals == NormalMap::DirectX ? "read as numbers, a DirectX normal map"
                                                        : "read as numbers, an OpenGL normal map",
                map.weight);
            map.image.copy(it->second, OIIO::TypeFloat);
            if (map.kind == MapKind::Normal && map.image.nchannels() < 3) {
                error = option_error(name, *opt.file_of(which),
                    "a normal map needs 3 channels (x, y, z); it has "
                        + std::to_string(map.image.nchannels()));
                return false;
            }
        }
        // Refused as a sample is: a map the search does not weigh would carry its NaN into
        // every copy of it, and into the files written.
        if (std::string why; !check_finite_pixels(map.image, why)) {
            error = which == MapName::Albedo ? inputs[0].name + ": " + why
                                             : option_error(name, *opt.file_of(which), why);
            return false;
        }
        material->maps.push_back(std::move(map));
    }
    OIIO::ImageBuf search;
    if (!material_search_image(*material, search, error))
        return false;
    result.material = std::move(material);
    result.notes = read;
    return true;
}

} // namespace

const Method& material_method()
{
    static const Method m { "material", MethodInputs::Image, MethodOutput::Material,
        [] { return MethodOptions(MaterialOptions()); }, run_material, "materials.md",
        "makes the current image the albedo of a material set with its other maps (normal, "
        "height, roughness…), for a copying method to synthesize together",
        "Material set: pops an image (the albedo) and pushes a material made of it and the "
        "maps the options name, read as their numbers. The next --patch, --neighborhood or "
        "--choosy synthesizes all of them with one source map: the search weighs the maps "
        "of search=, every map follows the same copy, normal maps turn with it. Write them "
        "with -o NAME_{map}.exr.",
        "texsyn data/samples/bricks.png --material:height=data/samples/bricks_height.png "
        "--patch:size=256x256 -o bricks_{map}.png",
        "" };
    return m;
}

} // namespace texsyn::detail
