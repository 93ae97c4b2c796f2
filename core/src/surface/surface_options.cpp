// SPDX-License-Identifier: Apache-2.0
// The options of --choosy-surface (texsyn/surface.h): its table and validation.
#include <texsyn/surface.h>

namespace texsyn {

namespace {

// Choosy sampling's options that apply on a surface (not size, not isotropic).
const OptionTable<ChoosyOptions>& surface_choosy_table()
{
    static const OptionTable<ChoosyOptions> t = [] {
        OptionTable<ChoosyOptions> sub;
        sub.subset(
            ChoosyOptions::table(), { "levels", "iterations", "penalty", "search", "dims", "eps" });
        return sub;
    }();
    return t;
}

} // namespace

const OptionTable<SurfaceOptions>& SurfaceOptions::table()
{
    return declared_table<SurfaceOptions>([](OptionTable<SurfaceOptions>& t) {
        using O = SurfaceOptions;
        t.file("mesh", &O::mesh, FileUse::ReadMesh, "",
            "the triangle mesh to grow the texture on: OBJ or PLY (polygons are split into "
            "triangles), one connected manifold surface; UVs (OBJ vt, PLY u v) allow a bake");
        t.include(&O::options, surface_choosy_table(),
            { { "levels",
                  "face pyramid levels: the finest has the mesh's faces x 4^(levels-1), each "
                  "the size of one sample pixel; the sample needs about 7 x 2^(levels-1) "
                  "pixels a side" },
                { "dims",
                    "kdtree: principal components kept of the 36-face neighbourhoods (36 x "
                    "channels or more = all: exact)" } });
        t.optional_integer("remesh", &O::remesh, 0, 50'000'000,
            "first remesh isotropically to about this many near-equilateral faces of equal "
            "size, so that faces behave like pixels; 0 = grow on the mesh as it is; auto = "
            "remesh to the mesh's own face count if its face areas differ more than 8x "
            "(99th over 1st percentile)",
            "auto");
        t.size("bake", &O::bake_width, &O::bake_height, 32768, "no bake",
            "if the mesh has UVs: the size WxH of its UV texture (each UDIM tile), written by "
            "an image -o");
        t.choice("boundary", &O::boundary,
            { { "own", BoundarySlots::Own }, { "wildcards", BoundarySlots::Wildcards } },
            "on a mesh with a boundary, what neighbourhood slots past it hold in a match: own "
            "(the face's own value; closest to the interior, measured) or wildcards (they "
            "count for nothing, as in the paper; slower)");
    });
}

bool SurfaceOptions::validate(std::string& error) const
{
    if (!table().check(*this, error))
        return false;
    if (mesh.empty()) {
        error = "mesh= : a mesh file is needed (OBJ or PLY)";
        return false;
    }
    if (remesh && *remesh > 0 && *remesh < 8) {
        error = "remesh=" + std::to_string(*remesh)
            + " : expected 0 (no remesh), 8 and more faces, or auto";
        return false;
    }
    return options.validate(error);
}

} // namespace texsyn
