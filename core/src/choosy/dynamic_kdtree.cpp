// SPDX-License-Identifier: Apache-2.0
// DynamicKdTree (dynamic_kdtree_pvt.h): the logarithmic method over static nanoflann trees.
#include "dynamic_kdtree_pvt.h"

#include <algorithm>

#include "search/nanoflann_adaptor_pvt.h"

namespace texsyn::detail {

namespace {

// The linear list: a full list becomes a tree; a tree with no more live points than this is
// searched linearly altogether ("sparse counts searched linearly", §6.4).
constexpr size_t kListSize = 128;

// Points per leaf: measured fastest of 8..64 for 20-dimensional queries with a penalty
// bound (16 about 6% faster than 64 at 128x128 -> 256x256).
constexpr size_t kChoosyLeafSize = 16;

// The squared distance between `dim`-float points a and b if it is below `bound`, otherwise
// some partial sum >= bound. Checked every 4 components: the leading principal components
// hold most of the variance, so most points are rejected after a few.
inline float distance2_early(const float* a, const float* b, int dim, float bound)
{
    float sum = 0.0f;
    int i = 0;
    for (; i + 4 <= dim; i += 4) {
        const float d0 = a[i] - b[i], d1 = a[i + 1] - b[i + 1], d2 = a[i + 2] - b[i + 2],
                    d3 = a[i + 3] - b[i + 3];
        sum += (d0 * d0 + d1 * d1) + (d2 * d2 + d3 * d3);
        if (sum >= bound)
            return sum;
    }
    for (; i < dim; ++i)
        sum += (a[i] - b[i]) * (a[i] - b[i]);
    return sum;
}

// The bound of the leaf nanoflann is scanning on this thread: nanoflann reads the result
// set's worstDist() just before evaluating a leaf's points, and the metric then abandons
// a point's sum once it passes it.
thread_local float t_leaf_bound = 0.0f;

// nanoflann's distance concept for the choosy trees: ReducedMetric with early abandoning.
struct EarlyMetric {
    using ElementType = float;
    using DistanceType = float;

    const ReducedPoints& points;

    explicit EarlyMetric(const ReducedPoints& p)
        : points(p)
    { }

    float evalMetric(const float* a, uint32_t b, size_t size) const
    {
        return distance2_early(
            a, points.data + size_t(b) * size_t(points.dim), int(size), t_leaf_bound);
    }
    template <typename U, typename V>
    float accum_dist(U a, V b, size_t) const
    {
        return (a - b) * (a - b);
    }
};

using ChoosyTree = nanoflann::KDTreeSingleIndexAdaptor<EarlyMetric, ReducedPoints, -1, uint32_t>;

// nanoflann's result-set concept: the live point of least penalized score below a bound.
// nanoflann prunes with worstDist(), a squared distance: the best score over the least
// penalty any point of the tree can have.
struct BoundedNearest {
    float best; // score
    float least_penalty;
    const uint32_t* ids;
    const LiveTest& live;
    const PointPenalty& penalty;
    uint32_t position = 0;
    bool found = false;

    size_t size() const { return found ? 1 : 0; }
    bool full() const { return true; }
    float worstDist() const
    {
        t_leaf_bound = best / least_penalty * 1.0001f;
        return t_leaf_bound;
    }
    bool addPoint(float d, uint32_t pos)
    {
        const uint32_t p = ids[pos];
        if (!live(p))
            return true;
        const float score = d * penalty(p);
        if (score < best) {
            best = score;
            position = pos;
            found = true;
        }
        return true;
    }
};

} // namespace

struct DynamicKdTree::Part {
    std::vector<uint32_t> ids; // point id at each tree position
    std::vector<float> points; // copies in tree order
    ReducedPoints data;
    std::unique_ptr<ChoosyTree> tree;

    Part(const float* all, int dim, std::vector<uint32_t> order)
        : ids(std::move(order))
        , points(ids.size() * size_t(dim))
    {
        for (size_t i = 0; i < ids.size(); ++i)
            std::copy_n(all + size_t(ids[i]) * size_t(dim), dim, points.data() + i * size_t(dim));
        data = ReducedPoints { points.data(), ids.size(), dim };
        tree = std::make_unique<ChoosyTree>(
            dim, data, nanoflann::KDTreeSingleIndexAdaptorParams(kChoosyLeafSize));
        // Store the points in the tree's leaf order so a leaf reads adjacent memory (as
        // KdTreeIndex does), and let the tree address them by position.
        std::vector<uint32_t>& slots = tree->vAcc;
        std::vector<uint32_t> sorted_ids(ids.size());
        std::vector<float> sorted(points.size());
        for (size_t p = 0; p < slots.size(); ++p) {
            sorted_ids[p] = ids[slots[p]];
            std::copy_n(points.data() + size_t(slots[p]) * size_t(dim), dim,
                sorted.data() + p * size_t(dim));
            slots[p] = uint32_t(p);
        }
        ids.swap(sorted_ids);
        points.swap(sorted);
        data.data = points.data();
    }
    size_t size() const { return ids.size(); }

    // Squared distance from `query` to the bounding box of the points.
    float box_distance(const float* query) const
    {
        float d = 0.0f;
        for (int i = 0; i < data.dim; ++i) {
            const auto& range = tree->root_bbox[size_t(i)];
            const float below = range.low - query[i], above = query[i] - range.high;
            const float out = std::max(std::max(below, above), 0.0f);
            d += out * out;
        }
        return d;
    }
};

DynamicKdTree::DynamicKdTree(const float* points, int dim)
    : m_points(points)
    , m_dim(dim)
{ }

DynamicKdTree::~DynamicKdTree() = default;
DynamicKdTree::DynamicKdTree(DynamicKdTree&&) noexcept = default;
DynamicKdTree& DynamicKdTree::operator=(DynamicKdTree&&) noexcept = default;

void DynamicKdTree::assign(std::vector<uint32_t> ids)
{
    m_parts.clear();
    m_list.clear();
    m_stored = m_live = ids.size();
    if (ids.size() <= kListSize)
        m_list = std::move(ids);
    else
        m_parts.push_back(std::make_unique<Part>(m_points, m_dim, std::move(ids)));
}

std::vector<uint32_t> DynamicKdTree::live_ids(const LiveTest& live) const
{
    std::vector<uint32_t> ids;
    ids.reserve(m_live);
    for (const auto& part : m_parts)
        for (uint32_t p : part->ids)
            if (live(p))
                ids.push_back(p);
    for (uint32_t p : m_list)
        if (live(p))
            ids.push_back(p);
    return ids;
}

void DynamicKdTree::insert(const std::vector<uint32_t>& ids, const LiveTest& live)
{
    m_list.insert(m_list.end(), ids.begin(), ids.end());
    m_stored += ids.size();
    m_live += ids.size();
    if (m_list.size() < kListSize || m_live <= kListSize)
        return;
    // The list becomes a tree; then merge trees while the newest is at least half the size
    // of the one before it (so sizes at least double from newest to oldest).
    std::vector<uint32_t> merged;
    for (uint32_t q : m_list)
        if (live(q))
            merged.push_back(q);
    m_stored -= m_list.size() - merged.size();
    m_list.clear();
    while (!m_parts.empty() && 2 * merged.size() >= m_parts.back()->size()) {
        const std::vector<uint32_t>& older = m_parts.back()->ids;
        const size_t before = merged.size();
        for (uint32_t q : older)
            if (live(q))
                merged.push_back(q);
        m_stored -= older.size() - (merged.size() - before);
        m_parts.pop_back();
    }
    if (!merged.empty())
        m_parts.push_back(std::make_unique<Part>(m_points, m_dim, std::move(merged)));
}

void DynamicKdTree::removed(size_t n, const LiveTest& live)
{
    m_live -= n;
    if (m_live == 0) {
        m_parts.clear();
        m_list.clear();
        m_stored = 0;
    } else if (m_stored > kListSize && (m_stored >= 2 * m_live || m_live <= kListSize)
        && !m_parts.empty()) {
        assign(live_ids(live));
    }
}

float DynamicKdTree::nearest(const float* query, float bound, float eps, const LiveTest& live,
    const PointPenalty& penalty, float least_penalty, uint32_t& point) const
{
    float best = bound;
    for (const auto& part : m_parts) {
        // nanoflann always descends to a leaf; a part wholly outside the bound (common in
        // the trees of used points, whose bound the penalty shrinks) is skipped here, with
        // the (1 + eps) slack nanoflann allows itself inside the tree.
        if (part->box_distance(query) * (1.0f + eps) * least_penalty >= best)
            continue;
        BoundedNearest result { best, least_penalty, part->ids.data(), live, penalty };
        part->tree->findNeighbors(result, query, nanoflann::SearchParams(0, eps));
        if (result.found) {
            best = result.best;
            point = part->ids[result.position];
        }
    }
    for (uint32_t p : m_list) {
        if (!live(p))
            continue;
        const float f = penalty(p);
        const float d = distance2_early(
            query, m_points + size_t(p) * size_t(m_dim), m_dim, best / f * 1.0001f);
        if (d * f < best) {
            best = d * f;
            point = p;
        }
    }
    return best;
}

} // namespace texsyn::detail
