// SPDX-License-Identifier: Apache-2.0
// The registry row of choosy sampling on surfaces: a sample and a mesh in, the mesh with a
// colour per face out (and, for a mesh with UVs, their bake).
#include <texsyn/methods.h>
#include <texsyn/surface.h>

#include <cmath>
#include <cstdio>

#include <OpenImageIO/filesystem.h>

#include "methods/method_helpers_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

namespace {

bool run_surface(const MethodOptions& options, const std::vector<MethodInput>& inputs,
    const OptionImages&, const RunSettings& settings, MethodResult& result, std::string& error)
{
    SurfaceOptions opt = options_of<SurfaceOptions>(options);
    apply_run_settings(settings, opt.options);
    auto texture = std::make_shared<SurfaceTexture>();
    if (!synthesize_surface(*texture, *inputs[0].image, opt, error))
        return false;
    for (auto& [udim, image] : texture->bake) {
        tag_synthesis(image.specmod(), "choosy-surface", settings.seed, options.format());
        image.specmod().attribute("synth:udim", udim);
        image.specmod().attribute("synth:sample", OIIO::Filesystem::filename(inputs[0].name));
    }
    if (!texture->bake.empty())
        result.image = texture->bake.front().second;
    const size_t faces = texture->faces.size();
    result.notes = std::to_string(faces) + " faces from " + std::to_string(texture->base_faces)
        + " (" + std::to_string(texture->colour_conflicts) + " same-coloured adjacent base faces)";
    if (const size_t tiles = texture->bake.size())
        result.notes += ", baked into " + std::to_string(tiles) + " UDIM tile"
            + (tiles == 1 ? "" : "s") + " ("
            + std::to_string(int(std::lround(texture->bake_coverage * 100.0)))
            + "% of the texels inside the UV layout, the rest padded)";
    // Uneven faces blur the texture and slow the synthesis (the filters' sigma is the
    // largest distance between adjacent faces), skewed ones streak it: say what was done.
    const FaceShapes& shapes = texture->input_shapes;
    char uneven[128];
    std::snprintf(uneven, sizeof uneven,
        "the mesh's faces are far from equal, equilateral triangles (areas %.0fx apart, "
        "angles %.0f degrees apart at the median)",
        shapes.area_spread, shapes.angle_spread);
    if (texture->remeshed_to && !opt.remesh)
        result.notes += "; remesh=auto: " + std::string(uneven) + ", so it was first remeshed to "
            + std::to_string(texture->remeshed_to) + " even faces (remesh=0 keeps it)";
    else if (!shapes.even() && !texture->remeshed_to)
        result.notes += "; WARNING: " + std::string(uneven)
            + ", so they do not behave like pixels: remesh=N evens them (docs/surfaces.md)";
    result.surface = std::move(texture);
    return true;
}

// The result as an image is the UV bake (its first UDIM tile): the mesh must have UVs,
// and bake= a size.
bool surface_layout(const MethodOptions& options, const std::vector<InputLayout>& inputs,
    ResultLayout& layout, std::string& error)
{
    const SurfaceOptions& opt = options_of<SurfaceOptions>(options);
    if (!opt.bake_width || !opt.bake_height) {
        error = "bake=0x0 : an image of choosy-surface is its UV bake; give bake=WxH";
        return false;
    }
    SurfaceMesh mesh;
    std::string why;
    if (!read_surface_mesh(opt.mesh, mesh, why)) {
        error = option_error("mesh", opt.mesh, why);
        return false;
    }
    if (mesh.uvs.empty()) {
        error = option_error("mesh", opt.mesh,
            "has no UVs, so its texture makes no image (write the mesh to a .ply)");
        return false;
    }
    layout.width = opt.bake_width;
    layout.height = opt.bake_height;
    layout.depth = 1;
    layout.channelnames = inputs[0].channelnames;
    layout.set_tiles(false);
    return true;
}

} // namespace

const Method& surface_method()
{
    static const Method m = [] {
        Method row { "choosy-surface", MethodInputs::Image, MethodOutput::Mesh,
            [] { return MethodOptions(SurfaceOptions()); }, run_surface, "surfaces.md",
            "Castellanos & Williams on surfaces: the texture grown face by face on a triangle "
            "mesh (-o x.ply), baked into its UVs (-o x.exr)",
            "Grows the current image over the triangle mesh mesh= (OBJ or PLY): choosy sampling "
            "on a pyramid of butterfly subdivisions, each finest face one sample pixel, the "
            "sample matched in six rotations (a surface has no global orientation). The result "
            "is the subdivided mesh with a colour per face: -o NAME.ply writes it (float "
            "scene-linear colours and 8-bit sRGB for viewers); if the mesh has UVs, -o "
            "NAME.exr (or .png, .tif) writes its UV bake at bake=WxH, with NAME_<UDIM>.exr "
            "when the UVs span several UDIM tiles. A mesh of uneven faces is first remeshed to "
            "as many even ones (remesh=auto); remesh=N makes N, remesh=0 keeps the mesh.",
            "texsyn data/samples/flowers.png --choosy-surface:mesh=data/meshes/"
            "torus_uv.obj:levels=3:bake=256x256 -o torus_flowers.ply -o torus_flowers.png",
            "any texture, on a mesh instead of a plane" };
        row.layout = surface_layout;
        return row;
    }();
    return m;
}

} // namespace texsyn::detail
