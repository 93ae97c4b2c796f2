// SPDX-License-Identifier: Apache-2.0
// Exhaustive search: every vector, exactly. The oracle the approximate back-ends are
// tested against.
#include "distance_pvt.h"
#include "search_pvt.h"

#include <algorithm>
#include <limits>
#include <vector>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {
namespace {

// Vectors are scanned in fixed chunks, whatever the thread count: each chunk's best is
// exact (lowest index among equals), and the chunks' bests are reduced in chunk order.
constexpr size_t kScanChunk = 2048;

struct Best {
    float distance = std::numeric_limits<float>::infinity();
    uint32_t index = 0;
};

class ExhaustiveSearch final : public NeighborSearch {
public:
    ExhaustiveSearch(const VectorSet& vectors, int nthreads)
        : m_vectors(vectors)
        , m_nthreads(nthreads)
        , m_nchunks((vectors.count + kScanChunk - 1) / kScanChunk)
    { }

    uint32_t nearest(const float* query, const uint32_t*, size_t) const override
    {
        std::vector<Best> bests(m_nchunks);
        // Parallel only when a query is worth a task switch (~a million multiply-adds).
        const bool parallel = m_nchunks > 1 && m_vectors.count * size_t(m_vectors.dim) > (1u << 20);
        if (parallel)
            OIIO::parallel_for(
                int64_t(0), int64_t(m_nchunks),
                [&](int64_t c) { bests[size_t(c)] = scan(query, size_t(c)); },
                detail::split_every_item(m_nthreads));
        else
            for (size_t c = 0; c < m_nchunks; ++c)
                bests[c] = scan(query, c);
        Best best;
        for (const Best& b : bests)
            if (b.distance < best.distance)
                best = b;
        return best.index;
    }

    size_t memory_bytes() const override { return 0; }

private:
    Best scan(const float* query, size_t chunk) const
    {
        const size_t begin = chunk * kScanChunk;
        const size_t end = std::min(m_vectors.count, begin + kScanChunk);
        const int dim = m_vectors.dim;
        Best best { std::numeric_limits<float>::infinity(), uint32_t(begin) };
        for (size_t i = begin; i < end; ++i) {
            const float d = distance2_below(query, m_vectors.row(i), dim, best.distance);
            if (d < best.distance)
                best = { d, uint32_t(i) };
        }
        return best;
    }

    VectorSet m_vectors;
    int m_nthreads;
    size_t m_nchunks;
};

} // namespace

std::unique_ptr<NeighborSearch> make_exhaustive_search(
    const VectorSet& vectors, const SearchSettings& settings, std::string&)
{
    return std::make_unique<ExhaustiveSearch>(vectors, settings.nthreads);
}

} // namespace texsyn::detail
