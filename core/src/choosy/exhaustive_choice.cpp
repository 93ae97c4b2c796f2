// SPDX-License-Identifier: Apache-2.0
// The exact choice (choosy_pvt.h make_exhaustive_choice): every point, full dimension.
#include "choosy_pvt.h"

#include <algorithm>
#include <limits>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

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

class ExhaustiveChoice final : public ChoiceIndex {
public:
    ExhaustiveChoice(const AnalysisPoints& points, float penalty, int nthreads)
        : ChoiceIndex(points.orientations)
        , m_dim(points.dim)
        , m_count(points.count)
        , m_vectors(points.count * size_t(points.dim))
        , m_counts(points.sites(), penalty)
        , m_masked(points)
    {
        const size_t blocks = (m_count + kFillBlock - 1) / kFillBlock;
        OIIO::parallel_for(
            int64_t(0), int64_t(blocks),
            [&](int64_t b) {
                const size_t end = std::min(m_count, size_t(b + 1) * kFillBlock);
                for (size_t p = size_t(b) * kFillBlock; p < end; ++p)
                    points.vector(p, m_vectors.data() + p * size_t(m_dim));
            },
            detail::split_every_item(nthreads));
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
        return m_masked.choose(m_counts, query, mask, hints, nhints);
    }

    void record(uint32_t point) override { m_counts.add(point / m_orientations); }
    void reset() override { m_counts.reset(); }
    const UseCounts& counts() const override { return m_counts; }

private:
    int m_dim;
    size_t m_count;
    std::vector<float> m_vectors;
    UseCounts m_counts;
    MaskedChoice m_masked;
};

} // namespace

MaskedChoice::MaskedChoice(const AnalysisPoints& points)
    : m_points(points)
{ }

uint32_t MaskedChoice::choose(const UseCounts& counts, const float* query, const float* mask,
    const uint32_t* hints, size_t nhints) const
{
    const size_t count = m_points.count, dim = size_t(m_points.dim);
    const size_t blocks = (dim + kBlock - 1) / kBlock, stride = count * size_t(kBlock);
    // Serial: it runs inside a pass's parallel loop (no nested parallel loops).
    std::call_once(m_once, [&] {
        m_blocks.assign(blocks * stride, 0.0f);
        std::vector<float> v(dim);
        for (size_t p = 0; p < count; ++p) {
            m_points.vector(p, v.data());
            for (size_t i = 0; i < dim; ++i)
                m_blocks[i / kBlock * stride + p * kBlock + i % kBlock] = v[i];
        }
    });
    thread_local std::vector<float> q, m;
    q.assign(blocks * kBlock, 0.0f);
    m.assign(blocks * kBlock, 0.0f);
    std::copy(query, query + dim, q.begin());
    std::copy(mask, mask + dim, m.begin());
    const float* data = m_blocks.data();
    // Checked after every block: exact, as distance2_below.
    return least_score_point(
        count, uint32_t(m_points.orientations), counts, hints, nhints, [&](size_t p, float bound) {
            SquaredDifferenceLanes lanes;
            float partial = 0.0f;
            for (size_t b = 0; b < blocks; ++b) {
                lanes.add_masked(q.data() + b * kBlock, data + b * stride + p * kBlock,
                    m.data() + b * kBlock, int(kBlock));
                partial = lanes.sum();
                if (partial >= bound)
                    break;
            }
            return partial;
        });
}

std::unique_ptr<ChoiceIndex> make_exhaustive_choice(
    const AnalysisPoints& points, float penalty, int nthreads)
{
    return std::make_unique<ExhaustiveChoice>(points, penalty, nthreads);
}

} // namespace texsyn::detail
