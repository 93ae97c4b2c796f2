// SPDX-License-Identifier: Apache-2.0
// Castellanos & Williams on surfaces: the face pyramid (subdivision, two-colouring), the
// face-domain filters, the 2-distant stencil, and Algorithm 1 on a flat grid and a sphere.
#include <algorithm>
#include <cmath>
#include <set>

#include <OpenImageIO/Imath.h>

#include <gtest/gtest.h>

#include "surface/face_filter_pvt.h"
#include "surface/face_stencil_pvt.h"
#include "surface/surface_choosy_pvt.h"
#include "surface/surface_synthesis_pvt.h"

#include "test_metrics.h"
#include "test_samples.h"

using namespace texsyn;
using namespace texsyn::detail;
using namespace texsyn::test;

namespace {

// An icosahedron subdivided `times` times at edge midpoints pushed onto the unit sphere:
// a closed mesh with twelve vertices of valence 5.
FaceLevel icosphere(int times)
{
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    FaceLevel m;
    m.vertices
        = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t }, { 0, 1, t },
              { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
    m.faces = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
        { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
        { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
        { 9, 8, 1 } };
    finish_level(m);
    for (int i = 0; i < times; ++i) {
        FaceLevel finer = subdivide(m, EdgePoints::Midpoint);
        finer.children.clear();
        m = std::move(finer);
    }
    for (Imath::V3f& v : m.vertices)
        v.normalize();
    m.colour.clear();
    finish_level(m);
    return m;
}

FaceValues constant_values(size_t n, float value)
{
    return FaceValues(1, std::vector<float>(n, value));
}

} // namespace

TEST(FacePyramid, SubdivisionKeepsVerticesAndInheritsColours)
{
    FaceLevel base = icosphere(1);
    const std::vector<Imath::V3f> before = base.vertices;
    FacePyramid p = build_face_pyramid(std::move(base), 3, EdgePoints::Butterfly);
    ASSERT_EQ(p.levels.size(), 3u);
    EXPECT_EQ(p.levels[1].size(), 4 * p.levels[0].size());
    EXPECT_EQ(p.levels[2].size(), 16 * p.levels[0].size());
    for (size_t v = 0; v < before.size(); ++v) // an interpolating scheme
        EXPECT_EQ(p.levels[2].vertices[v], before[v]);
    for (size_t f = 0; f < p.levels[0].size(); ++f) {
        const auto& children = p.levels[0].children[f];
        EXPECT_EQ(p.levels[1].colour[children[0]], p.levels[0].colour[f]);
        for (int e = 1; e < 4; ++e) {
            EXPECT_EQ(p.levels[1].colour[children[size_t(e)]], 1 - p.levels[0].colour[f]);
            // The corner child's first corner is its parent's corner e - 1.
            EXPECT_EQ(
                p.levels[1].faces[children[size_t(e)]][0], p.levels[0].faces[f][size_t(e - 1)]);
        }
    }
    // The butterfly's new vertices stay near the sphere; midpoints would fall inside it.
    for (const Imath::V3f& v : p.levels[2].vertices)
        EXPECT_NEAR(v.length(), 1.0f, 0.02f);
    // Closed: every face has three neighbours at every level.
    for (const FaceLevel& level : p.levels)
        for (const auto& across : level.across)
            for (uint32_t g : across)
                EXPECT_NE(g, kNoFace);
}

TEST(FacePyramid, ButterflyIsTheMidpointOnAFlatGrid)
{
    FacePyramid flat = triangular_grid(32, 32, 1);
    FaceLevel& base = flat.levels[0];
    FaceLevel mid = subdivide(base, EdgePoints::Midpoint);
    FaceLevel fly = subdivide(base, EdgePoints::Butterfly);
    ASSERT_EQ(mid.vertices.size(), fly.vertices.size());
    // In the plane; away from the zigzag border (where the 4-point rule applies), exactly
    // the midpoints.
    Imath::V3f lo(1e30f), hi(-1e30f);
    for (const Imath::V3f& v : base.vertices)
        for (int i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], v[i]);
            hi[i] = std::max(hi[i], v[i]);
        }
    const float margin = 2.0f * float(base.mean_edge_length);
    size_t inside = 0;
    for (size_t v = 0; v < mid.vertices.size(); ++v) {
        EXPECT_NEAR(fly.vertices[v].z, 0.0f, 1e-6f);
        const Imath::V3f& m = mid.vertices[v];
        if (m.x > lo.x + margin && m.x < hi.x - margin && m.y > lo.y + margin
            && m.y < hi.y - margin) {
            EXPECT_LT((fly.vertices[v] - m).length(), 1e-4f) << v;
            ++inside;
        }
    }
    EXPECT_GT(inside, mid.vertices.size() / 3);
}

TEST(FacePyramid, TwoColouring)
{
    // The flat grid's interior vertices all have valence 6: a perfect colouring.
    FacePyramid flat = triangular_grid(64, 64, 3);
    EXPECT_EQ(flat.colour_conflicts, 0u);
    // The icosphere has twelve vertices of valence 5: some conflicts remain, and they are
    // counted right.
    FaceLevel sphere = icosphere(2);
    const size_t conflicts = two_colour(sphere);
    size_t counted = 0;
    for (size_t f = 0; f < sphere.size(); ++f)
        for (uint32_t g : sphere.across[f])
            counted += g > f && sphere.colour[g] == sphere.colour[f];
    EXPECT_EQ(conflicts, counted);
    EXPECT_GT(conflicts, 0u);
    EXPECT_LT(conflicts, sphere.size() / 4);
}

TEST(FaceFilter, ConstantsStayConstant)
{
    FacePyramid p = build_face_pyramid(icosphere(1), 3, EdgePoints::Butterfly);
    const FaceKernel kernel { p.levels[2].max_adjacent_distance, 1.0 };
    const FaceValues blurred
        = filter_faces(p.levels[2], constant_values(p.levels[2].size(), 0.7f), kernel, nullptr, 2);
    for (float v : blurred[0])
        EXPECT_NEAR(v, 0.7f, 1e-5f);
    // Γ normalisation: only half the children carry the value, the result is still it.
    const FaceValues up = project_faces(
        p.levels[1], p.levels[2], constant_values(p.levels[1].size(), 0.3f), kernel, 2);
    for (float v : up[0])
        EXPECT_NEAR(v, 0.3f, 1e-5f);
    const FaceValues down = reduce_faces(
        p.levels[1], p.levels[2], constant_values(p.levels[2].size(), 0.3f), kernel, 2);
    for (float v : down[0])
        EXPECT_NEAR(v, 0.3f, 1e-5f);
}

// Eq. 3-4 the slow way: Ω(i) flooded with a std::set, then the weighted mean over it.
TEST(FaceFilter, MatchesTheWeightedMeanOverAFloodedNeighbourhood)
{
    FacePyramid p = build_face_pyramid(icosphere(1), 3, EdgePoints::Butterfly);
    const FaceLevel& level = p.levels[2];
    const FaceKernel kernel { 2.0 * level.max_adjacent_distance, 1.3 };
    FaceValues values(2, std::vector<float>(level.size()));
    for (size_t f = 0; f < level.size(); ++f) {
        values[0][f] = float(std::sin(0.37 * double(f)));
        values[1][f] = float(f % 7);
    }
    for (const std::vector<uint8_t>* only :
        { (const std::vector<uint8_t>*)nullptr, &level.colour }) {
        const FaceValues fast = filter_faces(level, values, kernel, only, 2);
        for (uint32_t i = 0; i < level.size(); ++i) {
            std::set<uint32_t> omega { i };
            std::vector<uint32_t> todo { i };
            while (!todo.empty()) {
                const uint32_t j = todo.back();
                todo.pop_back();
                if (double((level.centroid[j] - level.centroid[i]).length()) * kernel.scale
                    > 3.0 * kernel.sigma)
                    continue;
                for (uint32_t g : level.across[j])
                    if (g != kNoFace && omega.insert(g).second)
                        todo.push_back(g);
            }
            double weights = 0.0, sum[2] = { 0.0, 0.0 };
            for (uint32_t j : omega) {
                const double r = double((level.centroid[j] - level.centroid[i]).length())
                    * kernel.scale / kernel.sigma;
                if (r > 3.0 || (only && !(*only)[j]))
                    continue;
                const double w = std::exp(-0.5 * r * r) * double(level.area[j]);
                weights += w;
                for (int c = 0; c < 2; ++c)
                    sum[c] += w * double(values[size_t(c)][j]);
            }
            // Double sums in another order: equal to float rounding.
            for (int c = 0; c < 2; ++c)
                EXPECT_NEAR(fast[size_t(c)][i], sum[c] / weights, 1e-5) << i << " " << c;
        }
    }
}

TEST(FaceStencil, RegularGridFillsEverySlotAtItsPlace)
{
    const StencilShape& shape = stencil_shape();
    int ones = 0;
    for (int r : shape.ring)
        ones += r == 1;
    EXPECT_EQ(ones, 12);
    for (const auto& perm : shape.permutation) {
        std::vector<int> sorted(perm.begin(), perm.end());
        std::sort(sorted.begin(), sorted.end());
        for (int s = 0; s < kStencilSlots; ++s)
            EXPECT_EQ(sorted[size_t(s)], s);
    }
    FacePyramid grid = triangular_grid(48, 48, 1);
    const FaceLevel& level = grid.levels[0];
    const FaceStencils stencils = face_stencils(level, 2);
    size_t whole = 0;
    for (size_t f = 0; f < level.size(); ++f) {
        if (!complete(stencils[f]))
            continue;
        ++whole;
        const auto& corner = level.faces[f];
        const Imath::V3f x = (level.vertices[corner[1]] - level.vertices[corner[0]]).normalized();
        const Imath::V3f y = level.normal[f].cross(x);
        for (int s = 0; s < kStencilSlots; ++s) {
            const Imath::V3f d = level.centroid[stencils[f][size_t(s)]] - level.centroid[f];
            const Imath::V2f p(d.dot(x), d.dot(y));
            const float unit = float(level.mean_edge_length);
            EXPECT_LT((p / unit - shape.position[size_t(s)]).length(), 1e-3f) << f << " " << s;
        }
    }
    // Every face but those within two rows or two faces of the border.
    EXPECT_GT(whole, level.size() / 2);
}

// Algorithm 1 on a sphere: the faces' colour histogram is the sample's (first-order
// statistics, §3.11), once the output has more faces than the sample has neighbourhoods.
TEST(SurfaceSynthesis, SphereKeepsTheSamplesHistogram)
{
    const std::vector<Plane> sample = planes_of(linear_crop("flowers.png", 64, 64)).channels;
    ChoosyOptions opt;
    opt.levels = 3;
    opt.seed = 5;
    SurfaceSynthesis out;
    std::string error;
    ASSERT_TRUE(synthesize_on_surface(sample, icosphere(4), opt, out, error)) << error;
    const FaceLevel& finest = out.pyramid.levels.back();
    EXPECT_EQ(finest.size(), 20u * 256u * 16u);
    ASSERT_EQ(out.colours.size(), sample.size());
    ASSERT_EQ(out.colours[0].size(), finest.size());
    for (size_t c = 0; c < sample.size(); ++c)
        EXPECT_LT(area_weighted_w1(out.colours[c], finest.area, sample[c]), 0.02) << c;
}

TEST(SurfaceSynthesis, SameSeedSameColoursAtAnyThreadCount)
{
    const std::vector<Plane> sample = planes_of(linear_crop("flowers.png", 48, 48)).channels;
    ChoosyOptions opt;
    opt.levels = 3;
    opt.seed = 9;
    opt.iterations = { 2 };
    SurfaceSynthesis a, b, c;
    std::string error;
    opt.nthreads = 1;
    ASSERT_TRUE(synthesize_on_surface(sample, icosphere(2), opt, a, error)) << error;
    opt.nthreads = 2;
    ASSERT_TRUE(synthesize_on_surface(sample, icosphere(2), opt, b, error)) << error;
    EXPECT_EQ(a.colours, b.colours);
    opt.seed = 10;
    ASSERT_TRUE(synthesize_on_surface(sample, icosphere(2), opt, c, error)) << error;
    EXPECT_NE(a.colours, c.colours);
}

TEST(SurfaceSynthesis, TooSmallASampleIsRefused)
{
    const std::vector<Plane> sample = planes_of(linear_crop("flowers.png", 12, 12)).channels;
    ChoosyOptions opt;
    opt.levels = 4;
    SurfaceSynthesis out;
    std::string error;
    EXPECT_FALSE(synthesize_on_surface(sample, icosphere(1), opt, out, error));
    EXPECT_EQ(error.rfind("levels=4 is too many for the sample (12x12)", 0), 0u) << error;
}
