// SPDX-License-Identifier: Apache-2.0
// The set of dynamic kd-trees (choosy_pvt.h make_kdtree_choice; Castellanos & Williams
// §6.2–6.4).
#include "choosy_pvt.h"

#include <algorithm>
#include <limits>

#include <OpenImageIO/parallel.h>

#include "dynamic_kdtree_pvt.h"
#include "search/pca_pvt.h"

namespace texsyn::detail {

namespace {

// Points projected per task: fixed, so the work split never depends on the thread count.
constexpr size_t kProjectBlock = 1024;

// The PCA is fitted on every orientation of evenly spread sample sites (at most
// PcaProjection::kMaxSamples vectors), so the components do not favour one orientation.
PcaProjection fit_pca(const AnalysisPoints& points, int dims)
{
    const size_t per_site = size_t(points.orientations);
    const size_t nsites = std::min(points.sites(), PcaProjection::kMaxSamples / per_site);
    std::vector<float> vectors(nsites * per_site * size_t(points.dim));
    size_t row = 0;
    for (size_t i = 0; i < nsites; ++i) {
        const size_t site = i * points.sites() / nsites;
        for (size_t t = 0; t < per_site; ++t, ++row)
            points.vector(site * per_site + t, vectors.data() + row * size_t(points.dim));
    }
    VectorSet set;
    set.data = vectors.data();
    set.count = row;
    set.dim = points.dim;
    return PcaProjection(set, std::min(dims, points.dim), 1.0);
}

class KdTreeChoice final : public ChoiceIndex {
public:
    KdTreeChoice(const AnalysisPoints& points, float penalty, int dims, float eps, int nthreads)
        : ChoiceIndex(points.orientations)
        , m_pca(fit_pca(points, dims))
        , m_count(points.count)
        , m_eps(eps)
        , m_reduced(points.count * size_t(m_pca.output_dim()))
        , m_counts(points.sites(), penalty)
    {
        const size_t rd = size_t(m_pca.output_dim());
        const size_t blocks = (m_count + kProjectBlock - 1) / kProjectBlock;
        OIIO::parallel_for(
            int64_t(0), int64_t(blocks),
            [&](int64_t b) {
                std::vector<float> full(size_t(points.dim));
                const size_t end = std::min(m_count, size_t(b + 1) * kProjectBlock);
                for (size_t p = size_t(b) * kProjectBlock; p < end; ++p) {
                    points.vector(p, full.data());
                    m_pca.project(full.data(), m_reduced.data() + p * rd);
                }
            },
            OIIO::paropt(nthreads).minitems(1));
        reset();
    }

    uint32_t choose(const float* query) const override
    {
        thread_local std::vector<float> reduced;
        reduced.resize(size_t(m_pca.output_dim()));
        m_pca.project(query, reduced.data());
        // Trees by increasing count, so the penalty grows and each tree is searched only
        // within the radius that could still beat the best so far (loosened slightly so
        // rounding in the division never drops a winner).
        float best = std::numeric_limits<float>::infinity();
        uint32_t best_point = 0;
        const uint32_t first = m_counts.penalized() ? m_counts.min() : 0;
        for (uint32_t c = first; c < m_trees.size(); ++c) {
            const DynamicKdTree& tree = m_trees[c];
            if (tree.live() == 0)
                continue;
            const float f = m_counts.factor(c);
            const float bound = best / f * 1.0001f;
            uint32_t p = 0;
            const float d = tree.nearest(reduced.data(), bound, m_eps, live(c), p);
            if (d < bound && (d * f < best || (d * f == best && p < best_point))) {
                best = d * f;
                best_point = p;
            }
        }
        return best_point;
    }

    void record(uint32_t point) override
    {
        const uint32_t site = point / m_orientations;
        const uint32_t c = m_counts.count(site);
        m_counts.add(site);
        if (!m_counts.penalized())
            return; // one tree: counts do not change scores
        // The site's points leave tree c for tree c + 1 (§6.4).
        for (uint32_t t = 0; t < m_orientations; ++t)
            m_trees[c].removed(live(c));
        if (m_trees.size() <= c + 1)
            m_trees.emplace_back(m_reduced.data(), m_pca.output_dim());
        for (uint32_t t = 0; t < m_orientations; ++t)
            m_trees[c + 1].insert(site * m_orientations + t, live(c + 1));
    }

    void reset() override
    {
        m_counts.reset();
        m_trees.clear();
        m_trees.emplace_back(m_reduced.data(), m_pca.output_dim());
        std::vector<uint32_t> all(m_count);
        for (size_t p = 0; p < m_count; ++p)
            all[p] = uint32_t(p);
        m_trees[0].assign(std::move(all));
    }

    const UseCounts& counts() const override { return m_counts; }

private:
    // The points tree c holds: those whose site is used c times (all, unpenalized).
    LiveTest live(uint32_t c) const
    {
        if (!m_counts.penalized())
            return LiveTest {};
        return LiveTest { m_counts.counts(), c, m_orientations };
    }

    PcaProjection m_pca;
    size_t m_count;
    float m_eps;
    std::vector<float> m_reduced; // count x output_dim
    UseCounts m_counts;
    std::vector<DynamicKdTree> m_trees; // by use count
};

} // namespace

std::unique_ptr<ChoiceIndex> make_kdtree_choice(
    const AnalysisPoints& points, float penalty, int dims, float eps, int nthreads)
{
    return std::make_unique<KdTreeChoice>(points, penalty, dims, eps, nthreads);
}

} // namespace texsyn::detail
