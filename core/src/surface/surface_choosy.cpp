// SPDX-License-Identifier: Apache-2.0
// Choosy sampling on a surface (surface_choosy_pvt.h): the sample's two grid pyramids,
// their neighbourhoods in three rotations, and a synthesis level as a ChoosyTarget.
#include "surface_choosy_pvt.h"

#include <cmath>

namespace texsyn::detail {

namespace {

constexpr uint32_t kGridBit = 31;

// `image` turned a quarter: (x, y) of the result is (y, height - 1 - x) of the image.
std::vector<Plane> quarter_turn(const std::vector<Plane>& image)
{
    std::vector<Plane> out;
    for (const Plane& p : image) {
        Plane q(p.height(), p.width());
        for (int y = 0; y < q.height(); ++y)
            for (int x = 0; x < q.width(); ++x)
                q(x, y) = p(y, p.height() - 1 - x);
        out.push_back(std::move(q));
    }
    return out;
}

} // namespace

SurfaceAnalysis analyze_surface_sample(const std::vector<Plane>& sample, int levels,
    const std::vector<FaceKernel>& kernels, int nthreads)
{
    SurfaceAnalysis a;
    a.sites.resize(size_t(levels));
    for (uint32_t g = 0; g < 2; ++g) {
        const std::vector<Plane> image = g == 0 ? sample : quarter_turn(sample);
        a.grids[g] = triangular_grid(image[0].width(), image[0].height(), levels);
        const std::vector<FaceLevel>& grid = a.grids[g].levels;
        std::vector<FaceValues>& gaussian = a.gaussian[g];
        gaussian.resize(size_t(levels));
        gaussian.back() = sample_at_centroids(image, grid.back());
        for (int k = levels - 1; k > 0; --k)
            gaussian[size_t(k - 1)] = reduce_faces(grid[size_t(k - 1)], grid[size_t(k)],
                gaussian[size_t(k)], kernels[size_t(k)], nthreads);
        a.laplacian[g].resize(size_t(levels));
        for (int k = 1; k < levels; ++k) {
            FaceValues l = project_faces(grid[size_t(k - 1)], grid[size_t(k)],
                gaussian[size_t(k - 1)], kernels[size_t(k)], nthreads);
            for (size_t c = 0; c < l.size(); ++c)
                for (size_t f = 0; f < l[c].size(); ++f)
                    l[c][f] = gaussian[size_t(k)][c][f] - l[c][f];
            a.laplacian[g][size_t(k)] = std::move(l);
        }
        for (int k = 0; k < levels; ++k) {
            a.stencils[g].push_back(face_stencils(grid[size_t(k)], nthreads));
            const FaceStencils& stencils = a.stencils[g].back();
            for (uint32_t f = 0; f < stencils.size(); ++f)
                if (complete(stencils[f]))
                    a.sites[size_t(k)].push_back(g << kGridBit | f);
        }
    }
    return a;
}

std::array<float, kStencilSlots> stencil_weights(double edge, double sigma)
{
    std::array<float, kStencilSlots> beta {};
    const StencilShape& shape = stencil_shape();
    for (int s = 0; s < kStencilSlots; ++s) {
        const double d = double(shape.position[size_t(s)].length()) * edge / (1.3 * sigma);
        beta[size_t(s)] = float(std::exp(-0.5 * d * d));
    }
    return beta;
}

AnalysisPoints surface_points(
    const SurfaceAnalysis& analysis, int level, const std::array<float, kStencilSlots>& weights)
{
    const std::vector<uint32_t>& sites = analysis.sites[size_t(level)];
    const size_t nc = analysis.gaussian[0][0].size();
    AnalysisPoints points;
    points.orientations = 3;
    points.count = sites.size() * 3;
    points.dim = int(kStencilSlots * nc);
    points.vector = [&analysis, &sites, weights, level, nc](size_t p, float* out) {
        const uint32_t site = sites[p / 3];
        const uint32_t g = site >> kGridBit, f = site & ((1u << kGridBit) - 1);
        const auto& permutation = stencil_shape().permutation[p % 3];
        const auto& slots = analysis.stencils[g][size_t(level)][f];
        const FaceValues& values = analysis.gaussian[g][size_t(level)];
        for (int s = 0; s < kStencilSlots; ++s) {
            const size_t to = size_t(permutation[size_t(s)]);
            for (size_t c = 0; c < nc; ++c)
                out[to * nc + c] = weights[to] * values[c][slots[size_t(s)]];
        }
    };
    return points;
}

namespace {

// The faces whose empty slots count as beyond the boundary: those with a boundary vertex
// among the corners of the face or of a face in its stencil. Elsewhere an empty slot is an
// irregular vertex, where the surface closes up. Empty on a closed mesh.
std::vector<uint8_t> wildcard_sites(const FaceLevel& level, const FaceStencils& stencils)
{
    std::vector<uint8_t> on_boundary(level.vertices.size(), 0);
    bool any = false;
    for (size_t f = 0; f < level.size(); ++f)
        for (uint32_t e = 0; e < 3; ++e)
            if (level.across[f][e] == kNoFace) {
                on_boundary[level.faces[f][e]] = on_boundary[level.faces[f][(e + 1) % 3]] = 1;
                any = true;
            }
    if (!any)
        return {};
    const auto touches = [&](uint32_t f) {
        const auto& v = level.faces[f];
        return on_boundary[v[0]] || on_boundary[v[1]] || on_boundary[v[2]];
    };
    std::vector<uint8_t> wild(level.size(), 0);
    for (uint32_t f = 0; f < uint32_t(level.size()); ++f) {
        bool near = touches(f);
        for (uint32_t g : stencils[f])
            near = near || (g != kNoFace && touches(g));
        wild[f] = uint8_t(near && !complete(stencils[f]));
    }
    return wild;
}

class SurfaceTarget final : public ChoosyTarget {
public:
    SurfaceTarget(SurfaceLevel& out, const SurfaceAnalysis& analysis, int level,
        const std::array<float, kStencilSlots>& weights, bool wildcards)
        : m_out(out)
        , m_analysis(analysis)
        , m_level(size_t(level))
        , m_weights(weights)
        , m_wild(wildcards ? wildcard_sites(*out.geometry, *out.stencils) : std::vector<uint8_t>())
    { }

    size_t sites() const override { return m_out.geometry->size(); }
    int dim() const override { return int(kStencilSlots * m_out.gaussian.size()); }
    size_t max_neighbors() const override { return kStencilSlots; }

    void query(size_t site, float* out) const override
    {
        const auto& slots = (*m_out.stencils)[site];
        const size_t nc = m_out.gaussian.size();
        for (size_t s = 0; s < size_t(kStencilSlots); ++s) {
            const size_t face = slots[s] == kNoFace ? site : slots[s];
            for (size_t c = 0; c < nc; ++c)
                out[s * nc + c] = m_weights[s] * m_out.gaussian[c][face];
        }
    }

    size_t neighbors(size_t site, size_t* out) const override
    {
        size_t n = 0;
        for (uint32_t face : (*m_out.stencils)[site])
            if (face != kNoFace)
                out[n++] = face;
        return n;
    }

    size_t hints(size_t, uint32_t*) const override { return 0; }

    bool wildcards(size_t site, float* mask) const override
    {
        if (m_wild.empty() || !m_wild[site])
            return false;
        const auto& slots = (*m_out.stencils)[site];
        const size_t nc = m_out.gaussian.size();
        for (size_t s = 0; s < size_t(kStencilSlots); ++s)
            for (size_t c = 0; c < nc; ++c)
                mask[s * nc + c] = slots[s] == kNoFace ? 0.0f : 1.0f;
        return true;
    }

    void apply(size_t site, uint32_t point) override
    {
        const uint32_t a = m_analysis.sites[m_level][point / 3];
        const uint32_t g = a >> kGridBit, f = a & ((1u << kGridBit) - 1);
        const uint32_t r = point % 3;
        const size_t nc = m_out.gaussian.size();
        for (size_t c = 0; c < nc; ++c)
            m_out.gaussian[c][site] = m_analysis.gaussian[g][m_level][c][f];
        m_out.source[site] = point / 3;
        if (m_out.children.empty())
            return;
        // Synthesis corner e is the sample face's corner e + r in the frame they matched in.
        const auto& mine = m_out.geometry->children[site];
        const auto& theirs = m_analysis.grids[g].levels[m_level].children[f];
        const FaceValues& laplacian = m_analysis.laplacian[g][m_level + 1];
        for (uint32_t e = 0; e < 4; ++e) {
            const uint32_t from = e == 0 ? theirs[0] : theirs[1 + (e - 1 + r) % 3];
            for (size_t c = 0; c < nc; ++c)
                m_out.children[c][mine[e]] = laplacian[c][from];
        }
    }

private:
    SurfaceLevel& m_out;
    const SurfaceAnalysis& m_analysis;
    size_t m_level;
    std::array<float, kStencilSlots> m_weights;
    std::vector<uint8_t> m_wild; // per site: 1 if its empty slots are wildcards
};

} // namespace

std::unique_ptr<ChoosyTarget> make_surface_target(SurfaceLevel& out,
    const SurfaceAnalysis& analysis, int level, const std::array<float, kStencilSlots>& weights,
    bool wildcards)
{
    return std::make_unique<SurfaceTarget>(out, analysis, level, weights, wildcards);
}

} // namespace texsyn::detail
