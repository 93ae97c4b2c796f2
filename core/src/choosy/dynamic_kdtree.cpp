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

// nanoflann's result-set concept: the nearest live point closer than a bound.
struct BoundedNearest {
    float best;
    uint32_t position = 0;
    bool found = false;
    const uint32_t* ids;
    const LiveTest& live;

    size_t size() const { return found ? 1 : 0; }
    bool full() const { return true; }
    float worstDist() const { return best; }
    bool addPoint(float d, uint32_t pos)
    {
        if (d < best && live(ids[pos])) {
            best = d;
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
    std::unique_ptr<NanoflannTree> tree;

    Part(const float* all, int dim, std::vector<uint32_t> order)
        : ids(std::move(order))
        , points(ids.size() * size_t(dim))
    {
        for (size_t i = 0; i < ids.size(); ++i)
            std::copy_n(all + size_t(ids[i]) * size_t(dim), dim, points.data() + i * size_t(dim));
        data = ReducedPoints { points.data(), ids.size(), dim };
        tree = std::make_unique<NanoflannTree>(
            dim, data, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize));
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

void DynamicKdTree::rebuild(const LiveTest& live)
{
    assign(live_ids(live));
}

void DynamicKdTree::insert(uint32_t p, const LiveTest& live)
{
    m_list.push_back(p);
    ++m_stored;
    ++m_live;
    if (m_list.size() < kListSize || m_live <= kListSize)
        return;
    // The list becomes a tree; then merge trees while the newest is at least half the size
    // of the one before it (so sizes at least double from newest to oldest).
    std::vector<uint32_t> ids;
    for (uint32_t q : m_list)
        if (live(q))
            ids.push_back(q);
    m_stored -= m_list.size() - ids.size();
    m_list.clear();
    while (!m_parts.empty() && 2 * ids.size() >= m_parts.back()->size()) {
        const std::vector<uint32_t>& older = m_parts.back()->ids;
        const size_t before = ids.size();
        for (uint32_t q : older)
            if (live(q))
                ids.push_back(q);
        m_stored -= older.size() - (ids.size() - before);
        m_parts.pop_back();
    }
    if (!ids.empty())
        m_parts.push_back(std::make_unique<Part>(m_points, m_dim, std::move(ids)));
}

void DynamicKdTree::removed(const LiveTest& live)
{
    --m_live;
    if (m_live == 0) {
        m_parts.clear();
        m_list.clear();
        m_stored = 0;
    } else if (m_stored > kListSize && (m_stored >= 2 * m_live || m_live <= kListSize)
        && !m_parts.empty()) {
        rebuild(live);
    }
}

float DynamicKdTree::nearest(
    const float* query, float bound, float eps, const LiveTest& live, uint32_t& point) const
{
    float best = bound;
    for (const auto& part : m_parts) {
        BoundedNearest result { best, 0, false, part->ids.data(), live };
        part->tree->findNeighbors(result, query, nanoflann::SearchParams(0, eps));
        if (result.found) {
            best = result.best;
            point = part->ids[result.position];
        }
    }
    for (uint32_t p : m_list) {
        if (!live(p))
            continue;
        const float d = distance2_below(query, m_points + size_t(p) * size_t(m_dim), m_dim, best);
        if (d < best) {
            best = d;
            point = p;
        }
    }
    return best;
}

size_t DynamicKdTree::memory_bytes() const
{
    size_t bytes = m_list.capacity() * sizeof(uint32_t);
    for (const auto& part : m_parts)
        bytes += part->points.size() * sizeof(float) + part->ids.size() * sizeof(uint32_t)
            + part->tree->usedMemory(*part->tree);
    return bytes;
}

} // namespace texsyn::detail
