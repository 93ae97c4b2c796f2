// SPDX-License-Identifier: Apache-2.0
// A kd-tree that points enter and leave one at a time: one tree of the set of dynamic
// kd-trees of Castellanos & Williams §6.4 (kdtree_choice.cpp). nanoflann stays inside
// dynamic_kdtree.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace texsyn::detail {

/// Which points a tree still holds: p is live iff keys[p / per_site] == key (every point is
/// live when keys is null). A tree never checks this itself on removal: the owner changes
/// the keys and calls removed().
struct LiveTest {
    const uint32_t* keys = nullptr;
    uint32_t key = 0;
    uint32_t per_site = 1;
    bool operator()(uint32_t p) const { return !keys || keys[p / per_site] == key; }
};

/// A dynamic kd-tree over some of a fixed array of points (row-major, `dim` floats each):
/// static nanoflann trees of geometrically growing sizes (the logarithmic method) plus a
/// short list searched linearly. Inserting fills the list; a full list becomes a tree and
/// trees of similar size merge. A point that leaves is only marked (by the LiveTest); when
/// half the stored points have left, the rest are rebuilt, and a tree of few live points
/// is searched linearly. Everything is deterministic: the structure depends only on the
/// sequence of calls.
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
    /// Adds live point p.
    void insert(uint32_t p, const LiveTest& live);
    /// One stored point is no longer live (`live` already says so).
    void removed(const LiveTest& live);
    size_t live() const { return m_live; }

    /// The live point nearest `query` among those with squared distance < `bound` (nanoflann
    /// `eps`: a returned point may be up to (1 + eps) times farther than the nearest): sets
    /// `point` and returns its squared distance, or returns `bound` (point untouched) if
    /// there is none.
    float nearest(
        const float* query, float bound, float eps, const LiveTest& live, uint32_t& point) const;

    /// Bytes held (copies of the points in tree order, indices, nodes).
    size_t memory_bytes() const;

private:
    struct Part; // one static nanoflann tree over a copy of its points
    void rebuild(const LiveTest& live);
    std::vector<uint32_t> live_ids(const LiveTest& live) const;

    const float* m_points;
    int m_dim;
    std::vector<std::unique_ptr<Part>> m_parts; // sizes decreasing
    std::vector<uint32_t> m_list;               // searched linearly
    size_t m_stored = 0, m_live = 0;
};

} // namespace texsyn::detail
