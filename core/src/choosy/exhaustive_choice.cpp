// SPDX-License-Identifier: Apache-2.0
// The exact choice (choosy_pvt.h make_exhaustive_choice): every point, full dimension.
#include "choosy_pvt.h"

#include <algorithm>
#include <limits>

#include <OpenImageIO/parallel.h>

#include "search/distance_pvt.h"

namespace texsyn::detail {

namespace {

// Points whose vectors are written per task when copying them in.
constexpr size_t kFillBlock = 1024;

// The best of `count` points (and the hints first) by squared distance x factor, where
// distance_below(p, bound) is point p's distance if it is < bound, else a value >= bound.
// Scores are squared distance x factor; a point's distance need only be summed while it can
// still beat the best (slightly loosened so rounding in the division never drops a point
// whose product would win). The hints start the bound.
template <class DistanceBelow>
uint32_t least_score_point(size_t count, uint32_t orientations, const UseCounts& use,
    const uint32_t* hints, size_t nhints, DistanceBelow distance_below)
{
    float best = std::numeric_limits<float>::infinity();
    uint32_t best_point = 0;
    const uint32_t* counts = use.counts();
    auto offer = [&](size_t p) {
        const float f = use.factor(counts[p / orientations]);
        const float bound = best / f * 1.0001f;
        const float d = distance_below(p, bound);
        if (d < bound && (d * f < best || (d * f == best && p < best_point))) {
            best = d * f;
            best_point = uint32_t(p);
        }
    };
    for (size_t h = 0; h < nhints; ++h)
        offer(hints[h]);
    for (size_t p = 0; p < count; ++p)
        offer(p);
    return best_point;
}

// Sum over i of (mask[i] (a[i] - b[i]))^2 if it is < bound, else a value >= bound: the
// lanes of distance2_below, checked every 16 components.
float masked_distance2_below(
    const float* a, const float* b, const float* mask, int dim, float bound)
{
    float acc[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
    constexpr int block = 16;
    int i = 0;
    for (; i + 8 <= dim; i += 8) {
        for (int l = 0; l < 8; ++l) {
            const float d = (a[i + l] - b[i + l]) * mask[i + l];
            acc[l] += d * d;
        }
        if ((i + 8) % block == 0) {
            const float partial = sum_lanes(acc);
            if (partial >= bound)
                return partial;
        }
    }
    for (int l = 0; i + l < dim; ++l) {
        const float d = (a[i + l] - b[i + l]) * mask[i + l];
        acc[l] += d * d;
    }
    return sum_lanes(acc);
}

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
        return least_score_point(
            m_count, m_orientations, m_counts, hints, nhints, [&](size_t p, float bound) {
                return distance2_below(query, m_vectors.data() + p * size_t(m_dim), m_dim, bound);
            });
    }

    uint32_t choose_masked(
        const float* query, const float* mask, const uint32_t* hints, size_t nhints) const override
    {
        return choose_masked_exhaustively(
            m_vectors.data(), m_count, m_dim, m_orientations, m_counts, query, mask, hints, nhints);
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

uint32_t choose_masked_exhaustively(const float* vectors, size_t count, int dim,
    uint32_t orientations, const UseCounts& counts, const float* query, const float* mask,
    const uint32_t* hints, size_t nhints)
{
    return least_score_point(
        count, orientations, counts, hints, nhints, [&](size_t p, float bound) {
            return masked_distance2_below(query, vectors + p * size_t(dim), mask, dim, bound);
        });
}

std::unique_ptr<ChoiceIndex> make_exhaustive_choice(
    const AnalysisPoints& points, float penalty, int nthreads)
{
    return std::make_unique<ExhaustiveChoice>(points, penalty, nthreads);
}

} // namespace texsyn::detail
