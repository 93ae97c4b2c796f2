// SPDX-License-Identifier: Apache-2.0
// The UV bake of a texture grown on a mesh (issue #17): the descent through the
// subdivision, exact constants, padding from the nearest covered texel, UDIM tiles,
// refusals, determinism, and continuity across torus_uv's UV seams.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include <OpenImageIO/Imath.h>

#include <gtest/gtest.h>

#include "surface/surface_synthesis_pvt.h"
#include "surface/uv_bake_pvt.h"

#include "test_samples.h"

using namespace texsyn;
using namespace texsyn::detail;
using namespace texsyn::test;

namespace {

SurfaceMesh bundled(const std::string& name)
{
    SurfaceMesh mesh;
    std::string error;
    EXPECT_TRUE(
        read_surface_mesh(std::string(TEXSYN_SOURCE_DIR) + "/data/meshes/" + name, mesh, error))
        << error;
    return mesh;
}

FaceLevel level_of(const SurfaceMesh& mesh)
{
    FaceLevel level;
    level.vertices = mesh.vertices;
    level.faces = mesh.faces;
    finish_level(level);
    return level;
}

// A deterministic stream of numbers in [0, 1).
struct Lcg {
    uint64_t state = 0x9e3779b97f4a7c15ull;
    double next()
    {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) / double(uint64_t(1) << 53);
    }
};

// Brute force: the UV face containing `uv` (largest smallest barycentric coordinate) and
// its barycentric coordinates.
FacePoint uv_face_point(const SurfaceMesh& mesh, const Imath::V2d& uv)
{
    FacePoint best;
    double best_min = -std::numeric_limits<double>::infinity();
    for (size_t f = 0; f < mesh.faces.size(); ++f) {
        Imath::V2d t[3];
        for (size_t k = 0; k < 3; ++k)
            t[k] = Imath::V2d(mesh.uvs[mesh.face_uvs[f][k]].x, mesh.uvs[mesh.face_uvs[f][k]].y);
        const Imath::V2d e1 = t[1] - t[0], e2 = t[2] - t[0], d = uv - t[0];
        const double det = e1.x * e2.y - e1.y * e2.x;
        const double b1 = (d.x * e2.y - d.y * e2.x) / det, b2 = (e1.x * d.y - e1.y * d.x) / det;
        const Imath::V3d b(1 - b1 - b2, b1, b2);
        const double m = std::min({ b.x, b.y, b.z });
        if (m > best_min) {
            best_min = m;
            best = { uint32_t(f), b };
        }
    }
    return best;
}

Imath::V3d position(const std::vector<Imath::V3f>& vertices,
    const std::vector<std::array<uint32_t, 3>>& faces, const FacePoint& p)
{
    const auto& c = faces[p.face];
    return Imath::V3d(vertices[c[0]]) * p.barycentric.x
        + Imath::V3d(vertices[c[1]]) * p.barycentric.y
        + Imath::V3d(vertices[c[2]]) * p.barycentric.z;
}

// The UV of texel (x, y) of a tile.
Imath::V2d texel_uv(const UvBakeTile& tile, int x, int y)
{
    const Plane& p = tile.channels[0];
    return Imath::V2d(
        tile.u_tile + (x + 0.5) / p.width(), tile.v_tile + 1 - (y + 0.5) / p.height());
}

// Two unit squares side by side in the plane z = 0 (facing +z), each with its own UV
// island in [0.1, 0.9]^2 of its own tile: tiles 1001 and 1002.
SurfaceMesh two_tile_strip()
{
    SurfaceMesh m;
    m.vertices = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 2, 1, 0 } };
    m.faces = { { 0, 1, 4 }, { 0, 4, 3 }, { 1, 2, 5 }, { 1, 5, 4 } };
    for (int tile = 0; tile < 2; ++tile)
        for (int corner = 0; corner < 4; ++corner) { // (0,0) (1,0) (0,1) (1,1)
            const float x = float(corner & 1), y = float(corner >> 1);
            m.uvs.emplace_back(float(tile) + 0.1f + 0.8f * x, 0.1f + 0.8f * y);
        }
    m.face_uvs = { { 0, 1, 3 }, { 0, 3, 2 }, { 4, 5, 7 }, { 4, 7, 6 } };
    return m;
}

// One texture grown on torus_uv itself (remesh=0) and one on its remeshed version, shared
// by the tests that need a real synthesis.
class TorusBake : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        s_torus = new SurfaceMesh(bundled("torus_uv.obj"));
        const std::vector<Plane> sample = planes_of(linear_crop("flowers.png", 64, 64)).channels;
        ChoosyOptions opt;
        opt.levels = 3;
        opt.seed = 17;
        std::string error;
        s_same = new SurfaceSynthesis;
        ASSERT_TRUE(synthesize_on_surface(sample, level_of(*s_torus), opt, *s_same, error))
            << error;
        s_remeshed_mesh = new SurfaceMesh;
        ASSERT_TRUE(remesh_isotropic(*s_torus, 2000, *s_remeshed_mesh, error, 5)) << error;
        s_remeshed = new SurfaceSynthesis;
        ASSERT_TRUE(
            synthesize_on_surface(sample, level_of(*s_remeshed_mesh), opt, *s_remeshed, error))
            << error;
    }
    static void TearDownTestSuite()
    {
        delete s_torus;
        delete s_same;
        delete s_remeshed;
        delete s_remeshed_mesh;
    }

    static UvBake bake(const SurfaceSynthesis& s, bool same, int size, int nthreads = 0)
    {
        UvBakeOptions opt;
        opt.width = opt.height = size;
        opt.base_is_uv_mesh = same;
        opt.nthreads = nthreads;
        UvBake out;
        std::string error;
        EXPECT_TRUE(bake_uv_texture(*s_torus, s.pyramid, s.colours, opt, out, error)) << error;
        return out;
    }

    static SurfaceMesh* s_torus;
    static SurfaceSynthesis* s_same;
    static SurfaceSynthesis* s_remeshed;
    static SurfaceMesh* s_remeshed_mesh;
};

SurfaceMesh* TorusBake::s_torus = nullptr;
SurfaceSynthesis* TorusBake::s_same = nullptr;
SurfaceSynthesis* TorusBake::s_remeshed = nullptr;
SurfaceMesh* TorusBake::s_remeshed_mesh = nullptr;

// Mean over channels of |a - b| at two texels.
double texel_difference(const UvBakeTile& tile, int x0, int y0, int x1, int y1)
{
    double sum = 0.0;
    for (const Plane& c : tile.channels)
        sum += std::abs(double(c(x0, y0)) - double(c(x1, y1)));
    return sum / double(tile.channels.size());
}

// Mean over rows (or columns) and channels of the absolute colour difference between
// adjacent texel pairs: d[x] for columns x | x + 1 (d[W-1] for W-1 | 0, across torus_uv's
// u=0 seam), or for rows y | y + 1 (d[H-1] across the v=0 seam).
std::vector<double> pair_differences(const UvBakeTile& tile, bool columns)
{
    const int w = tile.channels[0].width(), h = tile.channels[0].height();
    const int n = columns ? w : h, m = columns ? h : w;
    std::vector<double> d(size_t(n), 0.0);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j)
            d[size_t(i)] += (columns ? texel_difference(tile, i, j, (i + 1) % w, j)
                                     : texel_difference(tile, j, i, j, (i + 1) % h))
                / m;
    return d;
}

// d[i] over the mean of the two pairs on either side, d[i-2], d[i-1], d[i+1], d[i+2]
// (circularly): how much pair i stands out from its neighbouring texel pairs.
double local_ratio(const std::vector<double>& d, size_t i)
{
    const size_t n = d.size();
    return 4.0 * d[i] / (d[(i + n - 2) % n] + d[(i + n - 1) % n] + d[(i + 1) % n] + d[(i + 2) % n]);
}

} // namespace

// On a midpoint-subdivided torus, the finest face and coordinates finest_face_point()
// returns are the same point of space as the base face and coordinates it was given.
TEST(UvBake, FinestFacePointIsTheSamePointOfTheMidpointSubdivision)
{
    const FacePyramid p
        = build_face_pyramid(level_of(bundled("torus_uv.obj")), 5, EdgePoints::Midpoint);
    const FaceLevel& base = p.levels[0];
    const FaceLevel& finest = p.levels.back();
    Lcg random;
    for (int i = 0; i < 2000; ++i) {
        const uint32_t f = uint32_t(random.next() * double(base.size()));
        double a = random.next(), b = random.next();
        if (a + b > 1) {
            a = 1 - a;
            b = 1 - b;
        }
        const FacePoint in { f, Imath::V3d(1 - a - b, a, b) };
        const FacePoint out = finest_face_point(p, in);
        ASSERT_LT(out.face, finest.size());
        // The finest face descends from f: 4^4 faces per base face, in blocks.
        EXPECT_EQ(out.face / 256u, f) << i;
        EXPECT_GE(std::min({ out.barycentric.x, out.barycentric.y, out.barycentric.z }), -1e-9);
        EXPECT_NEAR(out.barycentric.x + out.barycentric.y + out.barycentric.z, 1.0, 1e-9);
        // Float midpoints: a few ulps of the torus' unit size.
        const double d = (position(finest.vertices, finest.faces, out)
            - position(base.vertices, base.faces, in))
                             .length();
        EXPECT_LT(d, 1e-5) << i;
    }
}

// A colour constant on all faces comes back exactly in every texel; one constant on each
// base face's descendants comes back exactly wherever the finest face's vertices see only
// that base face (every base coordinate at least 1/2^(levels-1)), and elsewhere stays
// between the values around it (linear interpolation of area-weighted means).
TEST(UvBake, FaceConstantFieldsComeBackExactly)
{
    const SurfaceMesh torus = bundled("torus_uv.obj");
    const int levels = 4;
    const FacePyramid p = build_face_pyramid(level_of(torus), levels, EdgePoints::Butterfly);
    const size_t nf = p.levels.back().size();
    UvBakeOptions opt;
    opt.width = opt.height = 96;
    UvBake out;
    std::string error;
    const FaceValues constant { std::vector<float>(nf, 0.3f), std::vector<float>(nf, 0.7137f) };
    ASSERT_TRUE(bake_uv_texture(torus, p, constant, opt, out, error)) << error;
    ASSERT_EQ(out.tiles.size(), 1u);
    for (size_t c = 0; c < 2; ++c)
        for (size_t i = 0; i < out.tiles[0].channels[c].size(); ++i)
            ASSERT_EQ(out.tiles[0].channels[c].data()[i], constant[c][0]) << c << " " << i;

    FaceValues per_base(1, std::vector<float>(nf));
    for (size_t f = 0; f < nf; ++f)
        per_base[0][f] = 0.25f + float(f >> (2 * (levels - 1))) * 1e-3f; // the base ancestor
    ASSERT_TRUE(bake_uv_texture(torus, p, per_base, opt, out, error)) << error;
    const UvBakeTile& tile = out.tiles[0];
    const FaceLevel& base = p.levels[0];
    size_t exact = 0;
    for (int y = 0; y < opt.height; ++y)
        for (int x = 0; x < opt.width; ++x) {
            const FacePoint at = uv_face_point(torus, texel_uv(tile, x, y));
            const float value = tile.channels[0](x, y);
            const float own = per_base[0][size_t(at.face) << (2 * (levels - 1))];
            const double smallest
                = std::min({ at.barycentric.x, at.barycentric.y, at.barycentric.z });
            if (smallest > 1.0 / 8.0 + 1e-6) {
                EXPECT_EQ(value, own) << x << " " << y;
                ++exact;
                continue;
            }
            // Otherwise between the values of the base faces sharing a vertex with it.
            float lo = own, hi = own;
            for (uint32_t v : base.faces[at.face])
                for (uint32_t i = base.vertex_face_start[v]; i < base.vertex_face_start[v + 1];
                     ++i) {
                    const float other
                        = per_base[0][size_t(base.vertex_faces[i]) << (2 * (levels - 1))];
                    lo = std::min(lo, other);
                    hi = std::max(hi, other);
                }
            EXPECT_GE(value, lo) << x << " " << y;
            EXPECT_LE(value, hi) << x << " " << y;
        }
    EXPECT_GT(exact, size_t(opt.width * opt.height) / 8);
}

// UVs squeezed into part of the tile: padding fills every other texel with the values of
// a covered texel at the smallest distance (brute force), and leaves covered texels as
// they were without padding.
TEST(UvBake, PaddingCopiesTheNearestCoveredTexel)
{
    SurfaceMesh torus = bundled("torus_uv.obj");
    for (Imath::V2f& uv : torus.uvs)
        uv = Imath::V2f(0.05f + 0.6f * uv.x, 0.2f + 0.7f * uv.y);
    const FacePyramid p = build_face_pyramid(level_of(torus), 2, EdgePoints::Butterfly);
    const size_t nf = p.levels.back().size();
    FaceValues colours(2, std::vector<float>(nf));
    for (size_t f = 0; f < nf; ++f) {
        colours[0][f] = p.levels.back().centroid[f].x;
        colours[1][f] = p.levels.back().centroid[f].z;
    }
    UvBakeOptions opt;
    opt.width = 64;
    opt.height = 48;
    opt.pad = false;
    UvBake bare, padded;
    std::string error;
    ASSERT_TRUE(bake_uv_texture(torus, p, colours, opt, bare, error)) << error;
    opt.pad = true;
    ASSERT_TRUE(bake_uv_texture(torus, p, colours, opt, padded, error)) << error;
    ASSERT_EQ(padded.tiles.size(), 1u);
    const UvBakeTile& a = bare.tiles[0];
    const UvBakeTile& b = padded.tiles[0];
    EXPECT_EQ(a.covered, b.covered);
    EXPECT_EQ(b.covered_texels, size_t(std::count(b.covered.begin(), b.covered.end(), 1)));
    // Covered: the UV rectangle's texels and the ring of texels its edges cross.
    const double lo = 0.6 * 0.7, hi = (0.6 + 2.0 / 64) * (0.7 + 2.0 / 48);
    EXPECT_GE(padded.covered_fraction, lo);
    EXPECT_LE(padded.covered_fraction, hi);
    EXPECT_DOUBLE_EQ(padded.covered_fraction, double(b.covered_texels) / (64.0 * 48.0));
    const int w = opt.width, h = opt.height;
    size_t uncovered = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t k = size_t(y) * size_t(w) + size_t(x);
            if (b.covered[k]) {
                for (size_t c = 0; c < 2; ++c)
                    EXPECT_EQ(a.channels[c](x, y), b.channels[c](x, y)) << x << " " << y;
                continue;
            }
            ++uncovered;
            EXPECT_EQ(a.channels[0](x, y), 0.0f); // unpadded: nothing written
            int nearest = std::numeric_limits<int>::max();
            for (int sy = 0; sy < h; ++sy)
                for (int sx = 0; sx < w; ++sx)
                    if (b.covered[size_t(sy) * size_t(w) + size_t(sx)])
                        nearest = std::min(nearest, (sx - x) * (sx - x) + (sy - y) * (sy - y));
            bool found = false;
            for (int sy = 0; sy < h && !found; ++sy)
                for (int sx = 0; sx < w && !found; ++sx)
                    found = b.covered[size_t(sy) * size_t(w) + size_t(sx)]
                        && (sx - x) * (sx - x) + (sy - y) * (sy - y) == nearest
                        && b.channels[0](sx, sy) == b.channels[0](x, y)
                        && b.channels[1](sx, sy) == b.channels[1](x, y);
            EXPECT_TRUE(found) << x << " " << y;
        }
    EXPECT_GT(uncovered, size_t(w * h) / 3);
}

// UV islands in tiles 1001 and 1002: two tiles, in UDIM order, each showing its own square
// the right way up (row 0 is v = 1): a colour equal to the face centroid's x and y comes
// back as the texel's point of the plane, to within the finest faces' size.
TEST(UvBake, TwoUdimTilesHoldTheirOwnIslands)
{
    const SurfaceMesh strip = two_tile_strip();
    std::string error;
    ASSERT_TRUE(check_surface_mesh(strip, "strip", error)) << error;
    const FacePyramid p = build_face_pyramid(level_of(strip), 4, EdgePoints::Midpoint);
    const FaceLevel& finest = p.levels.back();
    FaceValues colours(2, std::vector<float>(finest.size()));
    for (size_t f = 0; f < finest.size(); ++f) {
        colours[0][f] = finest.centroid[f].x;
        colours[1][f] = finest.centroid[f].y;
    }
    UvBakeOptions opt;
    opt.width = 40;
    opt.height = 30;
    UvBake out;
    ASSERT_TRUE(bake_uv_texture(strip, p, colours, opt, out, error)) << error;
    ASSERT_EQ(out.tiles.size(), 2u);
    EXPECT_EQ(out.tiles[0].udim, 1001);
    EXPECT_EQ(out.tiles[1].udim, 1002);
    EXPECT_EQ(out.tiles[1].u_tile, 1);
    EXPECT_EQ(out.tiles[1].v_tile, 0);
    // Each island covers 0.8 x 0.8 of its tile plus the texels its edges cross.
    EXPECT_GE(out.covered_fraction, 0.64);
    EXPECT_LE(out.covered_fraction, (0.8 + 2.0 / 40) * (0.8 + 2.0 / 30));
    // Vertex means of a linear field are exact inside and biased by at most half a finest
    // face's leg (1/8 here) on the boundary (at the corners with two faces).
    const double tolerance = 1.0 / 16.0 + 1e-4;
    for (const UvBakeTile& tile : out.tiles) {
        EXPECT_EQ(tile.channels.size(), 2u);
        EXPECT_EQ(tile.channels[0].width(), 40);
        EXPECT_EQ(tile.channels[0].height(), 30);
        EXPECT_EQ(
            tile.covered_texels, size_t(std::count(tile.covered.begin(), tile.covered.end(), 1)));
        for (int y = 0; y < opt.height; ++y)
            for (int x = 0; x < opt.width; ++x) {
                // The nearest point of the island (covered texels straddle its edges;
                // padded ones copy the nearest covered texel, within a texel of it).
                const Imath::V2d uv = texel_uv(tile, x, y);
                const double local_u = std::clamp((uv.x - tile.u_tile - 0.1) / 0.8, 0.0, 1.0);
                const double local_v = std::clamp((uv.y - 0.1) / 0.8, 0.0, 1.0);
                const double texel = 1.0 / 0.8 / 30.0; // a texel, in plane units
                const bool covered = tile.covered[size_t(y) * 40 + size_t(x)] != 0;
                const double slack = covered ? tolerance : tolerance + 2.0 * texel;
                EXPECT_NEAR(tile.channels[0](x, y), tile.u_tile + local_u, slack) << x << " " << y;
                EXPECT_NEAR(tile.channels[1](x, y), local_v, slack) << x << " " << y;
            }
    }
}

// Issue #34: UVs reaching exactly 1.0 counted as four UDIM tiles in the memory estimate
// (an 8192x8192 bake estimated at 4.5 GB instead of 1.1 GB). A tile is counted where a UV
// triangle overlaps it with positive length, as the bake makes them.
TEST(UvBake, TilesAreThoseTheTrianglesOverlap)
{
    SurfaceMesh square = two_tile_strip();
    for (Imath::V2f& uv : square.uvs) // the first island fills its tile: 0..1 exactly
        if (uv.x < 1.0f)
            uv = Imath::V2f(uv.x < 0.5f ? 0.0f : 1.0f, uv.y < 0.5f ? 0.0f : 1.0f);
    auto udims = [](const SurfaceMesh& m) {
        std::vector<int> out;
        for (const auto& tile : bake_tiles(m))
            out.push_back(tile.first);
        return out;
    };
    EXPECT_EQ(udims(square), (std::vector<int> { 1001, 1002 }));
    square.face_uvs.resize(2); // the first island alone
    square.faces.resize(2);
    EXPECT_EQ(udims(square), (std::vector<int> { 1001 }));
    for (Imath::V2f& uv : square.uvs) // moved up one row, to 1..2 exactly
        uv.y += 1.0f;
    EXPECT_EQ(udims(square), (std::vector<int> { 1011 }));
    EXPECT_EQ(udims(bundled("torus_uv.obj")), (std::vector<int> { 1001 }));
}

TEST(UvBake, BadInputsAreRefusedWithOneLine)
{
    const SurfaceMesh strip = two_tile_strip();
    const FacePyramid p = build_face_pyramid(level_of(strip), 2, EdgePoints::Midpoint);
    const FaceValues colours(3, std::vector<float>(p.levels.back().size(), 0.5f));
    auto refused = [&](const SurfaceMesh& mesh, const FacePyramid& pyramid,
                       const FaceValues& values, const UvBakeOptions& opt) {
        UvBake out;
        out.tiles.resize(1);
        std::string error;
        EXPECT_FALSE(bake_uv_texture(mesh, pyramid, values, opt, out, error));
        EXPECT_TRUE(out.tiles.empty());
        EXPECT_EQ(error.find('\n'), std::string::npos) << error;
        return error;
    };
    UvBakeOptions opt;
    opt.width = opt.height = 64;

    SurfaceMesh no_uvs = strip;
    no_uvs.uvs.clear();
    no_uvs.face_uvs.clear();
    EXPECT_EQ(refused(no_uvs, p, colours, opt),
        "bake: the mesh has no UVs (one UV per face corner is needed)");

    UvBakeOptions bad = opt;
    bad.width = 0;
    EXPECT_EQ(refused(strip, p, colours, bad), "bake=0x64: width and height must be 1..65536");
    bad = opt;
    bad.height = 70000;
    EXPECT_EQ(refused(strip, p, colours, bad), "bake=64x70000: width and height must be 1..65536");
    bad = opt;
    bad.width = bad.height = 65536; // two tiles of 3 channels: 25.8e9 values
    EXPECT_EQ(refused(strip, p, colours, bad),
        "bake=65536x65536: 2 tiles of 3 channels would exceed 1073741824 values");

    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (const Imath::V2f& uv : { Imath::V2f(nan, 0.5f), Imath::V2f(10.5f, 0.5f),
             Imath::V2f(-0.25f, 0.5f), Imath::V2f(0.5f, -1.0f) }) {
        SurfaceMesh outside = strip;
        outside.uvs[2] = uv;
        EXPECT_EQ(refused(outside, p, colours, opt).rfind("bake: UV 3 is (", 0), 0u);
    }
    EXPECT_NE(refused(SurfaceMesh(strip), p, FaceValues(1, std::vector<float>(5)), opt)
                  .find("colour channel 0 has 5 values for 16 faces"),
        std::string::npos);
    EXPECT_EQ(refused(strip, FacePyramid(), colours, opt),
        "bake: nothing to bake (no synthesis levels or no colour channels)");

    SurfaceMesh flipped = strip; // another base: same vertices, faces in another order
    std::swap(flipped.faces[0], flipped.faces[1]);
    const FacePyramid other = build_face_pyramid(level_of(flipped), 2, EdgePoints::Midpoint);
    EXPECT_EQ(refused(strip, other, colours, opt),
        "bake: the synthesis base is not the UV mesh (remesh=0 needs its faces, in order)");
    // ... which is what base_is_uv_mesh = false is for.
    opt.base_is_uv_mesh = false;
    UvBake out;
    std::string error;
    EXPECT_TRUE(bake_uv_texture(strip, other, colours, opt, out, error)) << error;
}

// The seam test. Texels on either side of torus_uv's UV seams are neighbours on
// the surface (checked in 3-D). A field that is smooth on the surface (each face's
// centroid) changes across each seam no more than between the most distant interior
// neighbours of the same row or column. A synthesized texture's seam pairs stand out from
// their neighbouring interior pairs no more than the interior pairs do from theirs: the
// seam's local_ratio is at most the largest over all interior pairs, with the base the UV
// mesh itself and with a remeshed base.
TEST_F(TorusBake, ContinuousAcrossUvSeams)
{
    const int size = 256;
    const UvBake same = bake(*s_same, true, size);
    ASSERT_EQ(same.tiles.size(), 1u);
    const UvBakeTile& tile = same.tiles[0];
    EXPECT_EQ(tile.udim, 1001);
    EXPECT_EQ(tile.covered_texels, size_t(size * size)); // torus_uv's UVs fill the tile
    auto point = [&](int x, int y) {
        return position(
            s_torus->vertices, s_torus->faces, uv_face_point(*s_torus, texel_uv(tile, x, y)));
    };
    for (int y = 0; y < size; y += 16) {
        const double across = (point(0, y) - point(size - 1, y)).length();
        double inside = 0.0; // the farthest interior neighbours of the row
        for (int x = 0; x + 1 < size; ++x)
            inside = std::max(inside, (point(x, y) - point(x + 1, y)).length());
        EXPECT_LE(across, inside) << y;
    }

    for (const bool remeshed : { false, true }) {
        // The smooth field: every texel's value is a point of the finest mesh, near its own.
        const FacePyramid p = build_face_pyramid(
            level_of(remeshed ? *s_remeshed_mesh : *s_torus), 3, EdgePoints::Butterfly);
        FaceValues centroids(3, std::vector<float>(p.levels.back().size()));
        for (size_t f = 0; f < p.levels.back().size(); ++f)
            for (size_t c = 0; c < 3; ++c)
                centroids[c][f] = p.levels.back().centroid[f][int(c)];
        UvBakeOptions opt;
        opt.width = opt.height = size;
        opt.base_is_uv_mesh = !remeshed;
        UvBake smooth;
        std::string error;
        ASSERT_TRUE(bake_uv_texture(*s_torus, p, centroids, opt, smooth, error)) << error;
        const UvBakeTile& t = smooth.tiles[0];
        for (int i = 0; i < size; ++i) {
            double row = 0.0, column = 0.0;
            for (int j = 0; j + 1 < size; ++j) {
                row = std::max(row, texel_difference(t, j, i, j + 1, i));
                column = std::max(column, texel_difference(t, i, j, i, j + 1));
            }
            EXPECT_LE(texel_difference(t, 0, i, size - 1, i), row) << remeshed << " row " << i;
            EXPECT_LE(texel_difference(t, i, 0, i, size - 1), column)
                << remeshed << " column " << i;
        }

        const UvBake texture = remeshed ? bake(*s_remeshed, false, size) : same;
        for (const bool columns : { true, false }) {
            const std::vector<double> d = pair_differences(texture.tiles[0], columns);
            const size_t seam = d.size() - 1;
            double largest = 0.0, mean = 0.0;
            for (size_t i = 0; i < seam; ++i) {
                largest = std::max(largest, local_ratio(d, i));
                mean += d[i] / double(seam);
            }
            const double ratio = local_ratio(d, seam);
            std::printf("%s, %s seam: difference %.5f, interior mean %.5f, local ratio %.3f "
                        "(interior pairs: largest %.3f)\n",
                remeshed ? "remeshed base" : "base = UV mesh", columns ? "u=0" : "v=0", d[seam],
                mean, ratio, largest);
            EXPECT_LE(ratio, largest) << remeshed << " " << columns;
        }
        // The statistic can tell: column 0 against column W-1 half a turn around.
        double misaligned = 0.0;
        for (int y = 0; y < size; ++y)
            misaligned
                += texel_difference(texture.tiles[0], 0, y, size - 1, (y + size / 2) % size) / size;
        EXPECT_GT(misaligned, 2.0 * pair_differences(texture.tiles[0], true).back()) << remeshed;
    }
}

TEST_F(TorusBake, SameTexelsAtAnyThreadCount)
{
    for (const bool remeshed : { false, true }) {
        const SurfaceSynthesis& s = remeshed ? *s_remeshed : *s_same;
        const UvBake one = bake(s, !remeshed, 128, 1);
        const UvBake two = bake(s, !remeshed, 128, 2);
        ASSERT_EQ(one.tiles.size(), two.tiles.size());
        for (size_t t = 0; t < one.tiles.size(); ++t)
            for (size_t c = 0; c < one.tiles[t].channels.size(); ++c)
                EXPECT_TRUE(std::equal(one.tiles[t].channels[c].data(),
                    one.tiles[t].channels[c].data() + one.tiles[t].channels[c].size(),
                    two.tiles[t].channels[c].data()))
                    << remeshed << " " << c;
    }
}
