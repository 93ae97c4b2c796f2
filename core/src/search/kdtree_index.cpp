// SPDX-License-Identifier: Apache-2.0
// KdTreeIndex and KdTreeQuery (kdtree_pvt.h): nanoflann over PCA projections.
#include "kdtree_pvt.h"

#include <algorithm>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "distance_pvt.h"

#include "nanoflann_adaptor_pvt.h"

namespace texsyn::detail {

namespace {

// Vectors projected per task: fixed, so the work split never depends on the thread count
// (not that it could change a result: each projection is computed alone).
constexpr size_t kProjectBlock = 1024;

} // namespace

struct KdTreeIndex::Tree {
    ReducedPoints points;
    NanoflannTree index;
    size_t bytes = 0;

    explicit Tree(const ReducedPoints& p)
        : points(p)
        , index(p.dim, points, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize))
    {
        bytes = index.usedMemory(index);
    }
};

KdTreeIndex::KdTreeIndex(const VectorSet& vectors, int dims, int nthreads)
    : m_vectors(vectors)
    , m_pca(vectors, dims, kVarianceFraction)
{
    const size_t d = size_t(reduced_dim());
    std::vector<float> projected(vectors.count * d);
    const size_t blocks = (vectors.count + kProjectBlock - 1) / kProjectBlock;
    OIIO::parallel_for(
        int64_t(0), int64_t(blocks),
        [&](int64_t b) {
            const size_t end = std::min(vectors.count, size_t(b + 1) * kProjectBlock);
            for (size_t i = size_t(b) * kProjectBlock; i < end; ++i)
                m_pca.project(vectors.row(i), projected.data() + i * d);
        },
        detail::split_every_item(nthreads));
    m_tree
        = std::make_unique<Tree>(ReducedPoints { projected.data(), vectors.count, reduced_dim() });
    // Store the points in the tree's order (nanoflann's vAcc: leaf by leaf), so a leaf's
    // points are adjacent in memory, and let the tree address them by position: a query
    // then reads a few cache lines per leaf instead of one per point.
    std::vector<uint32_t>& slots = m_tree->index.vAcc;
    m_order.assign(slots.begin(), slots.end());
    m_points.resize(projected.size());
    for (size_t p = 0; p < slots.size(); ++p) {
        std::copy_n(projected.data() + size_t(slots[p]) * d, d, m_points.data() + p * d);
        slots[p] = uint32_t(p);
    }
    m_tree->points.data = m_points.data();
}

KdTreeIndex::~KdTreeIndex() = default;

size_t KdTreeIndex::nearest_reduced(
    const float* reduced, size_t k, float eps, uint32_t* indices, float* distances) const
{
    nanoflann::KNNResultSet<float, uint32_t, size_t> result(std::min(k, m_vectors.count));
    result.init(indices, distances);
    m_tree->index.findNeighbors(result, reduced, nanoflann::SearchParams(0, eps));
    const size_t n = result.size();
    for (size_t i = 0; i < n; ++i)
        indices[i] = m_order[indices[i]];
    return n;
}

size_t KdTreeIndex::memory_bytes() const
{
    // The tree's own index array (vAcc) is part of m_tree->bytes.
    return m_points.size() * sizeof(float) + m_order.size() * sizeof(uint32_t)
        + m_pca.memory_bytes() + sizeof(Tree) + m_tree->bytes;
}

KdTreeQuery::KdTreeQuery(const KdTreeIndex& index, int candidates, float eps)
    : m_index(index)
    , m_eps(eps)
    , m_candidates(size_t(std::max(candidates, 1)))
{ }

uint32_t KdTreeQuery::nearest(const float* query) const
{
    // Work space per thread (queries run on several workers at once), reused between
    // queries so that they allocate nothing of their own.
    thread_local std::vector<float> reduced, distances;
    thread_local std::vector<uint32_t> indices;
    reduced.resize(size_t(m_index.reduced_dim()));
    indices.resize(m_candidates);
    distances.resize(m_candidates);
    m_index.pca().project(query, reduced.data());
    const size_t n = m_index.nearest_reduced(
        reduced.data(), m_candidates, m_eps, indices.data(), distances.data());
    if (n == 1)
        return indices[0]; // nothing to re-rank
    const VectorSet& set = m_index.vectors();
    for (size_t i = 0; i < n; ++i)
        prefetch_row(set.row(indices[i]), set.dim);
    NearestCandidate best(query, set.dim);
    for (size_t i = 0; i < n; ++i)
        best.offer(indices[i], set.row(indices[i]));
    return best.index();
}

} // namespace texsyn::detail
