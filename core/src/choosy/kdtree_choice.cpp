// SPDX-License-Identifier: Apache-2.0
// The set of dynamic kd-trees (choosy_pvt.h make_kdtree_choice; Castellanos & Williams
// §6.2–6.4).
#include "choosy_pvt.h"

#include <algorithm>
#include <limits>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "dynamic_kdtree_pvt.h"
#include "search/distance_pvt.h"
#include "search/pca_pvt.h"

namespace texsyn::detail {

namespace {

// Points projected per task: fixed, so the work split never depends on the thread count.
constexpr size_t kProjectBlock = 1024;

// Sites chosen before their points move trees, at least (see settle()).
constexpr size_t kMinSettle = 256;

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

// Trees are keyed by use count: the points of a site used c times are in tree c (§6.4). A
// chosen site is scored with its new count at once, but its points move to their new tree
// in bulk, at the end of a round once enough sites are waiting (settle), rather than one
// site at a time. Scores stay exact meanwhile: a tree's search bound uses the least
// penalty its points can have, and each point is scored with its own count.
class KdTreeChoice final : public ChoiceIndex {
public:
    KdTreeChoice(const AnalysisPoints& points, float penalty, int dims, float eps, int nthreads)
        : ChoiceIndex(points.orientations)
        , m_pca(fit_pca(points, dims))
        , m_count(points.count)
        , m_eps(eps)
        , m_reduced(points.count * size_t(m_pca.output_dim()))
        , m_counts(points.sites(), penalty)
        , m_home(points.sites(), 0)
        , m_pending_flag(points.sites(), 0)
        , m_nthreads(nthreads)
        , m_masked(points)
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
            detail::split_every_item(nthreads));
        reset();
    }

    uint32_t choose(const float* query, const uint32_t* hints, size_t nhints) const override
    {
        thread_local std::vector<float> reduced;
        const int rd = m_pca.output_dim();
        reduced.resize(size_t(rd));
        m_pca.project(query, reduced.data());
        const PointPenalty penalty = point_penalty();
        // The hints (k-coherence) give a first bound.
        float best = std::numeric_limits<float>::infinity();
        uint32_t best_point = 0;
        for (size_t h = 0; h < nhints; ++h) {
            const uint32_t p = hints[h];
            const float d = penalty(p)
                * distance2(reduced.data(), m_reduced.data() + size_t(p) * size_t(rd), rd);
            if (d < best || (d == best && p < best_point)) {
                best = d;
                best_point = p;
            }
        }
        // Trees by increasing count, so the penalty grows and each tree is searched only
        // within the radius that could still beat the best so far.
        for (uint32_t c = 0; c < m_trees.size(); ++c) {
            const DynamicKdTree& tree = m_trees[c];
            if (tree.live() == 0)
                continue;
            const float least = m_counts.factor(std::max(c, m_counts.min()));
            uint32_t p = 0;
            const float score
                = tree.nearest(reduced.data(), best, m_eps, live(c), penalty, least, p);
            if (score < best) {
                best = score;
                best_point = p;
            }
        }
        return best_point;
    }

    uint32_t choose_masked(
        const float* query, const float* mask, const uint32_t* hints, size_t nhints) const override
    {
        return m_masked.choose(m_counts, query, mask, hints, nhints);
    }

    void record(uint32_t point) override
    {
        const size_t site = site_of(point);
        m_counts.add(site);
        if (m_counts.penalized() && !m_pending_flag[site]) {
            m_pending_flag[site] = 1;
            m_pending.push_back(uint32_t(site));
        }
    }

    void settle() override
    {
        // Moving points costs tree rebuilds; waiting until half the sites have been chosen
        // (or 256) rebuilds in larger batches while the searches stay exact. Measured on
        // C3 (2 threads, eps=30): waiting for 1/8 of the sites 5.9-6.2 s, 1/4 5.3-5.5 s,
        // 1/2 4.9-5.1 s, all of them 6.8 s (stale trees slow the searches); bench/README.md.
        if (m_pending.size() < std::max<size_t>(kMinSettle, m_counts.sites() / 2))
            return;
        // Each pending site's points leave their tree for the tree of their count now.
        std::vector<std::vector<uint32_t>> arriving;
        std::vector<size_t> leaving(m_trees.size(), 0);
        for (uint32_t site : m_pending) {
            const uint32_t from = m_home[site], to = m_counts.count(site);
            m_pending_flag[site] = 0;
            m_home[site] = to;
            leaving[from] += m_orientations;
            if (arriving.size() <= to)
                arriving.resize(to + 1);
            for (uint32_t t = 0; t < m_orientations; ++t)
                arriving[to].push_back(site * m_orientations + t);
        }
        m_pending.clear();
        while (m_trees.size() < arriving.size())
            m_trees.emplace_back(m_reduced.data(), m_pca.output_dim());
        leaving.resize(m_trees.size(), 0);
        arriving.resize(m_trees.size());
        // Trees change independently (each its removals, then its arrivals): in parallel.
        OIIO::parallel_for(
            int64_t(0), int64_t(m_trees.size()),
            [&](int64_t c) {
                if (leaving[size_t(c)])
                    m_trees[size_t(c)].removed(leaving[size_t(c)], live(uint32_t(c)));
                if (!arriving[size_t(c)].empty())
                    m_trees[size_t(c)].insert(arriving[size_t(c)], live(uint32_t(c)));
            },
            detail::split_every_item(m_nthreads));
    }

    void reset() override
    {
        m_counts.reset();
        std::fill(m_home.begin(), m_home.end(), 0u);
        std::fill(m_pending_flag.begin(), m_pending_flag.end(), char(0));
        m_pending.clear();
        m_trees.clear();
        m_trees.emplace_back(m_reduced.data(), m_pca.output_dim());
        std::vector<uint32_t> all(m_count);
        for (size_t p = 0; p < m_count; ++p)
            all[p] = uint32_t(p);
        m_trees[0].assign(std::move(all));
    }

    const UseCounts& counts() const override { return m_counts; }

private:
    // The points tree c holds: those of the sites whose home is c (all, unpenalized).
    LiveTest live(uint32_t c) const
    {
        if (!m_counts.penalized())
            return LiveTest {};
        return LiveTest { m_home.data(), c, m_orientations };
    }

    PointPenalty point_penalty() const
    {
        if (!m_counts.penalized())
            return PointPenalty {};
        const std::vector<float>& f = m_counts.factors();
        return PointPenalty { m_counts.counts(), f.data(), f.size(), m_counts.min(),
            m_orientations };
    }

    PcaProjection m_pca;
    size_t m_count;
    float m_eps;
    std::vector<float> m_reduced; // count x output_dim
    UseCounts m_counts;
    std::vector<uint32_t> m_home;     // per site: the tree holding its points
    std::vector<char> m_pending_flag; // per site: chosen this round
    std::vector<uint32_t> m_pending;  // sites chosen this round, in order
    std::vector<DynamicKdTree> m_trees;
    int m_nthreads;
    MaskedChoice m_masked;
};

} // namespace

std::unique_ptr<ChoiceIndex> make_kdtree_choice(
    const AnalysisPoints& points, float penalty, int dims, float eps, int nthreads)
{
    return std::make_unique<KdTreeChoice>(points, penalty, dims, eps, nthreads);
}

} // namespace texsyn::detail
