// SPDX-License-Identifier: Apache-2.0
// The geometry of Wei & Levoy neighbourhoods: which pixels a vector holds, where the sample's
// candidate neighbourhoods lie, and how vectors are gathered from the sample and the output.
#pragma once

#include <cstdint>
#include <vector>

#include <texsyn/image.h>
#include <texsyn/neighborhood.h>

#include "image/huge_pages_pvt.h"

namespace texsyn::detail {

/// i mod n in [0, n) for any i (n >= 1); no division in the common case of i inside.
inline int wrap(int i, int n)
{
    if (i >= 0 && i < n)
        return i;
    const int r = i % n;
    return r < 0 ? r + n : r;
}

struct Offset {
    int dx = 0;
    int dy = 0;
};

/// The pixels of one level's neighbourhood vector, in vector order: `fine` at the pixel's
/// own level (relative to the pixel), then `coarse` at the next coarser level (relative to
/// the parent (x/2, y/2)); all channels of a pixel are adjacent in the vector.
struct NeighborhoodLayout {
    int half = 0; ///< (n - 1) / 2
    std::vector<Offset> fine;
    std::vector<Offset> coarse; ///< empty at the coarsest level
    NeighborhoodShape shape = NeighborhoodShape::Causal;
    int npixels() const { return int(fine.size() + coarse.size()); }
};

/// The layout for width n (odd), a coarse x coarse square if `has_coarser`, and `shape`.
NeighborhoodLayout make_layout(int n, int coarse, bool has_coarser, NeighborhoodShape shape);

/// The sample positions whose `fine` neighbourhood lies inside a width x height sample
/// level, numbered row by row: index = (y - y0) * columns + (x - x0).
struct CandidateGrid {
    int x0 = 0, y0 = 0;
    int columns = 0, rows = 0;
    size_t count() const { return size_t(columns) * size_t(rows); }
    int x(size_t index) const { return x0 + int(index % size_t(columns)); }
    int y(size_t index) const { return y0 + int(index / size_t(columns)); }
    /// The index of position (x, y), or -1 if it is not a candidate.
    int64_t index(int x, int y) const
    {
        const int cx = x - x0, cy = y - y0;
        if (cx < 0 || cy < 0 || cx >= columns || cy >= rows)
            return -1;
        return int64_t(cy) * columns + cx;
    }
};

/// The candidates of a width x height level for `layout` (count 0 if it does not fit).
CandidateGrid candidate_grid(const NeighborhoodLayout& layout, int width, int height);

/// Sample neighbourhood vectors (tens of MB, filled once): in huge pages where possible.
using SampleVectors = std::vector<float, HugePageAllocator<float>>;

/// The neighbourhood vectors of every candidate of one sample level, row-major (count x
/// layout.npixels() * channels): `level` at the candidate, `coarser` (may be empty when the
/// layout has no coarse part) reflected at its edges around the parent.
SampleVectors sample_vectors(const NeighborhoodLayout& layout, const CandidateGrid& grid,
    const std::vector<Plane>& level, const std::vector<Plane>& coarser, int nthreads);

/// The neighbourhood vector of output pixel (x, y): `level` and `coarser` addressed
/// circularly (the output is a torus). `out` holds layout.npixels() * channels floats.
void output_vector(const NeighborhoodLayout& layout, const std::vector<Plane>& level,
    const std::vector<Plane>& coarser, int x, int y, float* out);

} // namespace texsyn::detail
