// SPDX-License-Identifier: Apache-2.0
// The 1-D resampling steps of the Burt & Adelson Laplacian pyramid, shared by the 2-D
// (laplacian.cpp) and 3-D (laplacian3d.cpp) pyramids: both are separable, so each axis is
// one of these passes.
#pragma once

#include <cstddef>
#include <vector>

#include <texsyn/image.h>

namespace texsyn::detail {

/// A 1-D resampling along one axis: out[i] = sum_t weight[i][t] * in[index[i][t]] /
/// divisor[i], five taps per output. Integer weights and one division keep constants exact.
struct Taps {
    static constexpr int ntaps = 5;
    std::vector<int> index;
    std::vector<float> weight;
    std::vector<float> divisor;
    int size() const { return int(divisor.size()); }
};

/// Blur with (1,4,6,4,1)/16 then keep the even samples of an n-sample axis: ceil(n/2)
/// outputs.
Taps reduce_taps(int n, Boundary b);

/// Insert zeros up to n samples, blur, and normalise by the kernel weight that fell on the
/// inserted samples (the inverse size change of reduce_taps(n, b)).
Taps expand_taps(int n, Boundary b);

/// Resamples one contiguous row: out[i] for i < t.size(), from `in`.
void filter_row(const float* in, const Taps& t, float* out);

/// Output row `i` of a resampling across rows: out = sum_k weight[i][k] * (row index[i][k]
/// of `in`) / divisor[i], where rows are `row_length` contiguous floats each.
void filter_rows(const float* in, size_t row_length, const Taps& t, int i, float* out);

} // namespace texsyn::detail

namespace texsyn::detail {

/// Burt & Adelson's build over `nlevels` levels of a plane or volume: bands[s] = G_s -
/// expand(G_{s+1}) for s < nlevels, bands[nlevels] = G_nlevels (the low-pass).
/// reduce(s, G_s, G_{s+1}) and expand(s, G_{s+1}, up) resample between levels s and s+1.
template <class Grid, class Reduce, class Expand>
void laplacian_build(
    const Grid& image, size_t nlevels, std::vector<Grid>& bands, Reduce&& reduce, Expand&& expand)
{
    bands.resize(nlevels + 1);
    Grid g = image, next, up;
    for (size_t s = 0; s < nlevels; ++s) {
        reduce(s, g, next);
        expand(s, next, up);
        float* gd = g.data();
        const float* ud = up.data();
        for (size_t i = 0; i < g.size(); ++i)
            gd[i] -= ud[i];
        bands[s] = std::move(g);
        g = std::move(next);
        next = Grid();
    }
    bands.back() = std::move(g);
}

/// The inverse of laplacian_build: image = expand(… expand(bands[nlevels]) + …) + bands[0].
template <class Grid, class Expand>
void laplacian_collapse(
    const std::vector<Grid>& bands, size_t nlevels, Grid& image, Expand&& expand)
{
    Grid g = bands.back(), up;
    for (size_t s = nlevels; s-- > 0;) {
        expand(s, g, up);
        const Grid& band = bands[s];
        float* ud = up.data();
        const float* bd = band.data();
        for (size_t i = 0; i < up.size(); ++i)
            ud[i] += bd[i];
        std::swap(g, up);
    }
    image = std::move(g);
}

} // namespace texsyn::detail
