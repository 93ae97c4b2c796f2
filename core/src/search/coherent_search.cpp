// SPDX-License-Identifier: Apache-2.0
// PLACEHOLDER: replaced by the real back-end before this lands.
#include "search_pvt.h"

namespace texsyn::detail {

std::unique_ptr<NeighborSearch> make_coherent_search(
    const VectorSet&, const SearchSettings&, std::string& error)
{
    error = "search=coherent is not available yet";
    return nullptr;
}

} // namespace texsyn::detail
