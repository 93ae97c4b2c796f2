// SPDX-License-Identifier: Apache-2.0
// Nearest-neighbour search over a fixed set of float vectors (the neighbourhoods of a
// texture sample), behind one interface (Wei & Levoy 2000; the implementation report's
// §3.3.1 and §6.2–6.3 for TSVQ; Ashikhmin 2001 / Tong et al. 2002 for coherence).
//
// Rules for this header:
//  - Distances are squared Euclidean (L2) over all `dim` components, summed in a fixed
//    order (squared_distance), so every back-end ranks vectors identically.
//  - Ties go to the lowest vector index: results never depend on thread count or timing.
//  - A searcher is built once per vector set; nearest() is const and safe to call from
//    several threads at once (the synthesis runs rows as a wavefront); it may use OIIO's
//    thread pool inside.
//  - The vector set must outlive the searcher (it is not copied).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// `count` vectors of `dim` floats, row-major and contiguous.
struct VectorSet {
    const float* data = nullptr;
    size_t count = 0;
    int dim = 0;
    const float* row(size_t i) const { return data + i * size_t(dim); }
};

/// The search back-ends.
enum class SearchMethod {
    /// Every vector, exactly: the oracle for the others. Vectorised, parallel over the
    /// vectors, early-abandoning partial sums.
    Exhaustive,
    /// Tree-structured vector quantizer (the report's §3.3.1, §6.2–6.3): a binary tree
    /// built by recursive 2-means (generalized Lloyd), each node's codeword the centre its
    /// vectors were assigned by (their centroid once the iteration converged), leaves of at
    /// most 16 vectors. A query descends to the child with the nearer codeword (ties left);
    /// `candidates` = k leaves are visited best-first (backtracking to the unexplored
    /// sibling whose codeword is nearest the query) and their vectors compared exactly.
    /// k = 1 is the report's plain descent; k >= the number of leaves is exact. A vector of
    /// the set always finds itself or an identical one. Holds 4 bytes per vector plus the
    /// codewords (about 0.2x the vector set on texture neighbourhoods); the tree does not
    /// depend on nthreads. Fails if candidates < 1.
    Tsvq,
    /// Approximate nearest neighbour (nanoflann kd-tree) on PCA-reduced vectors: `dims`
    /// components kept (0 = enough for 95% of the variance; the PCA is fitted on at most
    /// 4096 evenly spread vectors), `eps` the kd-tree's approximation (0 = exact in the
    /// reduced space); the `candidates` nearest in the reduced space are re-ranked with
    /// full distances.
    KdTree,
    /// The hints (the source positions of already synthesized neighbours, shifted) and
    /// their `coherence` - 1 most similar vectors each (k-coherence; precomputed for every
    /// vector by re-ranking the kd-tree's `coherence` - 1 + `candidates` nearest with full
    /// distances), optionally merged with the kd-tree's answer (`merge`); the best of them
    /// by full distance. Without hints (or with only invalid ones) it is the kd-tree's
    /// answer. The kd-tree is KdTree's, with the same dims, eps and candidates.
    Coherent,
};

/// "exhaustive", "tsvq", "kdtree" or "coherent".
const char* search_method_name(SearchMethod method);

/// The settings of a searcher (each back-end reads its own).
struct SearchSettings {
    SearchMethod method = SearchMethod::Exhaustive;
    int candidates = 1; ///< tsvq: leaves visited; kdtree: reduced-space matches re-ranked
    int dims = 0;       ///< kdtree: PCA components kept; 0 = 95% of the variance
    float eps = 0.0f;   ///< kdtree: approximation factor (nanoflann's eps)
    int coherence = 1;  ///< coherent: k of k-coherence (1 = Ashikhmin's)
    bool merge = false; ///< coherent: also ask the kd-tree
    int nthreads = 0;   ///< OIIO's convention; never changes results
};

/// Searches one VectorSet.
class NeighborSearch {
public:
    virtual ~NeighborSearch() = default;
    /// The index of the vector nearest `query` (dim floats). `hints` (nhints indices < count)
    /// are candidates the caller suggests: Coherent searches them (and their k-coherent
    /// neighbours); the other back-ends ignore them. Coherent with no hints and no merge
    /// falls back to the kd-tree.
    virtual uint32_t nearest(const float* query, const uint32_t* hints, size_t nhints) const = 0;
    /// Bytes the searcher holds beyond the vector set (for memory estimates).
    virtual size_t memory_bytes() const = 0;
};

/// A searcher of `settings.method` over `vectors` (count >= 1, dim >= 1, count < 2^32).
/// Returns nullptr with `error` if the settings are out of range or memory runs out.
std::unique_ptr<NeighborSearch> make_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error);

/// sum_i (a[i] - b[i])^2 in a fixed order (eight interleaved partial sums, then added
/// pairwise), identical on every thread and in every back-end.
float squared_distance(const float* a, const float* b, int dim);

/// squared_distance(a, b, dim) if it is < bound; otherwise some value >= bound (the sum
/// is abandoned once a block of it reaches `bound`). Exact where it matters: the result
/// is < bound exactly when squared_distance is.
float squared_distance_below(const float* a, const float* b, int dim, float bound);

} // namespace texsyn
#pragma GCC visibility pop
