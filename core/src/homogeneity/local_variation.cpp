// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen 1995 §6 in numbers: does the luminance's mean or contrast drift across
// the sample? Compared over a grid of equal square tiles.
#include "homogeneity_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/parallel.h>

namespace texsyn::homogeneity {

namespace {

// Smallest tile side: fewer pixels give a tile mean that mostly measures texture noise.
constexpr int kMinTile = 8;
// Tiles across the shorter side: 4x4 on a square sample, coarse enough that each tile
// holds several texture elements, fine enough to see a gradient's steps.
constexpr int kTilesAcross = 4;

double coefficient_of_variation(const std::vector<double>& v)
{
    double mean = 0.0;
    for (double x : v)
        mean += x;
    mean /= double(v.size());
    if (!(mean > 0.0))
        return 0.0;
    double var = 0.0;
    for (double x : v)
        var += (x - mean) * (x - mean);
    return std::sqrt(var / double(v.size())) / mean;
}

} // namespace

void measure_local_variation(const PlanarImage& image, HomogeneityReport& report, int nthreads)
{
    const int w = image.width(), h = image.height();
    const int tile = std::max(kMinTile, std::min(w, h) / kTilesAcross);
    const int nx = w / tile, ny = h / tile;
    if (nx < 2 || ny < 2)
        return;
    report.tile_size = tile;
    report.tiles_x = nx;
    report.tiles_y = ny;
    const int x0 = (w - nx * tile) / 2, y0 = (h - ny * tile) / 2; // centred grid
    const double area = double(tile) * double(tile);

    std::vector<double> means(size_t(nx * ny)), contrasts(means.size());
    OIIO::parallel_for_chunked(
        int64_t(0), int64_t(ny), int64_t(1),
        [&](int64_t begin, int64_t end) {
            std::vector<float> luma(static_cast<size_t>(w));
            std::vector<double> sum(static_cast<size_t>(nx)), squares(sum.size());
            for (int ty = int(begin); ty < int(end); ++ty) {
                // Two passes over the row of tiles (means, then centred squares): no
                // E[x²] - E[x]² cancellation. Each pass recomputes the luminance rows.
                std::fill(sum.begin(), sum.end(), 0.0);
                std::fill(squares.begin(), squares.end(), 0.0);
                for (int y = y0 + ty * tile; y < y0 + (ty + 1) * tile; ++y) {
                    luminance_row(image, y, luma.data());
                    for (int tx = 0; tx < nx; ++tx)
                        for (int x = x0 + tx * tile; x < x0 + (tx + 1) * tile; ++x)
                            sum[size_t(tx)] += luma[size_t(x)];
                }
                for (int y = y0 + ty * tile; y < y0 + (ty + 1) * tile; ++y) {
                    luminance_row(image, y, luma.data());
                    for (int tx = 0; tx < nx; ++tx) {
                        const double mean = sum[size_t(tx)] / area;
                        for (int x = x0 + tx * tile; x < x0 + (tx + 1) * tile; ++x)
                            squares[size_t(tx)]
                                += (luma[size_t(x)] - mean) * (luma[size_t(x)] - mean);
                    }
                }
                for (int tx = 0; tx < nx; ++tx) {
                    const double mean = sum[size_t(tx)] / area;
                    const double sd = std::sqrt(squares[size_t(tx)] / area);
                    means[size_t(ty * nx + tx)] = mean;
                    // RMS contrast; a black tile has none.
                    contrasts[size_t(ty * nx + tx)] = mean > 0.0 ? sd / mean : 0.0;
                }
            }
        },
        OIIO::paropt(nthreads, OIIO::paropt::SplitDir::Y, 1));
    report.local_mean_variation = coefficient_of_variation(means);
    report.local_contrast_variation = coefficient_of_variation(contrasts);
}

} // namespace texsyn::homogeneity
