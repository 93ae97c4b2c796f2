// SPDX-License-Identifier: Apache-2.0
// One pass of choosy sampling (choosy_pvt.h choosy_pass; Algorithm 2) in deterministic
// parallel rounds.
#include "choosy_pvt.h"

#include <algorithm>
#include <numeric>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include <texsyn/random.h>

#include "methods/method_helpers_pvt.h"

namespace texsyn::detail {

namespace {

constexpr size_t kMaxRound = 256;
constexpr uint32_t kNever = ~0u;

// A seeded uniformly random permutation of [0, n) (Fisher–Yates).
std::vector<size_t> visiting_order(size_t n, uint64_t seed, uint64_t stream)
{
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t(0));
    for (size_t i = n; i > 1; --i) {
        const uint64_t r = random_bits(seed, stream, i) >> 32;
        std::swap(order[i - 1], order[size_t((r * uint64_t(i)) >> 32)]);
    }
    return order;
}

// The choice for `site` as the target stands: index.choose(), or choose_masked() where the
// site's neighbourhood has wildcards. `q` and `mask` hold dim floats, `hints` max_neighbors().
uint32_t choose_for(const ChoosyTarget& target, const ChoiceIndex& index, size_t site, float* q,
    float* mask, uint32_t* hints)
{
    target.query(site, q);
    const size_t nhints = target.hints(site, hints);
    if (target.wildcards(site, mask))
        return index.choose_masked(q, mask, hints, nhints);
    return index.choose(q, hints, nhints);
}

} // namespace

size_t choosy_round_size(size_t sites)
{
    return std::clamp<size_t>(sites / 512, 1, kMaxRound);
}

void choosy_pass(ChoosyTarget& target, ChoiceIndex& index, const PassSettings& settings)
{
    index.reset();
    const size_t n = target.sites();
    const size_t dim = size_t(target.dim());
    const size_t round = choosy_round_size(n);
    const std::vector<size_t> order = visiting_order(n, settings.seed, settings.stream);
    std::vector<float> queries(round * dim), masks(round * dim);
    std::vector<uint32_t> choices(round);
    std::vector<uint32_t> hints(round * target.max_neighbors());
    // The round in which each output site was last written and each sample site chosen.
    std::vector<uint32_t> site_round(n, kNever);
    std::vector<uint32_t> sample_round(index.counts().sites(), kNever);
    std::vector<size_t> neighbors(target.max_neighbors());

    uint32_t r = 0;
    for (size_t start = 0; start < n; start += round, ++r) {
        const size_t m = std::min(round, n - start);
        OIIO::parallel_for(
            int64_t(0), int64_t(m),
            [&](int64_t i) {
                const size_t site = order[start + size_t(i)];
                choices[size_t(i)] = choose_for(target, index, site,
                    queries.data() + size_t(i) * dim, masks.data() + size_t(i) * dim,
                    hints.data() + size_t(i) * target.max_neighbors());
            },
            detail::split_every_item(settings.nthreads));
        for (size_t i = 0; i < m; ++i) {
            const size_t site = order[start + i];
            // An earlier visit of this round changed a neighbour, or used the same sample
            // site (raising its penalty): search again with the state as it is now.
            bool stale = sample_round[index.site_of(choices[i])] == r;
            const size_t k = stale ? 0 : target.neighbors(site, neighbors.data());
            for (size_t j = 0; j < k && !stale; ++j)
                stale = site_round[neighbors[j]] == r;
            if (stale)
                choices[i] = choose_for(target, index, site, queries.data() + i * dim,
                    masks.data() + i * dim, hints.data() + i * target.max_neighbors());
            target.apply(site, choices[i]);
            index.record(choices[i]);
            site_round[site] = r;
            sample_round[index.site_of(choices[i])] = r;
        }
        index.settle();
        if (settings.visited)
            settings.visited(m);
    }
}

void choosy_passes(ChoosyTarget& target, ChoiceIndex& index, const ChoosyOptions& opt,
    int iterations, uint64_t stream, PassProgress& progress)
{
    for (int it = 0; it < iterations; ++it) {
        PassSettings pass;
        pass.seed = opt.seed;
        pass.stream = stream + uint64_t(it);
        pass.nthreads = opt.nthreads;
        pass.visited = [&](size_t n) {
            progress.done += n;
            detail::report_progress(
                opt.progress, opt.stop, float(double(progress.done) / double(progress.total)));
        };
        choosy_pass(target, index, pass);
    }
}

} // namespace texsyn::detail
