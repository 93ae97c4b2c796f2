// SPDX-License-Identifier: Apache-2.0
// k-coherence lists over a KdTreeIndex (kdtree_pvt.h): each vector's most similar others.
#include "kdtree_pvt.h"

#include <algorithm>
#include <utility>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "distance_pvt.h"

namespace texsyn::detail {

namespace {

// Vectors whose similar lists one task builds: fixed, whatever the thread count.
constexpr size_t kListBlock = 256;

} // namespace

std::vector<uint32_t> similar_lists(const KdTreeIndex& index, size_t k, size_t candidates,
    float eps, int nthreads, size_t excluded_count,
    const std::function<bool(uint32_t, uint32_t)>& excluded, const StopFlag* stop)
{
    const VectorSet& set = index.vectors();
    std::vector<uint32_t> lists(set.count * k);
    if (k == 0)
        return lists;
    const size_t pool = k + candidates + 1 + excluded_count;
    const size_t blocks = (set.count + kListBlock - 1) / kListBlock;
    OIIO::parallel_for(
        int64_t(0), int64_t(blocks),
        [&](int64_t b) {
            if (stop_requested(stop))
                return;
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
                    if (found[j] != i && !(excluded && excluded(i, found[j])))
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
        detail::split_every_item(nthreads));
    return lists;
}

} // namespace texsyn::detail
