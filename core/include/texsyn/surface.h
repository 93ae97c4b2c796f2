// SPDX-License-Identifier: Apache-2.0
// Castellanos & Williams on surfaces (issue #17): a texture grown directly on a triangle
// mesh, face by face, with choosy sampling, and its bake into the mesh's UV texture.
//
// The mesh is read from an OBJ or PLY file (polygons become triangle fans) and must be one
// connected, manifold surface with no zero-area faces; remesh= first makes its triangles
// near-equilateral and near-uniform (§3.9) so that faces behave like pixels. Each of the
// levels-1 subdivisions splits every face in four (modified butterfly, §3.4), so the
// finest level has faces x 4^(levels-1) faces.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/choosy.h>
#include <texsyn/color.h>
#include <texsyn/options.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// remesh=auto keeps meshes of fewer faces than this.
constexpr size_t kAutoRemeshFaces = 100;

/// How far a mesh's faces are from the equal, equilateral faces the method assumes (its
/// stencils are laid out for equilateral faces, its filters for equal ones).
struct FaceShapes {
    double area_spread = 1.0;  ///< face areas, 99th percentile over 1st
    double angle_spread = 0.0; ///< median over faces of largest minus smallest angle, degrees
    /// What remesh=auto keeps: areas within 8x and angles within 25 degrees (CGAL's sphere:
    /// 1.5x, 4 degrees). The classic cow (82x, 62 degrees) and grids of right triangles
    /// (45 degrees, which grow streaks along their diagonals) are remeshed.
    bool even() const { return area_spread <= 8.0 && angle_spread <= 25.0; }
};

/// The options of --choosy-surface: the mesh, how to prepare it, the bake, and choosy
/// sampling's options (levels, iterations, penalty, search, dims, eps; not size or
/// isotropic: a surface has no size, and no global orientation, so the sample is always
/// matched in six rotations, §3.8).
/// What a face's stencil slots past a mesh boundary hold in a match (§3.12).
enum class BoundarySlots {
    /// The face's own value: measured closest to the interior (docs/surfaces.md), and fast.
    Own,
    /// Wildcards, as the paper has them: they count for nothing, and the faces near a
    /// boundary get an exact search of the full neighbourhoods without those slots.
    Wildcards,
};

struct SurfaceOptions {
    ChoosyOptions options;
    std::string mesh; ///< the OBJ or PLY file to grow the texture on
    /// Faces of the isotropic remesh before subdivision; 0 = the input mesh as it is; unset
    /// ("auto") = remesh to the input's face count unless its faces are even
    /// (FaceShapes::even()) or fewer than kAutoRemeshFaces (a coarse cage, which the
    /// subdivisions refine).
    std::optional<int> remesh;
    /// The UV bake's size (each UDIM tile), if the mesh has UVs; 0x0 = no bake.
    int bake_width = 1024;
    int bake_height = 1024;
    BoundarySlots boundary = BoundarySlots::Own;

    static const OptionTable<SurfaceOptions>& table();
    /// Ranges, list lengths and the rules between options. False with a message.
    bool validate(std::string& error) const;
};

/// A texture on a surface: the finest level's mesh with a colour per face, and, where the
/// input mesh has UVs, those colours baked into one image per UDIM tile the UVs touch.
struct SurfaceTexture {
    std::vector<std::array<float, 3>> vertices;
    std::vector<std::array<uint32_t, 3>> faces; ///< counter-clockwise seen from outside
    std::vector<std::string> channelnames;      ///< the sample's
    std::vector<std::vector<float>> colours;    ///< [channel][face], scene-linear
    /// UDIM numbers (1001 + u tile + 10 v tile) and their bakes (float, scene-linear, the
    /// sample's channels), in UDIM order; empty without UVs or with bake=0x0.
    std::vector<std::pair<int, OIIO::ImageBuf>> bake;
    double bake_coverage = 0.0;  ///< the share of the bake's texels inside the UV layout
    size_t base_faces = 0;       ///< faces of the mesh synthesis started from (after remesh)
    size_t colour_conflicts = 0; ///< §3.5: same-coloured adjacent base faces
    FaceShapes input_shapes;     ///< the input mesh's faces
    size_t remeshed_to = 0;      ///< the remesh's face count; 0 = not remeshed
};

/// Grows `sample` (scene-linear float; at least 2^levels pixels a side) on the mesh
/// options.mesh with choosy sampling (Algorithms 1 and 2 on the face pyramid), and bakes
/// it into the mesh's UVs. Refuses (false, one-line message naming the file or option)
/// an unreadable or malformed mesh, a sample too small for the levels, NaN/Inf pixels,
/// and work beyond the memory limit (before allocating it). Bit-identical for a seed
/// whatever options.nthreads is.
bool synthesize_surface(SurfaceTexture& out, const OIIO::ImageBuf& sample,
    const SurfaceOptions& options, std::string& error);

/// The 8-bit sRGB colours mesh viewers show for `texture`'s faces (write_surface_ply's
/// `display_rgb`): its first three channels (one channel: grey) converted from `colors`'
/// scene_linear like an untagged 8-bit image. False with OCIO's message otherwise.
bool surface_display_rgb(const SurfaceTexture& texture, const ColorConfig& colors,
    std::vector<std::array<uint8_t, 3>>& rgb, std::string& error, int nthreads = 0);

/// Writes `texture`'s mesh as a binary PLY (per-face float colours in scene-linear, named
/// after its channels, plus 8-bit red/green/blue from `display_rgb`, one per face, for
/// mesh viewers; may be null). Atomic; false with a message naming `path`.
bool write_surface_ply(const std::string& path, const SurfaceTexture& texture,
    const std::vector<std::array<uint8_t, 3>>* display_rgb, std::string& error);

} // namespace texsyn
#pragma GCC visibility pop
