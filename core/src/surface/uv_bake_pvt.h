// SPDX-License-Identifier: Apache-2.0
// Baking a texture grown on a mesh (surface_synthesis_pvt.h) into UV texture images, one per
// UDIM tile the mesh's UVs touch (issue #17), so that any renderer can use it.
//
// For every function here: failures return false with one line in `error` that names the
// parameter, the value received and what is allowed, checked before anything is allocated;
// an output argument is left empty on failure; nothing throws (std::bad_alloc is caught).
// Work runs under OIIO::parallel_for with `nthreads` (0 = all cores), and the result is
// bit-identical whatever nthreads is: every texel is a pure function of the inputs.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <OpenImageIO/Imath.h>

#include <map>
#include <vector>

#include <texsyn/image.h>

#include "face_filter_pvt.h"
#include "surface_mesh_pvt.h"

namespace texsyn::detail {

/// Most texel values (texels per tile x tiles x channels) one bake may make: 4 GiB of floats.
/// Baking one tile also takes about 9 bytes per texel of working memory.
constexpr size_t kMaxBakeValues = size_t(1) << 30;
/// Largest side of a tile, in texels.
constexpr int kMaxBakeSide = 65536;
/// Peak memory of a bake written by the tool, per texel value (texels x tiles x channels):
/// the baked tiles, a tile's working memory, the output's colour conversion and encoding.
/// Measured: 12.5 bytes on torus_uv.obj, bake=2048x2048 to 4096x4096, RGB, as EXR.
constexpr double kBakeBytesPerValue = 13.0;

/// The UDIM tiles (1001 + u + 10 v) a bake of `uv_mesh` (UVs in u 0..10, v 0..100) makes,
/// each with the faces whose UV triangles overlap it with positive length: a UV range
/// [lo, hi] spans tiles floor(lo) .. ceil(hi) - 1, so a face reaching u = 1.0 exactly is
/// in tile 1001 only. Faces of zero UV area are in none.
std::map<int, std::vector<uint32_t>> bake_tiles(const SurfaceMesh& uv_mesh);

struct UvBakeOptions {
    int width = 1024, height = 1024; ///< texels of every tile
    /// True when the synthesis base (pyramid.levels[0]) is the UV mesh itself: the same
    /// vertices' faces, in the same order and corner order (remesh=0). False when it is a
    /// remeshed version of the same surface: each texel's point on the UV mesh is then
    /// carried to the closest base face facing its way (SurfaceProjector).
    bool base_is_uv_mesh = true;
    /// Fill every texel no UV triangle covers from the nearest covered texel.
    bool pad = true;
    int nthreads = 0;
};

/// One UDIM tile: texels of u in [u_tile, u_tile + 1), v in [v_tile, v_tile + 1); texel
/// (x, y) is centred on u = u_tile + (x + 0.5) / width, v = v_tile + 1 - (y + 0.5) / height
/// (row 0 is the top of the tile, v = 1, as in OIIO and every renderer's UV convention).
struct UvBakeTile {
    int udim = 1001; ///< 1001 + u_tile + 10 v_tile
    int u_tile = 0, v_tile = 0;
    std::vector<Plane> channels; ///< one per colour channel, width x height
    /// 1 where some UV triangle overlaps the texel's square (conservative coverage), row-major.
    std::vector<uint8_t> covered;
    size_t covered_texels = 0;
};

struct UvBake {
    std::vector<UvBakeTile> tiles; ///< in increasing UDIM order
    /// Covered texels over all texels of all tiles.
    double covered_fraction = 0.0;
};

/// Bakes `colours` ([channel][face of pyramid.levels.back()], as SurfaceSynthesis holds
/// them) into the UV tiles of `uv_mesh`, which must have UVs (face_uvs one per face) in
/// u 0..10, v 0..100.
///
/// Tiles: every tile the UV triangles overlap with positive area (a triangle of zero UV
/// area bakes nothing). Coverage: a texel is covered when its closed square meets a UV
/// triangle, so texels straddling UV edges are covered; it takes the point of the nearest
/// such triangle closest to its centre (lowest face index among equals), and that
/// triangle's barycentric coordinates. Those give a point of the base mesh (the same face,
/// or the closest facing point of the remeshed base), whose face and barycentric
/// coordinates are carried down the subdivision hierarchy (finest_face_point()). Colour:
/// the finest face's vertex colours (vertex_colours()) interpolated linearly, so the bake
/// is continuous on the surface and across UV seams, and a colour that is constant on
/// every face around a finest face comes back exactly. Padding: each uncovered texel
/// takes the values of the nearest covered texel of its tile (exact Euclidean nearest, by
/// Felzenszwalb & Huttenlocher's distance transform), so mip-maps never see a background.
///
/// Fails if the mesh has no UVs, a UV is not finite or outside those ranges, width or
/// height is outside 1..kMaxBakeSide, the bake would hold more than kMaxBakeValues values,
/// the pyramid is empty, colours has no channel or a channel without one value per finest
/// face, or base_is_uv_mesh is set and the base's faces are not uv_mesh's.
bool bake_uv_texture(const SurfaceMesh& uv_mesh, const FacePyramid& pyramid,
    const FaceValues& colours, const UvBakeOptions& opt, UvBake& out, std::string& error);

/// A point of a face given by its barycentric coordinates (for the face's corners in order).
struct FacePoint {
    uint32_t face = 0;
    Imath::V3d barycentric { 1, 0, 0 };
};

/// The same point at the finest level of `pyramid`: at each level, the child of subdivide()
/// that contains it in the midpoint parameterisation (corner child k + 1 when coordinate k
/// is at least 1/2, else the centre child) and its coordinates there. `p.face` must be a
/// face of levels[0]; coordinates are clamped to non-negative and renormalised first.
FacePoint finest_face_point(const FacePyramid& pyramid, FacePoint p);

/// Per-vertex colours of `level` ([channel][vertex]): the area-weighted mean of the values
/// of the faces around each vertex, computed as the first face's value plus the weighted
/// mean of differences from it, so that equal values give exactly that value.
FaceValues vertex_colours(const FaceLevel& level, const FaceValues& values, int nthreads);

} // namespace texsyn::detail
