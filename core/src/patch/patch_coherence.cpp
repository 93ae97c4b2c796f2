// SPDX-License-Identifier: Apache-2.0
// k-coherence lists of a sample level's patches (Tong et al. 2002): for every patch centre
// the few most similar patches elsewhere in the sample, found with the kd-tree the
// neighbourhood method uses (search/kdtree_pvt.h) and ranked by full distance.
#include "patch_pvt.h"

#include <algorithm>
#include <cstdlib>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "search/kdtree_pvt.h"

namespace texsyn::detail {

namespace {

constexpr int kReducedDims = 8;  // PCA components of the kd-tree
constexpr float kTreeEps = 2.0f; // nanoflann's approximation
constexpr int kCandidates = 4;   // extra reduced-space matches re-ranked
constexpr int kExclusion = 2;    // centres this close (each axis) are the same patch

} // namespace

std::vector<uint32_t> similar_patches(const PixelImage& sample, int cell_width, int patch,
    int coherence, int nthreads, const StopFlag* stop)
{
    const CentreRange range { sample.width, sample.height, patch / 2, cell_width };
    if (coherence < 2 || range.empty())
        return {};
    const size_t k = size_t(coherence - 1);
    const int cw = range.columns(), half = patch / 2;
    // The descriptor of a patch: every other pixel of it, each way (a quarter of the
    // values, which keeps the PCA and the ranking cheap and sees the same structure).
    const int side = (patch + 1) / 2, c = sample.channels, dim = side * side * c;
    const size_t count = range.count();
    std::vector<float> vectors(count * size_t(dim));
    OIIO::parallel_for(
        int64_t(0), int64_t(count),
        [&](int64_t i) {
            const int cx = range.column_x(int(i % cw)), cy = range.y0() + int(i / cw);
            float* v = vectors.data() + size_t(i) * size_t(dim);
            for (int r = 0; r < side; ++r)
                for (int t = 0; t < side; ++t, v += c)
                    std::copy_n(sample.pixel(cx - half + 2 * t, cy - half + 2 * r), c, v);
        },
        detail::split_every_item(nthreads));
    const VectorSet set { vectors.data(), count, dim };
    const KdTreeIndex index(set, kReducedDims, nthreads);

    // Near-identical neighbours (centres within kExclusion pixels, each way) are not
    // "similar patches elsewhere".
    const std::vector<uint32_t> similar = similar_lists(
        index, k, kCandidates, kTreeEps, nthreads, (2 * kExclusion + 1) * (2 * kExclusion + 1),
        [cw](uint32_t i, uint32_t j) {
            const int dx = int(j % uint32_t(cw)) - int(i % uint32_t(cw));
            const int dy = int(j / uint32_t(cw)) - int(i / uint32_t(cw));
            return std::abs(dx) <= kExclusion && std::abs(dy) <= kExclusion;
        },
        stop);
    // Vector indices to sample indices, rows moved to their centres.
    auto centre = [&](uint32_t i) {
        return uint32_t(range.y0() + int(i / uint32_t(cw))) * uint32_t(sample.width)
            + uint32_t(range.column_x(int(i % uint32_t(cw))));
    };
    std::vector<uint32_t> lists(size_t(sample.width) * size_t(sample.height) * k);
    for (uint32_t i = 0; i < count; ++i)
        for (size_t j = 0; j < k; ++j)
            lists[size_t(centre(i)) * k + j] = centre(similar[size_t(i) * k + j]);
    return lists;
}

} // namespace texsyn::detail
