// SPDX-License-Identifier: Apache-2.0
#include "laplacian_taps_pvt.h"

#include <algorithm>

namespace texsyn::detail {

namespace {
constexpr float kernel[5] = { 1.0f, 4.0f, 6.0f, 4.0f, 1.0f };
}

Taps reduce_taps(int n, Boundary b)
{
    Taps t;
    for (int i = 0; i < (n + 1) / 2; ++i) {
        for (int k = 0; k < Taps::ntaps; ++k) {
            t.index.push_back(wrap_coordinate(2 * i + k - 2, n, b));
            t.weight.push_back(kernel[k]);
        }
        t.divisor.push_back(16.0f);
    }
    return t;
}

// The weight that falls on inserted samples is 8/16 everywhere (the usual x2 per axis)
// except where a circular odd size puts two coarse samples side by side across the seam;
// normalising there too keeps constants constant. Reconstruction is exact either way, since
// bands are differences.
Taps expand_taps(int n, Boundary b)
{
    Taps t;
    for (int x = 0; x < n; ++x) {
        float sum = 0.0f;
        for (int k = 0; k < Taps::ntaps; ++k) {
            const int j = wrap_coordinate(x + k - 2, n, b);
            const bool hit = j % 2 == 0;
            t.index.push_back(hit ? j / 2 : 0);
            t.weight.push_back(hit ? kernel[k] : 0.0f);
            sum += hit ? kernel[k] : 0.0f;
        }
        t.divisor.push_back(sum);
    }
    return t;
}

void filter_row(const float* in, const Taps& t, float* out)
{
    for (int x = 0; x < t.size(); ++x) {
        const int* idx = &t.index[size_t(x) * Taps::ntaps];
        const float* wt = &t.weight[size_t(x) * Taps::ntaps];
        float s = 0.0f;
        for (int k = 0; k < Taps::ntaps; ++k)
            s += wt[k] * in[idx[k]];
        out[x] = s / t.divisor[size_t(x)];
    }
}

void filter_rows(const float* in, size_t row_length, const Taps& t, int i, float* out)
{
    const int* idx = &t.index[size_t(i) * Taps::ntaps];
    const float* wt = &t.weight[size_t(i) * Taps::ntaps];
    std::fill(out, out + row_length, 0.0f);
    for (int k = 0; k < Taps::ntaps; ++k) {
        const float* src = in + size_t(idx[k]) * row_length;
        for (size_t x = 0; x < row_length; ++x)
            out[x] += wt[k] * src[x];
    }
    const float d = t.divisor[size_t(i)];
    for (size_t x = 0; x < row_length; ++x)
        out[x] /= d;
}

} // namespace texsyn::detail
