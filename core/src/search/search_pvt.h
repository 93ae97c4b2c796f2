// SPDX-License-Identifier: Apache-2.0
// The search back-ends, one file each; make_search (search.cpp) chooses.
#pragma once

#include <memory>
#include <string>

#include <texsyn/search.h>

namespace texsyn::detail {

std::unique_ptr<NeighborSearch> make_exhaustive_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error);
std::unique_ptr<NeighborSearch> make_tsvq_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error);
std::unique_ptr<NeighborSearch> make_kdtree_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error);
std::unique_ptr<NeighborSearch> make_coherent_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string& error);

} // namespace texsyn::detail
