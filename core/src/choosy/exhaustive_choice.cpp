// SPDX-License-Identifier: Apache-2.0
// The exact choice (choosy_pvt.h make_exhaustive_choice): every point, full dimension.
#include "choosy_pvt.h"

#include <limits>

#include <OpenImageIO/parallel.h>

#include "search/distance_pvt.h"

namespace texsyn::detail {

namespace {

// Points whose vectors are written per task when copying them in.
constexpr size_t kFillBlock = 1024;

class ExhaustiveChoice final : public ChoiceIndex {
public:
    ExhaustiveChoice(const AnalysisPoints& points, float penalty, int nthreads)
        : ChoiceIndex(points.orientations)
        , m_dim(points.dim)
        , m_count(points.count)
        , m_vectors(points.count * size_t(points.dim))
        , m_counts(points.sites(), penalty)
    {
        const size_t blocks = (m_count + kFillBlock - 1) / kFillBlock;
        OIIO::parallel_for(
            int64_t(0), int64_t(blocks),
            [&](int64_t b) {
                const size_t end = std::min(m_count, size_t(b + 1) * kFillBlock);
                for (size_t p = size_t(b) * kFillBlock; p < end; ++p)
                    points.vector(p, m_vectors.data() + p * size_t(m_dim));
            },
            OIIO::paropt(nthreads).minitems(1));
    }

    uint32_t choose(const float* query, const uint32_t* hints, size_t nhints) const override
    {
        // Scores are squared distance x factor; a point's distance need only be summed
        // while it can still beat the best (slightly loosened so rounding in the division
        // never drops a point whose product would win). The hints start the bound.
        float best = std::numeric_limits<float>::infinity();
        uint32_t best_point = 0;
        const uint32_t* counts = m_counts.counts();
        auto offer = [&](size_t p) {
            const float f = m_counts.factor(counts[p / m_orientations]);
            const float bound = best / f * 1.0001f;
            const float d
                = distance2_below(query, m_vectors.data() + p * size_t(m_dim), m_dim, bound);
            if (d < bound && (d * f < best || (d * f == best && p < best_point))) {
                best = d * f;
                best_point = uint32_t(p);
            }
        };
        for (size_t h = 0; h < nhints; ++h)
            offer(hints[h]);
        for (size_t p = 0; p < m_count; ++p)
            offer(p);
        return best_point;
    }

    void record(uint32_t point) override { m_counts.add(point / m_orientations); }
    void reset() override { m_counts.reset(); }
    const UseCounts& counts() const override { return m_counts; }

private:
    int m_dim;
    size_t m_count;
    std::vector<float> m_vectors;
    UseCounts m_counts;
};

} // namespace

std::unique_ptr<ChoiceIndex> make_exhaustive_choice(
    const AnalysisPoints& points, float penalty, int nthreads)
{
    return std::make_unique<ExhaustiveChoice>(points, penalty, nthreads);
}

} // namespace texsyn::detail
