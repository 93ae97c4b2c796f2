// SPDX-License-Identifier: Apache-2.0
// What a result copies: how much of the sample it uses, and its largest verbatim copy.
#include "patch_pvt.h"

#include <algorithm>
#include <numeric>

namespace texsyn::detail {

namespace {

// Union-find with path halving (only the sizes of the sets are read).
struct Sets {
    std::vector<uint32_t> parent;
    explicit Sets(size_t n)
        : parent(n)
    {
        std::iota(parent.begin(), parent.end(), 0u);
    }
    uint32_t find(uint32_t i)
    {
        while (parent[i] != i)
            i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(uint32_t a, uint32_t b)
    {
        a = find(a);
        b = find(b);
        if (a != b)
            parent[std::max(a, b)] = std::min(a, b);
    }
};

} // namespace

double used_fraction(const std::vector<uint32_t>& source, size_t npixels)
{
    std::vector<char> used(npixels, 0);
    for (uint32_t s : source)
        used[s] = 1;
    return double(std::count(used.begin(), used.end(), 1)) / double(npixels);
}

size_t largest_copy(const std::vector<uint32_t>& source, int width, int height, int sample_width,
    int sample_height, bool wrap_x, bool wrap_y)
{
    // Neighbours copy neighbours: the right neighbour holds the next sample pixel of the
    // same row, the one below the pixel of the next sample row.
    Sets sets(source.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const uint32_t q = uint32_t(y) * uint32_t(width) + uint32_t(x);
            const uint32_t s = source[q];
            const uint32_t right = uint32_t(y) * uint32_t(width) + uint32_t((x + 1) % width);
            const uint32_t below = uint32_t((y + 1) % height) * uint32_t(width) + uint32_t(x);
            if ((wrap_x || x + 1 < width) && int(s % uint32_t(sample_width)) + 1 < sample_width
                && source[right] == s + 1)
                sets.join(q, right);
            if ((wrap_y || y + 1 < height) && int(s / uint32_t(sample_width)) + 1 < sample_height
                && source[below] == s + uint32_t(sample_width))
                sets.join(q, below);
        }
    std::vector<uint32_t> size(source.size(), 0);
    size_t largest = 0;
    for (uint32_t q = 0; q < source.size(); ++q)
        largest = std::max<size_t>(largest, ++size[sets.find(q)]);
    return largest;
}

} // namespace texsyn::detail
