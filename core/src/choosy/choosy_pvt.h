// SPDX-License-Identifier: Apache-2.0
// Choosy sampling (Castellanos & Williams §3.11, Algorithm 2), split so that the sampling
// knows nothing of the grid: an output level is a set of sites whose neighbourhoods are
// lists of weighted slots (ChoosyTarget), the sample's neighbourhoods are a set of points
// (AnalysisPoints), and a ChoiceIndex picks among them under the use-count penalty. The
// pixel grid (grid_level.cpp) is one geometry; a surface can be another.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <texsyn/choosy.h>
#include <texsyn/image.h>

namespace texsyn::detail {

/// How often each sample site has been chosen in the current pass, and the penalty that
/// follows (Algorithm 2's c[] and c_min). Distances are squared, so a site used c times
/// multiplies its squared distance by 4^(penalty (c - c_min)).
class UseCounts {
public:
    UseCounts(size_t nsites, float penalty);

    /// Every count back to 0 (a new pass).
    void reset();
    void add(size_t site);
    size_t sites() const { return m_counts.size(); }
    uint32_t count(size_t site) const { return m_counts[site]; }
    const uint32_t* counts() const { return m_counts.data(); }
    uint32_t min() const { return m_min; }
    /// The largest count of any site.
    uint32_t max() const { return uint32_t(m_histogram.size() - 1); }
    /// Whether counts change scores at all (penalty > 0).
    bool penalized() const { return m_penalized; }
    /// The factor on the squared distance of a site used `c` times (c >= min()); 1 if not
    /// penalized; capped at 1e30 so products stay finite.
    float factor(uint32_t c) const
    {
        const size_t d = c - m_min;
        return d < m_factors.size() ? m_factors[d] : m_factors.back();
    }
    /// factor(min() + d) for d < factors().size() (later ones repeat the last).
    const std::vector<float>& factors() const { return m_factors; }

private:
    std::vector<uint32_t> m_counts;
    std::vector<size_t> m_histogram; // sites per count
    std::vector<float> m_factors;    // by c - c_min
    uint32_t m_min = 0;
    bool m_penalized = false;
};

/// The sample's neighbourhoods at one level as points: point p is sample site
/// p / orientations seen in orientation p % orientations; vector(p, out) writes its
/// weighted neighbourhood (dim floats). vector must be safe to call concurrently.
struct AnalysisPoints {
    size_t count = 0;
    int orientations = 1;
    int dim = 0;
    std::function<void(size_t, float*)> vector;
    size_t sites() const { return count / size_t(orientations); }
};

/// Picks the point that minimises squared distance x the penalty of its site's use count
/// (ties: the lowest point), and records uses.
/// Thread safety: choose() may run concurrently; record() and reset() may not run with
/// anything else.
class ChoiceIndex {
public:
    virtual ~ChoiceIndex() = default;
    /// The sample site of point `point`.
    size_t site_of(uint32_t point) const { return point / m_orientations; }
    /// The best point for `query` (a weighted neighbourhood of dim floats). `hints` (nhints
    /// points) are likely good choices the caller suggests (k-coherence): they are scored
    /// first, so that their best score bounds the search. They never change the answer of
    /// an exact search.
    virtual uint32_t choose(const float* query, const uint32_t* hints, size_t nhints) const = 0;
    /// choose() with wildcards: the squared distance sums only the components whose `mask`
    /// (dim floats, each 0 or 1) is 1, over the points' full-dimensional vectors, exactly
    /// (Castellanos & Williams §3.12: a wildcard's difference is zero to every point).
    virtual uint32_t choose_masked(
        const float* query, const float* mask, const uint32_t* hints, size_t nhints) const = 0;
    /// One more use of the site of point `point`.
    virtual void record(uint32_t point) = 0;
    /// Every use count back to 0 (a new pass).
    virtual void reset() = 0;
    /// The end of a round of records: deferred work (moving points between trees) may be
    /// done. choose() is exact at any time; this keeps it fast.
    virtual void settle() { }
    virtual const UseCounts& counts() const = 0;

protected:
    explicit ChoiceIndex(int orientations)
        : m_orientations(uint32_t(orientations))
    { }
    uint32_t m_orientations;
};

/// Every point in full dimension (the points are copied in): the exact O(N d) loop;
/// choose_masked() is MaskedChoice's (points.vector must stay valid as long as the index).
std::unique_ptr<ChoiceIndex> make_exhaustive_choice(
    const AnalysisPoints& points, float penalty, int nthreads);

/// The exact loop behind both indices' choose_masked: every point in full dimension,
/// copied in from points.vector (which must stay valid as long as this) at the first
/// choose(), in blocks of kBlock components (the first block of every point, then the
/// second, ...), so that the first block, which rules most points out, is read in one
/// cache line per point. Thread safety: choose() may run concurrently.
class MaskedChoice {
public:
    static constexpr int kBlock = 16;
    explicit MaskedChoice(const AnalysisPoints& points);
    /// ChoiceIndex::choose_masked scored with `counts` (point p: site p / orientations).
    uint32_t choose(const UseCounts& counts, const float* query, const float* mask,
        const uint32_t* hints, size_t nhints) const;

private:
    AnalysisPoints m_points;
    mutable std::once_flag m_once;
    mutable std::vector<float> m_blocks; // [block][point][kBlock], zero-padded
};

/// §6.2–6.4: points weighted, projected on their `dims` leading principal components (all
/// if dims >= dim), held in a set of dynamic kd-trees, one per use count; a tree's nearest
/// is scaled by its penalty and the smallest wins. `eps` is nanoflann's approximation.
/// choose_masked() is MaskedChoice's exact loop (points.vector must stay valid as long as
/// the index): a distance that skips components has no principal components to search by.
std::unique_ptr<ChoiceIndex> make_kdtree_choice(
    const AnalysisPoints& points, float penalty, int dims, float eps, int nthreads);

/// The index `opt.search` asks for over `points` (exhaustive or kd-trees).
std::unique_ptr<ChoiceIndex> make_choice_index(
    const AnalysisPoints& points, const ChoosyOptions& opt);

/// The top-left part of every plane whose sides are multiples of `unit` (the planes
/// themselves if they are).
std::vector<Plane> crop_to_multiple(const std::vector<Plane>& planes, int unit);

/// One output level as choosy sampling sees it.
class ChoosyTarget {
public:
    virtual ~ChoosyTarget() = default;
    virtual size_t sites() const = 0;
    /// Floats in a query vector (the AnalysisPoints' dim).
    virtual int dim() const = 0;
    /// The weighted neighbourhood of `site` as it is now. Safe to call concurrently (while
    /// nothing is applied).
    virtual void query(size_t site, float* out) const = 0;
    /// The sites query(site) reads (at most max_neighbors()), into `out`; returns how many.
    virtual size_t neighbors(size_t site, size_t* out) const = 0;
    virtual size_t max_neighbors() const = 0;
    /// Points that would continue the choices of the site's neighbours (Ashikhmin's
    /// coherence: each neighbour's point shifted back by its offset, in its orientation),
    /// at most max_neighbors(), into `out`; returns how many. Safe to call concurrently.
    virtual size_t hints(size_t site, uint32_t* out) const = 0;
    /// Wildcards (§3.12): whether some components of query(site) are to be left out of the
    /// distance; if so, writes `mask` (dim floats: 1 for a component that counts, 0 for a
    /// wildcard) for ChoiceIndex::choose_masked. False (mask untouched) by default. Safe to
    /// call concurrently.
    virtual bool wildcards(size_t, float*) const { return false; }
    /// `site` takes the value of `point` (and its children).
    virtual void apply(size_t site, uint32_t point) = 0;
};

/// Settings of one pass of Algorithm 2.
struct PassSettings {
    uint64_t seed = 0;
    uint64_t stream = 0; ///< distinguishes the passes of a synthesis (level, iteration)
    int nthreads = 0;
    std::function<void(size_t)> visited; ///< called with site counts as rounds complete
};

/// Algorithm 2: index.reset(), then every site of `target` once, in a random order drawn
/// from (seed, stream), takes the point index.choose(query) returns, and index.record()s
/// it. Visits run in rounds (choosy_round_size) searched in parallel against the state at
/// the round's start and applied in order; a visit that an earlier visit of its round
/// affected (a neighbour changed, or the same sample site was chosen) is searched again at
/// its turn. A site with wildcards (ChoosyTarget::wildcards) is searched with
/// index.choose_masked(). The result depends on the seed, never on nthreads.
void choosy_pass(ChoosyTarget& target, ChoiceIndex& index, const PassSettings& settings);

/// Progress over the passes of a synthesis: visits done of `total`.
struct PassProgress {
    size_t done = 0;
    size_t total = 1;
};

/// `iterations` passes of choosy_pass() over one level with `opt`'s seed, threads and
/// progress callback; pass `it` uses stream `stream + it`.
void choosy_passes(ChoosyTarget& target, ChoiceIndex& index, const ChoosyOptions& opt,
    int iterations, uint64_t stream, PassProgress& progress);

/// Visits per round for a level of `sites` sites: sites / 512 clamped to [1, 256], so
/// that few visits of a round are neighbours.
size_t choosy_round_size(size_t sites);

/// Whether a `sw` x `sh` sample (as given, before its crop) and a `w` x `h` output suit
/// opt.levels: the coarsest level of each at least the 5x5 neighbourhood, each output side
/// a multiple of 2^(levels-1). False with a message naming the option otherwise.
bool check_choosy_sizes(int sw, int sh, int w, int h, const ChoosyOptions& opt, std::string& error);

} // namespace texsyn::detail

namespace texsyn::detail {

/// The grid's 2-distant neighbourhood: the 24 offsets of the 5x5 square but its centre, in
/// row order, each with its eq. 7 weight beta = exp(-1/2 (d / 1.3)^2) (sigma = 1 pixel).
struct RingSlot {
    int dx = 0;
    int dy = 0;
    float weight = 0.0f;
};
const std::vector<RingSlot>& ring_slots();

/// Orientation t (0..7) of the square grid applied to an offset: swap x and y if t & 4,
/// then negate x if t & 1 and y if t & 2. 0 is the identity.
void orient(int t, int& dx, int& dy);

/// Gaussian and Laplacian pyramids of a sample, level 0 the finest:
/// gaussian[l+1] = reduce(gaussian[l]) and laplacian[l] = gaussian[l] -
/// project(gaussian[l+1]) (l below the coarsest), every plane reflected at its edges.
/// Each channel separately; sizes halve exactly (the caller crops to a multiple of
/// 2^(levels-1)).
struct ChoosyAnalysis {
    std::vector<std::vector<Plane>> gaussian;  ///< [level][channel]
    std::vector<std::vector<Plane>> laplacian; ///< [level][channel]; empty at the coarsest
};
ChoosyAnalysis analyze_choosy(const std::vector<Plane>& channels, int levels, int nthreads);

/// project(coarse) (twice the size: insert zeros, blur, normalise) + laplacian, per
/// channel: the incremental inversion G_{l} = L_{l} + project(G_{l+1}) (§3.2). `boundary`:
/// Circular for a synthesis (it tiles), Reflect to invert a sample's own analysis.
std::vector<Plane> invert_level(const std::vector<Plane>& laplacian,
    const std::vector<Plane>& coarse, Boundary boundary, int nthreads);

/// One output level on the pixel grid: its Gaussian values (`gaussian`, being synthesized)
/// and, below the finest, the Laplacian level under it (`children`, 2x the size) that
/// choices fill; `source` holds per pixel the sample pixel (index y * width + x at this
/// level) it copied.
/// GridLevel::orientation of a pixel no pass of its level has chosen yet.
constexpr uint8_t kNotChosen = 255;

struct GridLevel {
    std::vector<Plane> gaussian;
    std::vector<Plane> children; ///< empty at the finest level
    std::vector<uint32_t> source;
    std::vector<uint8_t> orientation; ///< of each choice; kNotChosen before the first
    int width() const { return gaussian[0].width(); }
    int height() const { return gaussian[0].height(); }
};

/// The sample positions whose 5x5 neighbourhood lies inside a width x height level: x and y
/// in [2, size - 3]. Point p of the grid's AnalysisPoints is candidate p / orientations.
struct GridCandidates {
    int width = 0, height = 0; ///< of the sample level
    size_t count() const
    {
        return width > 4 && height > 4 ? size_t(width - 4) * size_t(height - 4) : 0;
    }
    int x(size_t c) const { return 2 + int(c % size_t(width - 4)); }
    int y(size_t c) const { return 2 + int(c / size_t(width - 4)); }
    /// The candidate at (x, y), or -1 if (x, y) is not one.
    int64_t index(int x, int y) const
    {
        if (x < 2 || y < 2 || x >= width - 2 || y >= height - 2)
            return -1;
        return int64_t(y - 2) * (width - 4) + (x - 2);
    }
};

/// The points of sample level `gaussian` (every channel) in `orientations` (1 or 8).
AnalysisPoints grid_points(const std::vector<Plane>& gaussian, int orientations);

/// Output pixel (x, y) of `out` takes sample pixel (sx, sy) of `gaussian`, and its four
/// children the four Laplacian children of (sx, sy) in `laplacian` (the next finer sample
/// level; empty at the finest) turned by orientation t about the 2x2 block's centre.
void copy_choice(GridLevel& out, int x, int y, const std::vector<Plane>& gaussian,
    const std::vector<Plane>& laplacian, int sx, int sy, int t);

/// An output level (toroidal) as a ChoosyTarget over the sample level `gaussian` with
/// the Laplacian level under it (`laplacian`, empty at the finest) and `orientations`.
std::unique_ptr<ChoosyTarget> make_grid_target(GridLevel& out, const std::vector<Plane>& gaussian,
    const std::vector<Plane>& laplacian, int orientations);

} // namespace texsyn::detail
