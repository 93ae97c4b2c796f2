// SPDX-License-Identifier: Apache-2.0
// §3.5–3.7 on face levels: Gaussian convolution over faces (eq. 3–4), downsampling to the
// centre child, upsampling to the white children, and reduce and project (eq. 5–6).
#include "face_filter_pvt.h"

#include <cmath>

#include <OpenImageIO/parallel.h>

namespace texsyn::detail {

namespace {

// A set of face indices for one face's neighbourhood: open addressing, cleared per use.
class FaceSet {
public:
    void clear()
    {
        m_used.clear();
        if (m_slots.empty())
            m_slots.assign(1024, kNoFace);
    }
    // Inserts f; false if it was already there.
    bool insert(uint32_t f)
    {
        if (2 * (m_used.size() + 1) > m_slots.size())
            grow();
        size_t i = hash(f);
        while (m_slots[i] != kNoFace) {
            if (m_slots[i] == f)
                return false;
            i = (i + 1) & (m_slots.size() - 1);
        }
        m_slots[i] = f;
        m_used.push_back(i);
        return true;
    }
    void reset()
    {
        for (size_t i : m_used)
            m_slots[i] = kNoFace;
        m_used.clear();
    }

private:
    size_t hash(uint32_t f) const { return (size_t(f) * 0x9E3779B1u) & (m_slots.size() - 1); }
    void grow()
    {
        std::vector<uint32_t> faces;
        for (size_t i : m_used)
            faces.push_back(m_slots[i]);
        m_slots.assign(m_slots.size() * 2, kNoFace);
        m_used.clear();
        for (uint32_t f : faces)
            insert(f);
    }
    std::vector<uint32_t> m_slots;
    std::vector<size_t> m_used;
};

} // namespace

FaceValues filter_faces(const FaceLevel& level, const FaceValues& values, const FaceKernel& kernel,
    const std::vector<uint8_t>* only, int nthreads)
{
    const size_t nc = values.size(), nf = level.size();
    FaceValues out(nc, std::vector<float>(nf, 0.0f));
    const double reach = 3.0 * kernel.sigma;
    OIIO::parallel_for_chunked(
        0, int64_t(nf), 0,
        [&](int64_t begin, int64_t end) {
            FaceSet seen;
            seen.clear();
            std::vector<uint32_t> frontier;
            std::vector<double> sum(nc);
            for (int64_t i = begin; i < end; ++i) {
                const Imath::V3f& ci = level.centroid[size_t(i)];
                std::fill(sum.begin(), sum.end(), 0.0);
                double weights = 0.0;
                seen.reset();
                frontier.assign(1, uint32_t(i));
                seen.insert(uint32_t(i));
                // Ω(i): i and the faces reached through edges while within 3 sigma.
                while (!frontier.empty()) {
                    const uint32_t j = frontier.back();
                    frontier.pop_back();
                    const double d = double((level.centroid[j] - ci).length()) * kernel.scale;
                    if (d > reach)
                        continue;
                    if (!only || (*only)[j]) {
                        const double r = d / kernel.sigma;
                        const double w = std::exp(-0.5 * r * r) * double(level.area[j]);
                        weights += w;
                        for (size_t c = 0; c < nc; ++c)
                            sum[c] += w * double(values[c][j]);
                    }
                    for (uint32_t g : level.across[j])
                        if (g != kNoFace && seen.insert(g))
                            frontier.push_back(g);
                }
                for (size_t c = 0; c < nc; ++c)
                    out[c][size_t(i)] = weights > 0.0 ? float(sum[c] / weights) : 0.0f;
            }
        },
        OIIO::paropt(nthreads));
    return out;
}

FaceValues reduce_faces(const FaceLevel& coarse, const FaceLevel& fine, const FaceValues& values,
    const FaceKernel& kernel, int nthreads)
{
    const FaceValues blurred = filter_faces(fine, values, kernel, nullptr, nthreads);
    FaceValues out(values.size(), std::vector<float>(coarse.size()));
    for (size_t c = 0; c < values.size(); ++c)
        for (size_t f = 0; f < coarse.size(); ++f)
            out[c][f] = blurred[c][coarse.children[f][0]];
    return out;
}

FaceValues project_faces(const FaceLevel& coarse, const FaceLevel& fine, const FaceValues& values,
    const FaceKernel& kernel, int nthreads)
{
    // Upsampling: the white children take their parent's value, the black ones none; the
    // convolution then averages over the white faces only (Γ_i of eq. 5).
    FaceValues up(values.size(), std::vector<float>(fine.size(), 0.0f));
    for (size_t f = 0; f < coarse.size(); ++f)
        for (uint32_t child : coarse.children[f])
            if (fine.colour[child])
                for (size_t c = 0; c < values.size(); ++c)
                    up[c][child] = values[c][f];
    return filter_faces(fine, up, kernel, &fine.colour, nthreads);
}

} // namespace texsyn::detail
