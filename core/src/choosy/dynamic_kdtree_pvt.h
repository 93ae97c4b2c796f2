// SPDX-License-Identifier: Apache-2.0
// A kd-tree that points enter and leave: one tree of the set of dynamic kd-trees of
// Castellanos & Williams §6.4 (kdtree_choice.cpp). nanoflann stays inside
// dynamic_kdtree.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsyn::detail {

/// Which points a tree holds: p is live iff home[p / per_site] == key (every point is live
/// when home is null). A tree never checks this on removal: the owner changes home and calls
/// removed().
struct LiveTest {
    const uint32_t* home = nullptr;
    uint32_t key = 0;
    uint32_t per_site = 1;
    bool operator()(uint32_t p) const { return !home || home[p / per_site] == key; }
};

/// The factor on a point's squared distance: factors[min(count[site] - min, n - 1)], 1
/// without counts. A tree's points may have been used more often than the tree says
/// (a move waits for the end of a round), so each point is scored with its own count.
struct PointPenalty {
    const uint32_t* counts = nullptr;
    const float* factors = nullptr;
    size_t nfactors = 1;
    uint32_t min = 0;
    uint32_t per_site = 1;
    float operator()(uint32_t p) const
    {
        if (!counts)
            return 1.0f;
        const size_t d = counts[p / per_site] - min;
        return factors[d < nfactors ? d : nfactors - 1];
    }
};

/// A dynamic kd-tree over some of a fixed array of points (row-major, `dim` floats each):
/// static nanoflann trees of geometrically growing sizes (the logarithmic method) plus a
/// short list searched linearly. Inserted points join the list; a full list becomes a tree
/// and trees of similar size merge. A point that leaves is only marked (by the LiveTest);
/// when half the stored points have left, the rest are rebuilt, and a tree of few live
/// points is searched linearly. Deterministic: the structure depends only on the calls.
/// Thread safety: nearest() may be called concurrently; the rest may not.
class DynamicKdTree {
public:
    /// `points` must outlive the tree.
    DynamicKdTree(const float* points, int dim);
    ~DynamicKdTree();
    DynamicKdTree(DynamicKdTree&&) noexcept;
    DynamicKdTree& operator=(DynamicKdTree&&) noexcept;

    /// Holds exactly `ids` (all live), built in one go.
    void assign(std::vector<uint32_t> ids);
    /// Adds live points.
    void insert(const std::vector<uint32_t>& ids, const LiveTest& live);
    /// `n` stored points are no longer live (`live` already says so).
    void removed(size_t n, const LiveTest& live);
    size_t live() const { return m_live; }

    /// The live point of least score d x penalty(p) (d its squared distance to `query`)
    /// among those scoring below `bound`, where every point's penalty is at least
    /// `least_penalty`: sets `point` and returns its score, or returns `bound` (point
    /// untouched) if there is none. nanoflann's `eps` allows a point whose distance is up to
    /// (1 + eps) times the best's.
    float nearest(const float* query, float bound, float eps, const LiveTest& live,
        const PointPenalty& penalty, float least_penalty, uint32_t& point) const;

private:
    struct Part; // one static nanoflann tree over a copy of its points
    std::vector<uint32_t> live_ids(const LiveTest& live) const;

    const float* m_points;
    int m_dim;
    std::vector<std::unique_ptr<Part>> m_parts; // sizes decreasing
    std::vector<uint32_t> m_list;               // searched linearly
    size_t m_stored = 0, m_live = 0;
};

} // namespace texsyn::detail
