// SPDX-License-Identifier: Apache-2.0
#include <algorithm>
#include <tuple>

#include "mesh_detail_pvt.h"

namespace texsyn::detail {

std::vector<EdgeUse> sorted_edge_uses(const std::vector<std::array<uint32_t, 3>>& faces)
{
    std::vector<EdgeUse> uses;
    uses.reserve(faces.size() * 3);
    for (size_t f = 0; f < faces.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t from = faces[f][k], to = faces[f][(k + 1) % 3];
            EdgeUse use;
            use.a = std::min(from, to);
            use.b = std::max(from, to);
            use.face = uint32_t(f);
            use.forward = from < to;
            uses.push_back(use);
        }
    }
    std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return std::tie(x.a, x.b, x.face) < std::tie(y.a, y.b, y.face);
    });
    return uses;
}

} // namespace texsyn::detail
