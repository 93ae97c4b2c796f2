// SPDX-License-Identifier: Apache-2.0
// The sample's levels, made once per synthesis and shared by its runs (patch_pvt.h).
#include "patch_pvt.h"

#include <algorithm>

#include <texsyn/pyramid.h>

namespace texsyn::detail {

SampleLevels::SampleLevels(const std::vector<Plane>& planes, int levels, bool isotropic, int patch,
    int coherence, int nthreads)
    : m_variants(variant_count(planes.at(0).width(), planes.at(0).height(), isotropic))
    , m_patch(patch)
    , m_coherence(coherence)
    , m_nthreads(nthreads)
    , m_entries(size_t(std::max(levels, 1)))
{
    for (int t = 0; t < m_variants; ++t) {
        std::vector<Plane> turned;
        for (const Plane& p : planes)
            turned.push_back(t == 0 ? p : variant_plane(p, t));
        m_pyramids.push_back(gaussian_pyramid(turned, levels, Boundary::Reflect, nthreads));
    }
}

const SampleLevel& SampleLevels::level(int l)
{
    Entry& e = m_entries.at(size_t(l));
    if (!e.made) {
        const std::vector<Plane>& first = m_pyramids[0][size_t(l)];
        const int cw = first[0].width(), ch = first[0].height();
        std::vector<Plane> atlas(first.size(), Plane(cw * m_variants, ch));
        for (int t = 0; t < m_variants; ++t)
            for (size_t c = 0; c < atlas.size(); ++c)
                for (int y = 0; y < ch; ++y)
                    std::copy_n(m_pyramids[size_t(t)][size_t(l)][c].row(y), cw,
                        atlas[c].row(y) + size_t(t) * size_t(cw));
        e.level = sample_level(atlas, cw, m_nthreads);
        e.made = true;
    }
    return e.level;
}

const std::vector<uint32_t>& SampleLevels::similar(int l, const StopFlag* stop)
{
    const SampleLevel& sample = level(l);
    Entry& e = m_entries[size_t(l)];
    if (!e.similar_made) {
        e.similar = similar_patches(
            sample.pixels, sample.cell_width, m_patch, m_coherence, m_nthreads, stop);
        e.similar_made = !stop_requested(stop);
    }
    return e.similar;
}

} // namespace texsyn::detail
