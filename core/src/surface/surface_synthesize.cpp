// SPDX-License-Identifier: Apache-2.0
// Algorithm 1 on a mesh (surface_synthesis_pvt.h): the synthesis pyramid by butterfly
// subdivision, the distance scale and kernel of each level (§3.10), the sample's analysis
// on the triangular grids, then choosy sampling coarse to fine with the Laplacian pyramid
// inverted level by level.
#include "surface_synthesis_pvt.h"

#include <cmath>

#include <texsyn/random.h>

#include "surface_choosy_pvt.h"

namespace texsyn::detail {

bool synthesize_on_surface(const std::vector<Plane>& sample, FaceLevel base,
    const ChoosyOptions& opt, SurfaceSynthesis& out, std::string& error, BoundarySlots boundary)
{
    const int levels = opt.levels;
    const int unit = 1 << (levels - 1);
    if (sample[0].width() < 2 * unit || sample[0].height() < 2 * unit) {
        error = "levels=" + std::to_string(levels) + " is too many for the sample ("
            + std::to_string(sample[0].width()) + "x" + std::to_string(sample[0].height())
            + "): each side must be at least " + std::to_string(2 * unit);
        return false;
    }
    out.pyramid = build_face_pyramid(std::move(base), levels, EdgePoints::Butterfly);
    const std::vector<FaceLevel>& mesh = out.pyramid.levels;

    // §3.10: the grids' faces are equilateral, 2^(levels-1-k) pixel rows high at level k;
    // synthesis distances are scaled to them, and sigma_k is the largest scaled distance
    // between adjacent faces of the synthesis level.
    std::vector<FaceKernel> analysis_kernels, synthesis_kernels;
    std::vector<double> analysis_edges;
    for (int k = 0; k < levels; ++k) {
        const double rows = double(1 << (levels - 1 - k));
        const double adjacent = rows * 2.0 / 3.0;
        analysis_edges.push_back(rows * 2.0 / std::sqrt(3.0));
        const FaceLevel& level = mesh[size_t(k)];
        const double scale
            = level.mean_adjacent_distance > 0.0 ? adjacent / level.mean_adjacent_distance : 1.0;
        const double sigma = std::max(level.max_adjacent_distance * scale, adjacent);
        analysis_kernels.push_back({ sigma, 1.0 });
        synthesis_kernels.push_back({ sigma, scale });
    }
    const SurfaceAnalysis analysis = analyze_surface_sample(
        crop_to_multiple(sample, unit), levels, analysis_kernels, opt.nthreads);
    for (int k = 0; k < levels; ++k)
        if (analysis.sites[size_t(k)].empty()) {
            error = "levels=" + std::to_string(levels) + " is too many for the sample ("
                + std::to_string(sample[0].width()) + "x" + std::to_string(sample[0].height())
                + "): its coarsest level has no whole 2-distant neighbourhood";
            return false;
        }

    const size_t nc = sample.size();
    PassProgress progress;
    progress.total = 0;
    for (int k = 0; k < levels; ++k)
        progress.total += size_t(opt.iterations_at(levels - 1 - k)) * mesh[size_t(k)].size();

    SurfaceLevel level;
    for (int k = 0; k < levels; ++k) {
        const FaceLevel& geometry = mesh[size_t(k)];
        const FaceStencils stencil = face_stencils(geometry, opt.nthreads);
        level.geometry = &geometry;
        level.stencils = &stencil;
        level.source.assign(geometry.size(), 0);
        if (k == 0) { // G_0: random sites of the sample's coarsest level
            level.gaussian.assign(nc, std::vector<float>(geometry.size()));
            const std::vector<uint32_t>& sites = analysis.sites[0];
            for (size_t f = 0; f < geometry.size(); ++f) {
                const uint64_t r = random_bits(opt.seed, 0x53430000, f) >> 32;
                const uint32_t site = sites[size_t((r * sites.size()) >> 32)];
                const uint32_t g = site >> 31, face = site & 0x7fffffffu;
                for (size_t c = 0; c < nc; ++c)
                    level.gaussian[c][f] = analysis.gaussian[g][0][c][face];
            }
        }
        const bool finest = k == levels - 1;
        level.children.assign(
            finest ? 0 : nc, std::vector<float>(finest ? 0 : mesh[size_t(k + 1)].size()));
        {
            const auto weights
                = stencil_weights(analysis_edges[size_t(k)], analysis_kernels[size_t(k)].sigma);
            const AnalysisPoints points = surface_points(analysis, k, weights);
            auto index = make_choice_index(points, opt);
            auto target = make_surface_target(
                level, analysis, k, weights, boundary == BoundarySlots::Wildcards);
            choosy_passes(*target, *index, opt, opt.iterations_at(levels - 1 - k),
                0x53530000 + uint64_t(k) * 256, progress);
        }
        if (finest)
            break;
        // G_{k+1} = L_{k+1} + project(G_k).
        FaceValues next = project_faces(geometry, mesh[size_t(k + 1)], level.gaussian,
            synthesis_kernels[size_t(k + 1)], opt.nthreads);
        for (size_t c = 0; c < nc; ++c)
            for (size_t f = 0; f < next[c].size(); ++f)
                next[c][f] += level.children[c][f];
        level.gaussian = std::move(next);
    }
    out.colours = std::move(level.gaussian);
    return true;
}

} // namespace texsyn::detail
