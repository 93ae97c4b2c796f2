// SPDX-License-Identifier: Apache-2.0
// §3.5–3.7 on face levels: Gaussian convolution over faces (eq. 3–4), downsampling to the
// centre child, upsampling to the white children, and reduce and project (eq. 5–6).
#include "face_filter_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::detail {

namespace {

// Tasks per convolution: few, because each task marks the faces it reaches in an array as
// long as the level (a hash set per face's neighbourhood cost 1.6x the time on the cow).
constexpr int64_t kFilterChunks = 16;

// What the traversal reads of a face, in one place (one cache line for two faces instead of
// five arrays): its centroid, area and neighbours, and whether it takes part (eq. 6's Γ).
struct FaceSite {
    Imath::V3f centroid;
    float area;
    std::array<uint32_t, 3> across;
    uint32_t counts;
};

} // namespace

FaceValues filter_faces(const FaceLevel& level, const FaceValues& values, const FaceKernel& kernel,
    const std::vector<uint8_t>* only, int nthreads)
{
    const size_t nc = values.size(), nf = level.size();
    FaceValues out(nc, std::vector<float>(nf, 0.0f));
    std::vector<FaceSite> sites(nf);
    std::vector<float> interleaved(nf * nc);
    for (size_t f = 0; f < nf; ++f) {
        sites[f]
            = { level.centroid[f], level.area[f], level.across[f], uint32_t(!only || (*only)[f]) };
        for (size_t c = 0; c < nc; ++c)
            interleaved[f * nc + c] = values[c][f];
    }
    const double reach = 3.0 * kernel.sigma;
    const int64_t chunk = std::max<int64_t>(1, (int64_t(nf) + kFilterChunks - 1) / kFilterChunks);
    OIIO::parallel_for_chunked(
        0, int64_t(nf), chunk,
        [&](int64_t begin, int64_t end) {
            // seen[j] == i: face j was reached in the traversal from face i.
            std::vector<uint32_t> seen(nf, kNoFace), frontier;
            std::vector<double> sum(nc);
            for (int64_t i = begin; i < end; ++i) {
                const Imath::V3f ci = sites[size_t(i)].centroid;
                std::fill(sum.begin(), sum.end(), 0.0);
                double weights = 0.0;
                frontier.assign(1, uint32_t(i));
                seen[size_t(i)] = uint32_t(i);
                // Ω(i): i and the faces reached through edges while within 3 sigma.
                while (!frontier.empty()) {
                    const uint32_t j = frontier.back();
                    frontier.pop_back();
                    const FaceSite& s = sites[j];
                    const double d = double((s.centroid - ci).length()) * kernel.scale;
                    if (d > reach)
                        continue;
                    if (s.counts) {
                        const double r = d / kernel.sigma;
                        const double w = std::exp(-0.5 * r * r) * double(s.area);
                        weights += w;
                        const float* v = interleaved.data() + size_t(j) * nc;
                        for (size_t c = 0; c < nc; ++c)
                            sum[c] += w * double(v[c]);
                    }
                    for (uint32_t g : s.across)
                        if (g != kNoFace && seen[g] != uint32_t(i)) {
                            seen[g] = uint32_t(i);
                            frontier.push_back(g);
                        }
                }
                for (size_t c = 0; c < nc; ++c)
                    out[c][size_t(i)] = weights > 0.0 ? float(sum[c] / weights) : 0.0f;
            }
        },
        detail::split_every_item(nthreads));
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
