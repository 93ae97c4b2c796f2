// SPDX-License-Identifier: Apache-2.0
// synthesize_surface() (texsyn/surface.h): the mesh read, checked and optionally remeshed,
// the texture grown on its face pyramid, and the result baked into its UVs.
#include <texsyn/surface.h>

#include <algorithm>
#include <cctype>

#include "face_stencil_pvt.h"
#include "methods/method_helpers_pvt.h"
#include "surface_mesh_pvt.h"
#include "surface_synthesis_pvt.h"
#include "uv_bake_pvt.h"

namespace texsyn {

namespace {

using detail::SurfaceMesh;

// Bytes a synthesis of `finest` faces from a w x h sample of nc channels needs: the face
// pyramid with its stencils and the synthesis values (about 450 bytes a finest face
// measured on the cow at 1.5M faces, all levels included), and the sample's points in six
// phases for the search.
size_t surface_memory_estimate(double finest, int w, int h, int nc, const ChoosyOptions& opt)
{
    const double per_face = 400.0 + 24.0 * nc;
    const double dim = 36.0 * nc;
    const double per_point = opt.search == ChoosySearch::Exhaustive
        ? dim
        : 2.0 * std::min(dim, double(opt.dims)) + 2.0;
    const double points = 2.0 * double(w) * double(h) * 6.0;
    const double bytes = finest * per_face + 4.0 * points * per_point;
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

// Whether a w x h sample, cropped to a multiple of 2^(levels-1), has a whole 2-distant
// neighbourhood at its coarsest level on one of its two analysis grids (§3.8, §3.12): the
// coarsest level is the grid of the sample shrunk 2^(levels-1) times.
bool sample_fits_levels(int w, int h, int levels)
{
    const int unit = 1 << (levels - 1);
    for (const auto& [gw, gh] : { std::pair(w / unit, h / unit), std::pair(h / unit, w / unit) }) {
        if (gw < 1 || gh < 1)
            continue;
        const detail::FacePyramid grid = detail::triangular_grid(gw, gh, 1);
        for (const auto& slots : detail::face_stencils(grid.levels[0], 1))
            if (detail::complete(slots))
                return true;
    }
    return false;
}

// The value at fraction `q` (0..1) of `values`' sorted order (reorders them).
double quantile(std::vector<double>& values, double q)
{
    const size_t at = std::min(values.size() - 1, size_t(q * double(values.size())));
    std::nth_element(values.begin(), values.begin() + long(at), values.end());
    return values[at];
}

FaceShapes face_shapes(const SurfaceMesh& mesh)
{
    const size_t n = mesh.faces.size();
    std::vector<double> areas(n), angles(n);
    for (size_t f = 0; f < n; ++f) {
        const auto& c = mesh.faces[f];
        const Imath::V3d p[3] = { Imath::V3d(mesh.vertices[c[0]]), Imath::V3d(mesh.vertices[c[1]]),
            Imath::V3d(mesh.vertices[c[2]]) };
        areas[f] = 0.5 * ((p[1] - p[0]) % (p[2] - p[0])).length();
        double lo = 180.0, hi = 0.0;
        for (int k = 0; k < 3; ++k) {
            const Imath::V3d u = (p[(k + 1) % 3] - p[k]).normalized();
            const Imath::V3d v = (p[(k + 2) % 3] - p[k]).normalized();
            const double a = std::acos(std::clamp(u ^ v, -1.0, 1.0)) * 180.0 / M_PI;
            lo = std::min(lo, a), hi = std::max(hi, a);
        }
        angles[f] = hi - lo;
    }
    FaceShapes shapes;
    const double small = quantile(areas, 0.01);
    shapes.area_spread = small > 0.0 ? quantile(areas, 0.99) / small : 0.0;
    shapes.angle_spread = quantile(angles, 0.5);
    return shapes;
}

// The message of a mesh function without its leading "PATH: " (mesh= names the file).
std::string mesh_error(const std::string& path, const std::string& message)
{
    const std::string prefix = path + ": ";
    return option_error(
        "mesh", path, message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message);
}

bool grow(SurfaceTexture& out, const OIIO::ImageBuf& sample, const SurfaceOptions& options,
    std::string& error)
{
    if (!options.validate(error))
        return false;
    if (sample.has_error()) {
        error = "sample: " + sample.geterror();
        return false;
    }
    PlanarImage in;
    if (!planes_from_imagebuf(sample, in, error))
        return false;
    const ChoosyOptions& opt = options.options;
    if (opt.flatten)
        flatten_illumination(in, opt.nthreads);
    detail::scale_sample(in, opt.scale, opt.nthreads);
    if (!sample_fits_levels(in.width(), in.height(), opt.levels)) {
        error = "levels=" + std::to_string(opt.levels) + " is too many for the sample ("
            + std::to_string(in.width()) + "x" + std::to_string(in.height())
            + "): it needs about 7 x 2^(levels-1) = " + std::to_string(7 << (opt.levels - 1))
            + " pixels a side";
        return false;
    }

    SurfaceMesh mesh;
    std::string why;
    if (!detail::read_surface_mesh(options.mesh, mesh, why)) {
        error = mesh_error(options.mesh, why);
        return false;
    }
    const FaceShapes shapes = face_shapes(mesh);
    const size_t remesh_to = options.remesh                     ? size_t(*options.remesh)
        : shapes.even() || mesh.faces.size() < kAutoRemeshFaces ? 0
                                                                : mesh.faces.size();
    // remesh=auto may try up to 20% more faces (below).
    const size_t base_faces
        = remesh_to ? (options.remesh ? remesh_to : remesh_to * 6 / 5) : mesh.faces.size();
    const double finest = double(base_faces) * double(uint64_t(1) << (2 * (opt.levels - 1)));
    const std::string what = "levels=" + std::to_string(opt.levels) + " on "
        + std::to_string(base_faces) + " faces (" + std::to_string(uint64_t(finest))
        + " at the finest level)";
    if (finest > double(detail::kMaxMeshElements)) {
        error = what + " : more than " + std::to_string(detail::kMaxMeshElements)
            + " faces; use fewer levels or remesh= to fewer faces";
        return false;
    }
    if (!check_memory(surface_memory_estimate(finest, in.width(), in.height(), in.nchannels(), opt),
            what, error))
        return false;
    // The bake's size is checked before the synthesis, for the UDIM tiles it will make.
    const bool bake = !mesh.uvs.empty() && options.bake_width && options.bake_height;
    if (bake) {
        const std::string size
            = std::to_string(options.bake_width) + "x" + std::to_string(options.bake_height);
        for (const Imath::V2f& uv : mesh.uvs)
            if (!(uv.x >= 0.0f && uv.x <= 10.0f && uv.y >= 0.0f && uv.y <= 100.0f)) {
                error = mesh_error(
                    options.mesh, "has UVs outside u 0..10, v 0..100 (the UDIM tiles 1001..1999)");
                return false;
            }
        const size_t tiles = detail::bake_tiles(mesh).size();
        const double values = double(options.bake_width) * double(options.bake_height)
            * double(in.nchannels()) * double(tiles);
        if (values > double(detail::kMaxBakeValues)) {
            error = option_error("bake", size,
                "too large: " + std::to_string(tiles) + " UDIM tiles of "
                    + std::to_string(in.nchannels()) + " channels would hold over "
                    + std::to_string(detail::kMaxBakeValues) + " values");
            return false;
        }
        if (!check_memory(size_t(values * detail::kBakeBytesPerValue),
                "bake=" + size + " (" + std::to_string(tiles) + " UDIM tile"
                    + (tiles == 1 ? "" : "s") + ")",
                error))
            return false;
    }

    // A regular grid of right triangles with edges near the target length is a fixed point
    // of the remesher (every valence is already 6): remesh=auto then asks for 10% and 20%
    // more faces, which makes it move.
    SurfaceMesh remeshed;
    for (int attempt = 0; remesh_to && attempt < (options.remesh ? 1 : 3); ++attempt) {
        if (!detail::remesh_isotropic(
                mesh, remesh_to + remesh_to * size_t(attempt) / 10, remeshed, why)) {
            error = option_error(
                "remesh", options.remesh ? std::to_string(*options.remesh) : "auto", why);
            return false;
        }
        if (face_shapes(remeshed).even())
            break;
    }
    const SurfaceMesh& grown = remesh_to ? remeshed : mesh;
    detail::FaceLevel base;
    base.vertices = grown.vertices;
    base.faces = grown.faces;
    detail::finish_level(base);
    detail::SurfaceSynthesis synthesis;
    if (!detail::synthesize_on_surface(
            in.channels, std::move(base), opt, synthesis, error, options.boundary))
        return false;

    const detail::FaceLevel& level = synthesis.pyramid.levels.back();
    if (bake) {
        detail::UvBakeOptions settings;
        settings.width = options.bake_width;
        settings.height = options.bake_height;
        settings.base_is_uv_mesh = remesh_to == 0;
        settings.nthreads = opt.nthreads;
        detail::UvBake baked;
        if (!detail::bake_uv_texture(
                mesh, synthesis.pyramid, synthesis.colours, settings, baked, why)) {
            error = option_error("bake",
                std::to_string(options.bake_width) + "x" + std::to_string(options.bake_height),
                why);
            return false;
        }
        for (detail::UvBakeTile& tile : baked.tiles) {
            PlanarImage image;
            image.channels = std::move(tile.channels);
            image.channel_names = in.channel_names;
            image.alpha_channel = in.alpha_channel;
            OIIO::ImageBuf buf;
            imagebuf_from_planes(image, buf, true);
            out.bake.emplace_back(tile.udim, std::move(buf));
        }
        out.bake_coverage = baked.covered_fraction;
    }
    out.vertices.resize(level.vertices.size());
    for (size_t v = 0; v < level.vertices.size(); ++v)
        out.vertices[v] = { level.vertices[v].x, level.vertices[v].y, level.vertices[v].z };
    out.faces = level.faces;
    out.channelnames = in.channel_names;
    out.colours = std::move(synthesis.colours);
    out.base_faces = synthesis.pyramid.levels.front().size();
    out.colour_conflicts = synthesis.pyramid.colour_conflicts;
    out.input_shapes = shapes;
    out.remeshed_to = remesh_to ? remeshed.faces.size() : 0;
    return true;
}

} // namespace

bool synthesize_surface(SurfaceTexture& out, const OIIO::ImageBuf& sample,
    const SurfaceOptions& options, std::string& error)
{
    out = SurfaceTexture();
    const bool ok = detail::guarded(
        error, "synthesize_surface", [&] { return grow(out, sample, options, error); });
    if (!ok)
        out = SurfaceTexture();
    return ok;
}

bool write_surface_ply(const std::string& path, const SurfaceTexture& texture,
    const std::vector<std::array<uint8_t, 3>>* display_rgb, std::string& error)
{
    std::vector<Imath::V3f> vertices(texture.vertices.size());
    for (size_t v = 0; v < vertices.size(); ++v)
        vertices[v] = { texture.vertices[v][0], texture.vertices[v][1], texture.vertices[v][2] };
    std::vector<std::string> names;
    for (const std::string& n : texture.channelnames) {
        // PLY property names: letters, digits and '_' (e.g. "R" stays, "diffuse.R" becomes
        // "diffuse_R").
        std::string s = n;
        for (char& c : s)
            if (!std::isalnum(static_cast<unsigned char>(c)))
                c = '_';
        names.push_back(s);
    }
    return detail::guarded(error, "write_surface_ply", [&] {
        return detail::write_face_colour_ply(
            path, vertices, texture.faces, texture.colours, names, display_rgb, error);
    });
}

} // namespace texsyn
