// SPDX-License-Identifier: Apache-2.0
// The kd-tree back-end: approximate nearest neighbour on PCA-reduced vectors (nanoflann),
// the reduced-space candidates re-ranked by full distance.
#include "kdtree_pvt.h"
#include "search_pvt.h"

namespace texsyn::detail {
namespace {

class KdTreeSearch final : public NeighborSearch {
public:
    KdTreeSearch(const VectorSet& vectors, const SearchSettings& settings)
        : m_index(vectors, settings.dims, settings.nthreads)
        , m_query(m_index, settings.candidates, settings.eps)
    { }

    uint32_t nearest(const float* query, const uint32_t*, size_t) const override
    {
        return m_query.nearest(query);
    }

    size_t memory_bytes() const override { return m_index.memory_bytes(); }

private:
    KdTreeIndex m_index;
    KdTreeQuery m_query;
};

} // namespace

bool check_kdtree_settings(const SearchSettings& settings, std::string& error)
{
    if (settings.candidates < 1 || settings.dims < 0 || !(settings.eps >= 0.0f)) {
        error = std::string(search_method_name(settings.method))
            + " search: candidates=" + std::to_string(settings.candidates)
            + ", dims=" + std::to_string(settings.dims) + ", eps=" + std::to_string(settings.eps)
            + " (allowed: candidates >= 1, dims >= 0, eps >= 0)";
        return false;
    }
    return true;
}

std::unique_ptr<NeighborSearch> make_kdtree_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error)
{
    if (!check_kdtree_settings(settings, error))
        return nullptr;
    return std::make_unique<KdTreeSearch>(vectors, settings);
}

} // namespace texsyn::detail
