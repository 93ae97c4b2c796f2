// SPDX-License-Identifier: Apache-2.0
// The coherent back-end: k-coherence search (Ashikhmin 2001 for k = 1, Tong et al. 2002 for
// k > 1) over the coherence hints, with the kd-tree as fallback and optional merge.
#include "distance_pvt.h"
#include "kdtree_pvt.h"
#include "search_pvt.h"

#include <algorithm>
#include <utility>

#include <OpenImageIO/parallel.h>

namespace texsyn::detail {
namespace {

// Vectors whose similar lists one task builds: fixed, whatever the thread count.
constexpr size_t kListBlock = 256;

// Row i: the `k` vectors most similar to vector i (full distance; i excluded), nearest
// first, ties to the lowest index. The `k + candidates` nearest in reduced space (plus i
// itself) are re-ranked; a set with fewer than k other vectors pads the row with i.
// Vectors are taken in the tree's order (neighbours in space one after the other: the
// searches share cache lines); each row depends on its vector alone.
std::vector<uint32_t> similar_lists(
    const KdTreeIndex& index, size_t k, size_t candidates, float eps, int nthreads)
{
    const VectorSet& set = index.vectors();
    std::vector<uint32_t> lists(set.count * k);
    if (k == 0)
        return lists;
    const size_t pool = k + candidates + 1;
    const size_t blocks = (set.count + kListBlock - 1) / kListBlock;
    OIIO::parallel_for(
        int64_t(0), int64_t(blocks),
        [&](int64_t b) {
            std::vector<uint32_t> found(pool);
            std::vector<float> reduced(pool);
            std::vector<std::pair<float, uint32_t>> ranked;
            const size_t end = std::min(set.count, size_t(b + 1) * kListBlock);
            for (size_t p = size_t(b) * kListBlock; p < end; ++p) {
                const uint32_t i = index.original(p);
                const size_t n = index.nearest_reduced(
                    index.point(p), pool, eps, found.data(), reduced.data());
                ranked.clear();
                for (size_t j = 0; j < n; ++j)
                    if (found[j] != i)
                        ranked.emplace_back(
                            distance2(set.row(i), set.row(found[j]), set.dim), found[j]);
                const size_t keep = std::min(k, ranked.size());
                std::partial_sort(
                    ranked.begin(), ranked.begin() + std::ptrdiff_t(keep), ranked.end());
                uint32_t* row = lists.data() + size_t(i) * k;
                for (size_t j = 0; j < k; ++j)
                    row[j] = j < keep ? ranked[j].second : i;
            }
        },
        OIIO::paropt(nthreads).minitems(1));
    return lists;
}

class CoherentSearch final : public NeighborSearch {
public:
    CoherentSearch(const VectorSet& vectors, const SearchSettings& settings)
        : m_index(vectors, settings.dims, settings.nthreads)
        , m_query(m_index, settings.candidates, settings.eps)
        , m_k(size_t(settings.coherence - 1))
        , m_lists(similar_lists(
              m_index, m_k, size_t(settings.candidates), settings.eps, settings.nthreads))
        , m_merge(settings.merge)
    { }

    uint32_t nearest(const float* query, const uint32_t* hints, size_t nhints) const override
    {
        // The candidates, each once (seen[i] == stamp once listed), are gathered first and
        // fetched from memory together, then evaluated. The work space is per thread
        // (queries run on several workers at once) and kept between queries; a thread's
        // stamps only grow, so marks left by another searcher's queries never match.
        thread_local std::vector<uint32_t> seen, candidates;
        thread_local uint32_t stamp = 0;
        const VectorSet& set = m_index.vectors();
        if (seen.size() < set.count)
            seen.resize(set.count, 0u);
        if (++stamp == 0) {
            std::fill(seen.begin(), seen.end(), 0u);
            stamp = 1;
        }
        candidates.clear();
        auto add = [&](uint32_t i) {
            if (seen[i] != stamp) {
                seen[i] = stamp;
                candidates.push_back(i);
                prefetch_row(set.row(i), set.dim);
            }
        };
        for (size_t h = 0; h < nhints; ++h) {
            const uint32_t hint = hints[h];
            if (hint >= set.count) // outside the contract: ignored rather than read past
                continue;
            add(hint);
            const uint32_t* similar = m_lists.data() + size_t(hint) * m_k;
            for (size_t j = 0; j < m_k; ++j)
                add(similar[j]);
        }
        if (m_merge || candidates.empty())
            add(m_query.nearest(query));
        NearestCandidate best(query, set.dim);
        for (uint32_t i : candidates)
            best.offer(i, set.row(i));
        return best.index();
    }

    size_t memory_bytes() const override
    {
        // Plus, per thread that queried, a stamp per vector (4 bytes each).
        return m_index.memory_bytes() + m_lists.size() * sizeof(uint32_t);
    }

private:
    KdTreeIndex m_index;
    KdTreeQuery m_query;
    size_t m_k; // similar vectors listed per vector: coherence - 1
    std::vector<uint32_t> m_lists;
    bool m_merge;
};

} // namespace

std::unique_ptr<NeighborSearch> make_coherent_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error)
{
    if (settings.coherence < 1) {
        error = "coherent search: coherence=" + std::to_string(settings.coherence)
            + " (allowed: 1 or more)";
        return nullptr;
    }
    if (!check_kdtree_settings(settings, error))
        return nullptr;
    return std::make_unique<CoherentSearch>(vectors, settings);
}

} // namespace texsyn::detail
