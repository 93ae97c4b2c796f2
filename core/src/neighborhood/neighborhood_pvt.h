// SPDX-License-Identifier: Apache-2.0
// The geometry of Wei & Levoy neighbourhoods: which pixels a vector holds, where the sample's
// candidate neighbourhoods lie, and how vectors are gathered from the sample and the output.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <texsyn/image.h>
#include <texsyn/neighborhood.h>

#include "image/huge_pages_pvt.h"
#include "image/wrap_pvt.h"

namespace texsyn::detail {

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

/// The neighbourhood vector of sample position (x, y), whose `fine` part lies inside
/// `level`: `coarser` is reflected at its edges around the parent.
void sample_vector(const NeighborhoodLayout& layout, const std::vector<Plane>& level,
    const std::vector<Plane>& coarser, int x, int y, float* out);

/// Sample neighbourhood vectors (tens of MB, filled once): in huge pages where possible.
using SampleVectors = std::vector<float, HugePageAllocator<float>>;

/// The neighbourhood vectors of every candidate of one sample level, row-major (count x
/// layout.npixels() * channels): `level` at the candidate, `coarser` (may be empty when the
/// layout has no coarse part) reflected at its edges around the parent.
SampleVectors sample_vectors(const NeighborhoodLayout& layout, const CandidateGrid& grid,
    const std::vector<Plane>& level, const std::vector<Plane>& coarser, int nthreads);

/// One output level being synthesized: its channels and, per pixel, the index of the sample
/// pixel (at the same level) it holds — `live` as synthesis proceeds, `initial` the noise it
/// started from.
struct OutputLevel {
    struct Pixels {
        std::vector<Plane> channels;
        std::vector<uint32_t> source;
    };
    Pixels live, initial;
    int width() const { return live.channels[0].width(); }
    int height() const { return live.channels[0].height(); }
};

/// Which values an output neighbourhood sees.
enum class NeighborView {
    /// The scanline pass: a neighbour that comes after the pixel in scanline order, or lies
    /// across the top or left edge, is read from the initial noise. Pixels then depend only
    /// on pixels above and to the left without wrapping, so rows can be synthesized as a
    /// wavefront (each row a few pixels behind the one above) with the result of one thread.
    Scanline,
    /// Every neighbour as it is now (the seam pass, when the level is complete).
    Current,
};

/// Reads the neighbourhoods of output pixels: the level (circularly, since the output is a
/// torus, and per `view`) and the coarser level (complete; empty at the coarsest).
/// Interior pixels take precomputed linear offsets; only pixels near an edge pay for
/// wrapping. Safe to use from several threads at once.
class NeighborAccess {
public:
    NeighborAccess(const NeighborhoodLayout& layout, const OutputLevel& level,
        const std::vector<Plane>& coarser, NeighborView view);
    /// The vector of pixel (x, y) into `out` (layout.npixels() * channels floats).
    void gather(int x, int y, float* out) const;
    /// The source (sample pixel index) of the neighbour at layout.fine[i] of (x, y).
    uint32_t neighbor_source(int x, int y, size_t i) const;
    /// How far right of a pixel, in the rows above it, its neighbourhood reaches.
    int reach() const { return m_reach; }

private:
    // Where neighbour i of (x, y) is read: the pixels (live or initial) and an index.
    const OutputLevel::Pixels& locate(int x, int y, size_t i, size_t& index) const;

    const NeighborhoodLayout& m_layout;
    const OutputLevel& m_level;
    const std::vector<Plane>& m_coarser;
    NeighborView m_view;
    std::vector<std::ptrdiff_t> m_fine_offsets, m_coarse_offsets;
    std::vector<char> m_after;           // fine neighbour i comes after the pixel in scanline order
    int m_reach = 0, m_coarse_reach = 0; // largest |dx|, |dy| of each part
};

/// Whether a `sw` x `sh` sample and a `w` x `h` output suit opt.levels and opt.n: every
/// level of each at least its neighbourhood's side. False with a message naming the option
/// otherwise.
bool check_neighborhood_sizes(
    int sw, int sh, int w, int h, const NeighborhoodOptions& opt, std::string& error);

} // namespace texsyn::detail

namespace texsyn::detail {

/// The number of threads `nthreads` means (OIIO's convention: 0 = the "threads" attribute,
/// which defaults to the number of cores).
int resolve_threads(int nthreads);

/// Calls pixel(worker, x, y) once for every pixel of a width x height level such that each
/// call happens after the calls for every pixel above it up to `reach` columns to its right
/// (and to the right end of the row above when that is nearer), and after the pixels to its
/// left in its row: the dependencies of a NeighborView::Scanline neighbourhood. Rows run on
/// up to `nthreads` workers (worker 0 is the calling thread) as a wavefront; the result is
/// the sequential one whatever nthreads is. `row_done()` is called on the calling thread as
/// rows complete (for progress). An exception in a worker stops the pass and is rethrown.
void scanline_pass(int width, int height, int reach, int nthreads,
    const std::function<void(int, int, int)>& pixel, const std::function<void()>& row_done);

} // namespace texsyn::detail

namespace texsyn::detail {

/// The pixels within `band` of the wrap-around seams of a width x height level, in the
/// order the seam pass visits them: the 2 x band rows across the bottom/top seam (from row
/// height - band down across the wrap), then the 2 x band columns across the right/left
/// seam in the other rows.
std::vector<std::pair<int, int>> seam_band(int width, int height, int band);

/// The seam pass of one complete level: every pixel of seam_band(…, (n-1)/2) is
/// re-synthesized, in order, with the full n x n square neighbourhood (plus the coarse
/// square below the coarsest level), which now sees finished texture on both sides of the
/// seam. Its candidates are the continuations of its neighbours' sources (k-coherence with
/// k = 1) and its own source, compared exactly: a few dozen per pixel, no search structure.
void repair_seams(OutputLevel& out, const std::vector<Plane>& sample,
    const std::vector<Plane>& sample_coarser, const std::vector<Plane>& coarser, int n, int coarse);

} // namespace texsyn::detail
