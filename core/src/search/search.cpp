// SPDX-License-Identifier: Apache-2.0
// make_search: checks the settings common to every back-end and dispatches.
#include "distance_pvt.h"
#include "search_pvt.h"

#include <limits>
#include <new>

namespace texsyn {

const char* search_method_name(SearchMethod method)
{
    switch (method) {
    case SearchMethod::Exhaustive:
        return "exhaustive";
    case SearchMethod::Tsvq:
        return "tsvq";
    case SearchMethod::KdTree:
        return "kdtree";
    case SearchMethod::Coherent:
        return "coherent";
    }
    return "?";
}

float squared_distance(const float* a, const float* b, int dim)
{
    return detail::distance2(a, b, dim);
}

float squared_distance_below(const float* a, const float* b, int dim, float bound)
{
    return detail::distance2_below(a, b, dim, bound);
}

std::unique_ptr<NeighborSearch> make_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error)
{
    if (!vectors.data || vectors.count < 1 || vectors.dim < 1
        || vectors.count >= size_t(std::numeric_limits<uint32_t>::max())) {
        error = "search: needs 1..2^32-1 vectors of at least 1 component";
        return nullptr;
    }
    try {
        switch (settings.method) {
        case SearchMethod::Exhaustive:
            return detail::make_exhaustive_search(vectors, settings, error);
        case SearchMethod::Tsvq:
            return detail::make_tsvq_search(vectors, settings, error);
        case SearchMethod::KdTree:
            return detail::make_kdtree_search(vectors, settings, error);
        case SearchMethod::Coherent:
            return detail::make_coherent_search(vectors, settings, error);
        }
    } catch (const std::bad_alloc&) {
        error = std::string(search_method_name(settings.method)) + " search: out of memory";
    }
    return nullptr;
}

} // namespace texsyn
