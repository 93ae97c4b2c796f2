// SPDX-License-Identifier: Apache-2.0
// The UV bake (uv_bake_pvt.h): conservative rasterisation of the UV triangles of each UDIM
// tile, texel -> base face -> finest face by the subdivision's midpoint parameterisation,
// per-vertex colours interpolated linearly, and padding by an exact nearest-covered-texel
// transform.
#include "uv_bake_pvt.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <new>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "closest_point_pvt.h"

namespace texsyn::detail {

namespace {

using Imath::V2d;
using Imath::V3d;

// Rows of texels rasterised by one task: each texel belongs to one band, so the bands'
// results do not depend on how they are scheduled.
constexpr int kBandRows = 16;

double cross(const V2d& a, const V2d& b)
{
    return a.x * b.y - a.y * b.x;
}

// The barycentric coordinates (for a, b, c) of the point of triangle abc closest to p.
V3d closest_barycentric(const V2d& p, const V2d& a, const V2d& b, const V2d& c)
{
    V3d bary;
    closest_on_triangle(p, a, b, c, bary);
    return bary;
}

// The UV corners of face f.
std::array<V2d, 3> face_uv(const SurfaceMesh& mesh, size_t f)
{
    std::array<V2d, 3> t;
    for (size_t k = 0; k < 3; ++k) {
        const Imath::V2f& uv = mesh.uvs[mesh.face_uvs[f][k]];
        t[k] = V2d(uv.x, uv.y);
    }
    return t;
}

// Whether a UV triangle has area enough to bake: slivers below 1e-12 of their longest edge
// squared have no usable barycentric coordinates, and their neighbours cover their texels.
bool bakeable(const std::array<V2d, 3>& t)
{
    const double longest
        = std::max({ (t[1] - t[0]).length2(), (t[2] - t[1]).length2(), (t[0] - t[2]).length2() });
    return std::abs(cross(t[1] - t[0], t[2] - t[0])) > 1e-12 * longest;
}

// The tiles a UV range overlaps with positive length: [floor(lo), ceil(hi) - 1].
std::pair<int, int> tile_range(double lo, double hi, int last)
{
    const int a = std::clamp(int(std::floor(lo)), 0, last);
    const int b = std::clamp(int(std::ceil(hi)) - 1, a, last);
    return { a, b };
}

// A UV triangle in the texel units of one tile (x right, y down, texel (x, y) the square
// [x, x + 1] x [y, y + 1]), with its edges' outward normals for the separating-axis test.
struct TexelTriangle {
    std::array<V2d, 3> p;
    std::array<V2d, 3> outward;

    TexelTriangle(const std::array<V2d, 3>& uv, int u_tile, int v_tile, int width, int height)
    {
        for (size_t k = 0; k < 3; ++k)
            p[k] = V2d((uv[k].x - u_tile) * width, (v_tile + 1 - uv[k].y) * height);
        const double side = cross(p[1] - p[0], p[2] - p[0]) > 0 ? 1.0 : -1.0;
        for (size_t k = 0; k < 3; ++k) {
            const V2d e = p[(k + 1) % 3] - p[k];
            outward[k] = V2d(e.y, -e.x) * side;
        }
    }

    // Whether the closed texel square centred on c meets the triangle (the bounding boxes
    // are known to meet: only the edge normals remain to be tried as separating axes).
    bool meets_square(const V2d& c) const
    {
        for (size_t k = 0; k < 3; ++k) {
            const V2d& n = outward[k];
            if ((n ^ (c - p[k])) - 0.5 * (std::abs(n.x) + std::abs(n.y)) > 0)
                return false;
        }
        return true;
    }

    double distance2(const V2d& c) const
    {
        bool inside = true;
        for (size_t k = 0; k < 3 && inside; ++k)
            inside = (outward[k] ^ (c - p[k])) <= 0;
        if (inside)
            return 0.0;
        const V3d b = barycentric(c);
        return (p[0] * b.x + p[1] * b.y + p[2] * b.z - c).length2();
    }

    V3d barycentric(const V2d& c) const { return closest_barycentric(c, p[0], p[1], p[2]); }
};

// Texels of one tile: [lo, hi] columns and rows whose closed squares meet the triangle's
// bounding box, clipped to the tile (x <= X_max and x + 1 >= X_min).
struct TexelBox {
    int x0, x1, y0, y1;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

TexelBox texel_box(const TexelTriangle& t, int width, int height)
{
    const double xmin = std::min({ t.p[0].x, t.p[1].x, t.p[2].x });
    const double xmax = std::max({ t.p[0].x, t.p[1].x, t.p[2].x });
    const double ymin = std::min({ t.p[0].y, t.p[1].y, t.p[2].y });
    const double ymax = std::max({ t.p[0].y, t.p[1].y, t.p[2].y });
    auto lo = [](double v, int n) { return int(std::clamp(std::ceil(v) - 1.0, 0.0, double(n))); };
    auto hi = [](double v, int n) { return int(std::clamp(std::floor(v), -1.0, double(n - 1))); };
    return { lo(xmin, width), hi(xmax, width), lo(ymin, height), hi(ymax, height) };
}

// Felzenszwalb & Huttenlocher's exact Euclidean distance transform, keeping the argument:
// each uncovered texel takes every channel of the nearest covered texel. Ties go to the
// upper row within a column, then the leftmost parabola, the same at any thread count.
void pad_tile(std::vector<Plane>& channels, const std::vector<uint8_t>& covered, int nthreads)
{
    const int w = channels[0].width(), h = channels[0].height();
    auto at = [w](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
    std::vector<int32_t> row_of(size_t(w) * size_t(h));
    OIIO::parallel_for_chunked(
        0, int64_t(w), 0,
        [&](int64_t begin, int64_t end) {
            for (int x = int(begin); x < int(end); ++x) {
                int last = -1;
                for (int y = 0; y < h; ++y) {
                    if (covered[at(x, y)])
                        last = y;
                    row_of[at(x, y)] = last;
                }
                int next = -1;
                for (int y = h - 1; y >= 0; --y) {
                    if (covered[at(x, y)])
                        next = y;
                    const int up = row_of[at(x, y)];
                    if (next >= 0 && (up < 0 || next - y < y - up))
                        row_of[at(x, y)] = next;
                }
            }
        },
        detail::split_every_item(nthreads));
    OIIO::parallel_for_chunked(
        0, int64_t(h), 0,
        [&](int64_t begin, int64_t end) {
            std::vector<int> v(static_cast<size_t>(w));
            std::vector<double> z(size_t(w) + 1);
            for (int y = int(begin); y < int(end); ++y) {
                auto f = [&](int x) {
                    const double d = double(row_of[at(x, y)] - y);
                    return d * d;
                };
                int k = -1; // the lower envelope of the parabolas of columns with a source
                for (int q = 0; q < w; ++q) {
                    if (row_of[at(q, y)] < 0)
                        continue;
                    double s = -std::numeric_limits<double>::infinity();
                    while (k >= 0) {
                        const int r = v[size_t(k)];
                        s = ((f(q) + double(q) * q) - (f(r) + double(r) * r)) / (2.0 * (q - r));
                        if (s > z[size_t(k)])
                            break;
                        --k;
                    }
                    if (k < 0)
                        s = -std::numeric_limits<double>::infinity();
                    ++k;
                    v[size_t(k)] = q;
                    z[size_t(k)] = s;
                }
                if (k < 0)
                    continue; // no covered texel in the tile
                for (int x = 0, j = 0; x < w; ++x) {
                    while (j < k && z[size_t(j) + 1] <= double(x))
                        ++j;
                    if (covered[at(x, y)])
                        continue;
                    const size_t src = at(v[size_t(j)], row_of[at(v[size_t(j)], y)]);
                    for (Plane& c : channels)
                        c.data()[at(x, y)] = c.data()[src];
                }
            }
        },
        detail::split_every_item(nthreads));
}

// Everything a tile's texels are computed from.
struct BakeContext {
    const SurfaceMesh& uv_mesh;
    const FacePyramid& pyramid;
    const FaceValues& vertex_values;   // [channel][vertex of the finest level]
    const SurfaceProjector* projector; // null when the base is the UV mesh
    const UvBakeOptions& opt;
};

// The colour of the UV mesh's face f at barycentric coordinates b.
void texel_colour(const BakeContext& ctx, uint32_t f, const V3d& b, std::vector<float>& out)
{
    FacePoint p { f, b };
    if (ctx.projector) {
        const auto& corners = ctx.uv_mesh.faces[f];
        const Imath::V3f& a = ctx.uv_mesh.vertices[corners[0]];
        const Imath::V3f& e = ctx.uv_mesh.vertices[corners[1]];
        const Imath::V3f& c = ctx.uv_mesh.vertices[corners[2]];
        const Imath::V3f point(V3d(a) * b.x + V3d(e) * b.y + V3d(c) * b.z);
        const Imath::V3f normal = (e - a).cross(c - a);
        SurfacePoint s;
        if (!ctx.projector->closest_facing_point(point, normal, s))
            s = ctx.projector->closest_point(point);
        p = { s.face, V3d(s.barycentric) };
    }
    p = finest_face_point(ctx.pyramid, p);
    const auto& v = ctx.pyramid.levels.back().faces[p.face];
    for (size_t c = 0; c < out.size(); ++c) {
        // The first corner plus weighted differences: equal corners give that value exactly.
        const std::vector<float>& values = ctx.vertex_values[c];
        const double v0 = values[v[0]];
        out[c] = float(v0 + p.barycentric.y * (double(values[v[1]]) - v0)
            + p.barycentric.z * (double(values[v[2]]) - v0));
    }
}

void bake_tile(const BakeContext& ctx, const std::vector<uint32_t>& faces, UvBakeTile& tile)
{
    const int w = ctx.opt.width, h = ctx.opt.height;
    const size_t texels = size_t(w) * size_t(h);
    std::vector<TexelTriangle> triangles;
    std::vector<TexelBox> boxes;
    triangles.reserve(faces.size());
    boxes.reserve(faces.size());
    // The faces of each band of rows, in increasing face order (CSR).
    const int bands = (h + kBandRows - 1) / kBandRows;
    std::vector<size_t> band_start(size_t(bands) + 1, 0);
    for (uint32_t f : faces) {
        triangles.emplace_back(face_uv(ctx.uv_mesh, f), tile.u_tile, tile.v_tile, w, h);
        boxes.push_back(texel_box(triangles.back(), w, h));
        const TexelBox& b = boxes.back();
        if (!b.empty())
            for (int band = b.y0 / kBandRows; band <= b.y1 / kBandRows; ++band)
                ++band_start[size_t(band) + 1];
    }
    for (int band = 0; band < bands; ++band)
        band_start[size_t(band) + 1] += band_start[size_t(band)];
    std::vector<uint32_t> band_faces(band_start.back());
    std::vector<size_t> fill(band_start.begin(), band_start.end() - 1);
    for (size_t i = 0; i < faces.size(); ++i) {
        const TexelBox& b = boxes[i];
        if (!b.empty())
            for (int band = b.y0 / kBandRows; band <= b.y1 / kBandRows; ++band)
                band_faces[fill[size_t(band)]++] = uint32_t(i);
    }

    std::vector<uint32_t> nearest(texels, kNoFace); // index into `faces`
    std::vector<float> distance2(texels, std::numeric_limits<float>::infinity());
    OIIO::parallel_for(
        int64_t(0), int64_t(bands),
        [&](int64_t band) {
            const int row0 = int(band) * kBandRows, row1 = std::min(h, row0 + kBandRows);
            for (size_t j = band_start[size_t(band)]; j < band_start[size_t(band) + 1]; ++j) {
                const uint32_t i = band_faces[j];
                const TexelTriangle& t = triangles[i];
                const TexelBox& b = boxes[i];
                for (int y = std::max(row0, b.y0); y <= std::min(row1 - 1, b.y1); ++y)
                    for (int x = b.x0; x <= b.x1; ++x) {
                        const V2d c(x + 0.5, y + 0.5);
                        if (!t.meets_square(c))
                            continue;
                        const size_t k = size_t(y) * size_t(w) + size_t(x);
                        // Faces come in increasing order: the first of equals stays.
                        const float d = float(t.distance2(c));
                        if (d < distance2[k]) {
                            distance2[k] = d;
                            nearest[k] = i;
                        }
                    }
            }
        },
        detail::split_every_item(ctx.opt.nthreads));
    distance2 = std::vector<float>();

    const size_t nc = ctx.vertex_values.size();
    tile.channels.assign(nc, Plane(w, h, 0.0f));
    tile.covered.assign(texels, 0);
    OIIO::parallel_for_chunked(
        0, int64_t(h), 0,
        [&](int64_t begin, int64_t end) {
            std::vector<float> colour(nc);
            for (int y = int(begin); y < int(end); ++y)
                for (int x = 0; x < w; ++x) {
                    const size_t k = size_t(y) * size_t(w) + size_t(x);
                    if (nearest[k] == kNoFace)
                        continue;
                    const uint32_t i = nearest[k];
                    texel_colour(
                        ctx, faces[i], triangles[i].barycentric(V2d(x + 0.5, y + 0.5)), colour);
                    for (size_t c = 0; c < nc; ++c)
                        tile.channels[c].data()[k] = colour[c];
                    tile.covered[k] = 1;
                }
        },
        detail::split_every_item(ctx.opt.nthreads));
    tile.covered_texels = size_t(std::count(tile.covered.begin(), tile.covered.end(), 1));
    if (ctx.opt.pad)
        pad_tile(tile.channels, tile.covered, ctx.opt.nthreads);
}

bool check_inputs(const SurfaceMesh& uv_mesh, const FacePyramid& pyramid, const FaceValues& colours,
    const UvBakeOptions& opt, std::string& error)
{
    if (uv_mesh.uvs.empty() || uv_mesh.face_uvs.size() != uv_mesh.faces.size()) {
        error = "bake: the mesh has no UVs (one UV per face corner is needed)";
        return false;
    }
    if (opt.width < 1 || opt.width > kMaxBakeSide || opt.height < 1 || opt.height > kMaxBakeSide) {
        error = "bake=" + std::to_string(opt.width) + "x" + std::to_string(opt.height)
            + ": width and height must be 1.." + std::to_string(kMaxBakeSide);
        return false;
    }
    for (size_t i = 0; i < uv_mesh.uvs.size(); ++i) {
        const Imath::V2f& uv = uv_mesh.uvs[i];
        if (!(uv.x >= 0.0f && uv.x <= 10.0f && uv.y >= 0.0f && uv.y <= 100.0f)) {
            error = "bake: UV " + std::to_string(i + 1) + " is (" + std::to_string(uv.x) + ", "
                + std::to_string(uv.y) + "); u must be in 0..10 and v in 0..100 (UDIM tiles)";
            return false;
        }
    }
    for (const auto& corners : uv_mesh.face_uvs)
        for (uint32_t t : corners)
            if (t >= uv_mesh.uvs.size()) {
                error = "bake: a face's UV index " + std::to_string(t)
                    + " is out of range (the mesh has " + std::to_string(uv_mesh.uvs.size())
                    + " UVs)";
                return false;
            }
    if (pyramid.levels.empty() || colours.empty()) {
        error = "bake: nothing to bake (no synthesis levels or no colour channels)";
        return false;
    }
    for (size_t k = 0; k + 1 < pyramid.levels.size(); ++k)
        if (pyramid.levels[k].children.size() != pyramid.levels[k].size()) {
            error = "bake: synthesis level " + std::to_string(k) + " has no children";
            return false;
        }
    const FaceLevel& finest = pyramid.levels.back();
    for (size_t c = 0; c < colours.size(); ++c)
        if (colours[c].size() != finest.size()) {
            error = "bake: colour channel " + std::to_string(c) + " has "
                + std::to_string(colours[c].size()) + " values for " + std::to_string(finest.size())
                + " faces";
            return false;
        }
    if (opt.base_is_uv_mesh && pyramid.levels[0].faces != uv_mesh.faces) {
        error = "bake: the synthesis base is not the UV mesh (remesh=0 needs its faces, in order)";
        return false;
    }
    return true;
}

} // namespace

FacePoint finest_face_point(const FacePyramid& pyramid, FacePoint p)
{
    V3d b(std::max(p.barycentric.x, 0.0), std::max(p.barycentric.y, 0.0),
        std::max(p.barycentric.z, 0.0));
    const double sum = b.x + b.y + b.z;
    b = sum > 0 ? b / sum : V3d(1, 0, 0);
    for (size_t k = 0; k + 1 < pyramid.levels.size(); ++k) {
        // subdivide(): m0, m1, m2 on edges 01, 12, 20; the centre child is (m0, m1, m2),
        // corner child 1 + e is (v_e, m_e, m_(e+2)). In each, the coordinates are the
        // parent's rescaled about the child's corners.
        const auto& children = pyramid.levels[k].children[p.face];
        if (b.x >= 0.5) {
            p.face = children[1];
            b = V3d(2 * b.x - 1, 2 * b.y, 2 * b.z);
        } else if (b.y >= 0.5) {
            p.face = children[2];
            b = V3d(2 * b.y - 1, 2 * b.z, 2 * b.x);
        } else if (b.z >= 0.5) {
            p.face = children[3];
            b = V3d(2 * b.z - 1, 2 * b.x, 2 * b.y);
        } else {
            p.face = children[0];
            b = V3d(1 - 2 * b.z, 1 - 2 * b.x, 1 - 2 * b.y);
        }
    }
    p.barycentric = b;
    return p;
}

FaceValues vertex_colours(const FaceLevel& level, const FaceValues& values, int nthreads)
{
    const size_t nv = level.vertices.size();
    FaceValues out(values.size(), std::vector<float>(nv, 0.0f));
    OIIO::parallel_for_chunked(
        0, int64_t(nv), 0,
        [&](int64_t begin, int64_t end) {
            for (size_t v = size_t(begin); v < size_t(end); ++v) {
                const uint32_t first = level.vertex_face_start[v];
                const uint32_t last = level.vertex_face_start[v + 1];
                if (first == last)
                    continue;
                for (size_t c = 0; c < values.size(); ++c) {
                    const double ref = values[c][level.vertex_faces[first]];
                    double sum = 0.0, weights = 0.0;
                    for (uint32_t i = first; i < last; ++i) {
                        const uint32_t f = level.vertex_faces[i];
                        sum += double(level.area[f]) * (double(values[c][f]) - ref);
                        weights += double(level.area[f]);
                    }
                    out[c][v] = float(weights > 0 ? ref + sum / weights : ref);
                }
            }
        },
        detail::split_every_item(nthreads));
    return out;
}

std::map<int, std::vector<uint32_t>> bake_tiles(const SurfaceMesh& uv_mesh)
{
    std::map<int, std::vector<uint32_t>> tile_faces; // by UDIM
    for (size_t f = 0; f < uv_mesh.face_uvs.size(); ++f) {
        const std::array<V2d, 3> t = face_uv(uv_mesh, f);
        if (!bakeable(t))
            continue;
        const auto [u0, u1] = tile_range(
            std::min({ t[0].x, t[1].x, t[2].x }), std::max({ t[0].x, t[1].x, t[2].x }), 9);
        const auto [v0, v1] = tile_range(
            std::min({ t[0].y, t[1].y, t[2].y }), std::max({ t[0].y, t[1].y, t[2].y }), 99);
        for (int v = v0; v <= v1; ++v)
            for (int u = u0; u <= u1; ++u)
                tile_faces[1001 + u + 10 * v].push_back(uint32_t(f));
    }
    return tile_faces;
}

bool bake_uv_texture(const SurfaceMesh& uv_mesh, const FacePyramid& pyramid,
    const FaceValues& colours, const UvBakeOptions& opt, UvBake& out, std::string& error)
{
    out = UvBake();
    if (!check_inputs(uv_mesh, pyramid, colours, opt, error))
        return false;
    try {
        // The tiles first, so that the size is checked before texels are allocated.
        const std::map<int, std::vector<uint32_t>> tile_faces = bake_tiles(uv_mesh);
        const size_t per_tile = size_t(opt.width) * size_t(opt.height);
        if (tile_faces.empty()
            || per_tile
                > kMaxBakeValues / colours.size() / std::max<size_t>(1, tile_faces.size())) {
            error = tile_faces.empty() ? "bake: every UV triangle has zero area"
                                       : "bake=" + std::to_string(opt.width) + "x"
                    + std::to_string(opt.height) + ": " + std::to_string(tile_faces.size())
                    + " tiles of " + std::to_string(colours.size()) + " channels would exceed "
                    + std::to_string(kMaxBakeValues) + " values";
            return false;
        }

        std::unique_ptr<SurfaceMesh> base_mesh;
        std::unique_ptr<SurfaceProjector> projector;
        if (!opt.base_is_uv_mesh) {
            base_mesh = std::make_unique<SurfaceMesh>();
            base_mesh->vertices = pyramid.levels[0].vertices;
            base_mesh->faces = pyramid.levels[0].faces;
            projector = std::make_unique<SurfaceProjector>(*base_mesh);
        }
        const FaceValues vertex_values
            = vertex_colours(pyramid.levels.back(), colours, opt.nthreads);
        const BakeContext ctx { uv_mesh, pyramid, vertex_values, projector.get(), opt };
        size_t covered = 0;
        for (const auto& [udim, faces] : tile_faces) {
            UvBakeTile tile;
            tile.udim = udim;
            tile.u_tile = (udim - 1001) % 10;
            tile.v_tile = (udim - 1001) / 10;
            bake_tile(ctx, faces, tile);
            covered += tile.covered_texels;
            out.tiles.push_back(std::move(tile));
        }
        out.covered_fraction = double(covered) / (double(per_tile) * double(out.tiles.size()));
    } catch (const std::bad_alloc&) {
        out = UvBake();
        error = "bake=" + std::to_string(opt.width) + "x" + std::to_string(opt.height)
            + ": out of memory";
        return false;
    }
    return true;
}

} // namespace texsyn::detail
