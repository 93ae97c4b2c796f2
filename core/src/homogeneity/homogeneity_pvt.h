// SPDX-License-Identifier: Apache-2.0
// Private helpers of homogeneity.h: luminance, the illumination fit, tile statistics.
#pragma once

#include <texsyn/homogeneity.h>

#include <functional>

namespace texsyn::homogeneity {

/// Rows per block of every row-parallel pass. Fixed (never derived from the thread count)
/// so that per-block partial sums, combined in block order, are the same at any nthreads.
inline constexpr int rows_per_block = 16;

/// Runs fn(block, y0, y1) for the row blocks [y0, y1) of an image `height` rows high, in
/// parallel; returns the number of blocks. Blocks are numbered top to bottom.
int for_each_row_block(int height, int nthreads, const std::function<void(int, int, int)>& fn);

// The luminance is computed a row at a time where it is needed, never stored as a plane:
// these functions allocate nothing of the image's size, so they cannot run out of memory
// on an image that is already in memory (and nothing throws across homogeneity.h).

/// Whether `image` has pixels and colour channels, so a luminance.
bool has_luminance(const PlanarImage& image);

/// Row y of the luminance of `image` (rules in homogeneity.h) into out[0, width).
void luminance_row(const PlanarImage& image, int y, float* out);

/// Least-squares quadratic fit to the luminance (see IlluminationFit). False if the image
/// has no luminance or its mean is not positive (no light: nothing to fit or divide by).
bool fit_illumination(const PlanarImage& image, IlluminationFit& fit, int nthreads);

/// Fills report.illumination_{amplitude,direction,planar_fraction,description} from
/// report.illumination, evaluated over the pixels of the report's width x height.
void describe_illumination(HomogeneityReport& report, int nthreads);

/// HomogeneityReport::lighting_share and lit_out_contrast_variation of `image`, for the
/// fitted illumination in `report`.
void measure_lighting(const PlanarImage& image, HomogeneityReport& report, int nthreads);

/// The tile statistics of check_homogeneity, filled into `report` (tiles_*, tile_size,
/// local_*_variation). Leaves them zero if fewer than 2x2 tiles fit.
void measure_local_variation(const PlanarImage& image, HomogeneityReport& report, int nthreads);

} // namespace texsyn::homogeneity
