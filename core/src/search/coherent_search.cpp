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
