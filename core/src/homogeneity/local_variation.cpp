// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen 1995 §6 in numbers: does the luminance's mean or contrast drift across
// the sample? Compared over a grid of equal square tiles.
#include "homogeneity_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

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
        detail::split_every_item(nthreads));
    report.local_mean_variation = coefficient_of_variation(means);
    report.local_contrast_variation = coefficient_of_variation(contrasts);
}

void measure_lighting(const PlanarImage& image, HomogeneityReport& report, int nthreads)
{
    // 8x8 regions: enough of them for a six-term fit not to explain their means by chance.
    constexpr int kRegions = 8;
    const IlluminationFit& fit = report.illumination;
    const int w = image.width(), h = image.height();
    const int rw = w / kRegions, rh = h / kRegions;
    if (rw < 2 || rh < 2)
        return;
    const size_t n = kRegions * kRegions;
    // Per region: the luminance's sum, the fit's, and the lit-out luminance's sum and sum
    // of squares (about its region's mean, in a second pass: no cancellation).
    std::vector<double> measured(n), fitted(n), flat_mean(n), flat_squares(n);
    const double area = double(rw) * double(rh);
    OIIO::parallel_for(
        int64_t(0), int64_t(kRegions),
        [&](int64_t ry) {
            std::vector<float> luma(static_cast<size_t>(w));
            const size_t row = size_t(ry) * kRegions;
            for (int pass = 0; pass < 2; ++pass)
                for (int y = int(ry) * rh; y < int(ry + 1) * rh; ++y) {
                    luminance_row(image, y, luma.data());
                    for (int rx = 0; rx < kRegions; ++rx)
                        for (int x = rx * rw; x < (rx + 1) * rw; ++x) {
                            const double g = std::max(fit.at(x, y, w, h), 1e-12);
                            const double flat = luma[size_t(x)] / g;
                            if (pass == 0) {
                                measured[row + size_t(rx)] += luma[size_t(x)];
                                fitted[row + size_t(rx)] += g;
                                flat_mean[row + size_t(rx)] += flat / area;
                            } else {
                                const double d = flat - flat_mean[row + size_t(rx)];
                                flat_squares[row + size_t(rx)] += d * d;
                            }
                        }
                }
        },
        detail::split_every_item(nthreads));
    double mean = 0.0;
    for (double v : measured)
        mean += v;
    mean /= double(n);
    double total = 0.0, residual = 0.0;
    std::vector<double> contrasts(n);
    for (size_t i = 0; i < n; ++i) {
        total += (measured[i] - mean) * (measured[i] - mean);
        residual += (measured[i] - fitted[i]) * (measured[i] - fitted[i]);
        contrasts[i] = flat_mean[i] > 0.0 ? std::sqrt(flat_squares[i] / area) / flat_mean[i] : 0.0;
    }
    report.lighting_share = total > 0.0 ? std::max(0.0, 1.0 - residual / total) : 0.0;
    report.lit_out_contrast_variation = coefficient_of_variation(contrasts);
}

} // namespace texsyn::homogeneity
