// SPDX-License-Identifier: Apache-2.0
// The kd-tree over PCA-reduced vectors that the KdTree and Coherent back-ends share
// (search.h). nanoflann stays inside kdtree_index.cpp: this header does not include it.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <texsyn/search.h>
#include <texsyn/stop.h>

#include "pca_pvt.h"

namespace texsyn::detail {

/// Checks what the kd-tree reads (candidates >= 1, dims >= 0, eps >= 0 and not NaN); false
/// with a message naming the values otherwise.
bool check_kdtree_settings(const SearchSettings& settings, std::string& error);

/// A nanoflann kd-tree over the PCA projections of a VectorSet (`dims` components; 0 =
/// enough for kVarianceFraction of the variance). Building is deterministic: the PCA is
/// (pca_pvt.h), every vector is projected by the same code whatever thread does it, and
/// nanoflann builds serially.
/// Thread safety: immutable after construction; const methods may be called concurrently.
class KdTreeIndex {
public:
    static constexpr double kVarianceFraction = 0.95;

    /// Projects `vectors` (which must outlive the index) in parallel over `nthreads` and
    /// builds the tree. May throw std::bad_alloc.
    KdTreeIndex(const VectorSet& vectors, int dims, int nthreads);
    ~KdTreeIndex();

    const VectorSet& vectors() const { return m_vectors; }
    const PcaProjection& pca() const { return m_pca; }
    int reduced_dim() const { return m_pca.output_dim(); }

    /// The projections are stored in the tree's order (leaf by leaf): position p holds the
    /// projection of vector original(p), reduced_dim() floats. Walking positions in order
    /// visits vectors that are near in reduced space one after the other.
    const float* point(size_t position) const
    {
        return m_points.data() + position * size_t(reduced_dim());
    }
    uint32_t original(size_t position) const { return m_order[position]; }

    /// The k nearest points (in reduced space) to `reduced`, nearest first, allowing
    /// nanoflann's approximation `eps`: their vector indices in indices[0, n) and reduced
    /// squared distances, n = min(k, count) returned. Equal reduced distances keep tree
    /// order (deterministic).
    size_t nearest_reduced(
        const float* reduced, size_t k, float eps, uint32_t* indices, float* distances) const;

    /// Bytes held beyond the vector set: projections, PCA, tree nodes and index.
    size_t memory_bytes() const;

private:
    struct Tree; // nanoflann's index, defined in kdtree_index.cpp

    VectorSet m_vectors;
    PcaProjection m_pca;
    std::vector<float> m_points;   // projections in tree order
    std::vector<uint32_t> m_order; // position -> vector index
    std::unique_ptr<Tree> m_tree;
};

/// Queries of a KdTreeIndex, answered as the KdTree back-end does: the query projected, its
/// `candidates` nearest in reduced space (eps), re-ranked by full distance (ties: lowest
/// index; a single candidate is returned as is). Its work space is per thread and reused,
/// so a query allocates nothing of its own (nanoflann allocates one small vector per search).
/// Thread safety: nearest() may be called concurrently.
class KdTreeQuery {
public:
    KdTreeQuery(const KdTreeIndex& index, int candidates, float eps);

    uint32_t nearest(const float* query) const;

private:
    const KdTreeIndex& m_index;
    float m_eps;
    size_t m_candidates;
};

/// Row i: the `k` vectors most similar to vector i of the index's set (full distance; i
/// itself and every j with excluded(i, j) left out), nearest first, ties to the lowest
/// index. The `k + candidates + excluded_count` nearest in reduced space (plus i itself;
/// `excluded_count` at most are expected to be excluded) are re-ranked; a row with fewer
/// than k such vectors is padded with i. Vectors are taken in the tree's order (neighbours
/// in space one after the other: the searches share cache lines); each row depends on its
/// vector alone, so the lists do not depend on nthreads. Once `stop` is set (stop.h) the
/// blocks of rows not yet started are skipped, leaving them unspecified: the caller checks.
std::vector<uint32_t> similar_lists(const KdTreeIndex& index, size_t k, size_t candidates,
    float eps, int nthreads, size_t excluded_count = 0,
    const std::function<bool(uint32_t, uint32_t)>& excluded = {}, const StopFlag* stop = nullptr);

} // namespace texsyn::detail
