// SPDX-License-Identifier: Apache-2.0
// The seam pass: the pixels near the wrap-around seams, re-synthesized with full square
// neighbourhoods once the level is complete, so that the output tiles.
#include "neighborhood_pvt.h"

#include <algorithm>
#include <limits>

#include "search/distance_pvt.h"

namespace texsyn::detail {

std::vector<std::pair<int, int>> seam_band(int width, int height, int band)
{
    std::vector<std::pair<int, int>> pixels;
    std::vector<char> in_row_band(size_t(height), 0);
    for (int i = 0; i < std::min(2 * band, height); ++i) {
        const int y = ((height - band + i) % height + height) % height;
        in_row_band[size_t(y)] = 1;
        for (int x = 0; x < width; ++x)
            pixels.emplace_back(x, y);
    }
    for (int y = 0; y < height; ++y)
        if (!in_row_band[size_t(y)])
            for (int i = 0; i < std::min(2 * band, width); ++i)
                pixels.emplace_back(((width - band + i) % width + width) % width, y);
    return pixels;
}

void repair_seams(OutputLevel& out, const std::vector<Plane>& sample,
    const std::vector<Plane>& sample_coarser, const std::vector<Plane>& coarser, int n, int coarse)
{
    const NeighborhoodLayout layout
        = make_layout(n, coarse, !coarser.empty(), NeighborhoodShape::Square);
    const int sw = sample[0].width();
    const CandidateGrid grid = candidate_grid(layout, sw, sample[0].height());
    if (grid.count() == 0)
        return; // the sample is too small for a square neighbourhood: keep the scanline pass
    const NeighborAccess access(layout, out, coarser, NeighborView::Current);
    const size_t dim = size_t(layout.npixels()) * sample.size();
    std::vector<float> query(dim), candidate(dim);
    std::vector<int64_t> tried;
    const int w = out.width();
    for (auto [x, y] : seam_band(w, out.height(), layout.half)) {
        access.gather(x, y, query.data());
        // Candidates: the current source and the continuation of every neighbour's source,
        // compared exactly; ties to the lowest candidate index.
        tried.clear();
        auto consider = [&](uint32_t source, int dx, int dy) {
            const int64_t c
                = grid.index(int(source % uint32_t(sw)) - dx, int(source / uint32_t(sw)) - dy);
            if (c >= 0)
                tried.push_back(c);
        };
        consider(out.live.source[size_t(y) * size_t(w) + size_t(x)], 0, 0);
        for (size_t i = 0; i < layout.fine.size(); ++i)
            consider(access.neighbor_source(x, y, i), layout.fine[i].dx, layout.fine[i].dy);
        std::sort(tried.begin(), tried.end());
        tried.erase(std::unique(tried.begin(), tried.end()), tried.end());
        float best = std::numeric_limits<float>::infinity();
        int64_t best_index = -1;
        for (int64_t c : tried) {
            sample_vector(layout, sample, sample_coarser, grid.x(size_t(c)), grid.y(size_t(c)),
                candidate.data());
            const float d = distance2_below(query.data(), candidate.data(), int(dim), best);
            if (d < best) {
                best = d;
                best_index = c;
            }
        }
        if (best_index < 0)
            continue;
        const size_t from
            = size_t(grid.y(size_t(best_index))) * size_t(sw) + size_t(grid.x(size_t(best_index)));
        const size_t to = size_t(y) * size_t(w) + size_t(x);
        for (size_t c = 0; c < sample.size(); ++c)
            out.live.channels[c].data()[to] = sample[c].data()[from];
        out.live.source[to] = uint32_t(from);
    }
}

} // namespace texsyn::detail
