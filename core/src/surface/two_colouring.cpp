// SPDX-License-Identifier: Apache-2.0
// §3.5's black/white colouring of a base mesh's faces (Sirl-Moore & Williams): a
// breadth-first colouring, each face opposite to most of its coloured neighbours, then
// sweeps that flip faces with more same-colour neighbours than others.
#include "face_level_pvt.h"

#include <deque>

namespace texsyn::detail {

namespace {

// Edge-adjacent faces of f with colour `c` (coloured ones only: colour < 2).
int neighbours_coloured(const FaceLevel& level, uint32_t f, uint8_t c)
{
    int n = 0;
    for (uint32_t g : level.across[f])
        if (g != kNoFace && level.colour[g] == c)
            ++n;
    return n;
}

} // namespace

size_t two_colour(FaceLevel& level)
{
    constexpr uint8_t kUncoloured = 2;
    const size_t nf = level.size();
    level.colour.assign(nf, kUncoloured);
    std::deque<uint32_t> queue;
    for (uint32_t start = 0; start < nf; ++start) {
        if (level.colour[start] != kUncoloured)
            continue;
        level.colour[start] = 0;
        queue.push_back(start);
        while (!queue.empty()) {
            const uint32_t f = queue.front();
            queue.pop_front();
            for (uint32_t g : level.across[f]) {
                if (g == kNoFace || level.colour[g] != kUncoloured)
                    continue;
                // Opposite to most of its coloured neighbours (to f's on a tie).
                const int black = neighbours_coloured(level, g, 0);
                const int white = neighbours_coloured(level, g, 1);
                level.colour[g] = black != white ? uint8_t(black > white ? 1 : 0)
                                                 : uint8_t(1 - level.colour[f]);
                queue.push_back(g);
            }
        }
    }
    // Flip faces that have more same-colour neighbours than other-colour ones; each flip
    // removes at least one conflict, so this ends.
    for (bool changed = true; changed;) {
        changed = false;
        for (uint32_t f = 0; f < nf; ++f) {
            const uint8_t c = level.colour[f];
            if (neighbours_coloured(level, f, c) > neighbours_coloured(level, f, uint8_t(1 - c))) {
                level.colour[f] = uint8_t(1 - c);
                changed = true;
            }
        }
    }
    size_t conflicts = 0;
    for (uint32_t f = 0; f < nf; ++f)
        for (uint32_t g : level.across[f])
            if (g != kNoFace && g > f && level.colour[g] == level.colour[f])
                ++conflicts;
    return conflicts;
}

} // namespace texsyn::detail
