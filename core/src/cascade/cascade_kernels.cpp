// SPDX-License-Identifier: Apache-2.0
// The cascade's convolution kernels (cascade_pvt.h).
#include "cascade_pvt.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace texsyn::detail {

namespace {

// exp(-1/2 (u/su)^2 - 1/2 (v/sv)^2) with (u, v) the offset rotated by -angle (degrees).
std::vector<double> gaussian(int size, double su, double sv, double angle)
{
    const double a = angle * 3.14159265358979 / 180.0, c = std::cos(a), s = std::sin(a);
    const int h = size / 2;
    std::vector<double> w;
    for (int j = -h; j <= h; ++j)
        for (int i = -h; i <= h; ++i) {
            const double u = c * i + s * j, v = -s * i + c * j;
            w.push_back(std::exp(-0.5 * (u * u / (su * su) + v * v / (sv * sv))));
        }
    return w;
}

CascadeKernelWeights normalised(int size, const std::vector<double>& w)
{
    const double sum = std::accumulate(w.begin(), w.end(), 0.0);
    CascadeKernelWeights k;
    k.size = size;
    for (double v : w)
        k.weights.push_back(float(sum != 0.0 ? v / sum : v));
    return k;
}

// The kernel's side: 3, 5 or 7 from the preset's name.
int preset_size(CascadeKernel k)
{
    switch (k) {
    case CascadeKernel::Box3:
    case CascadeKernel::Gauss3:
        return 3;
    case CascadeKernel::Box5:
    case CascadeKernel::Gauss5:
    case CascadeKernel::Dog5:
    case CascadeKernel::Aniso5:
        return 5;
    default:
        return 7;
    }
}

} // namespace

CascadeKernelWeights cascade_kernel(const CascadeOptions& opt, int level)
{
    const CascadeKernel kernel = at_level(opt.kernel, level, CascadeKernel::Gauss5);
    if (kernel == CascadeKernel::Custom)
        return normalised(opt.ksize, std::vector<double>(opt.weights.begin(), opt.weights.end()));
    const int n = preset_size(kernel);
    const double size = n;
    switch (kernel) {
    case CascadeKernel::Box3:
    case CascadeKernel::Box5:
    case CascadeKernel::Box7:
        return normalised(n, std::vector<double>(size_t(n * n), 1.0));
    case CascadeKernel::Dog5:
    case CascadeKernel::Dog7: {
        std::vector<double> narrow = gaussian(n, size / 6, size / 6, 0),
                            wide = gaussian(n, size / 3, size / 3, 0);
        const double sn = std::accumulate(narrow.begin(), narrow.end(), 0.0),
                     sw = std::accumulate(wide.begin(), wide.end(), 0.0);
        std::vector<double> w(narrow.size());
        for (size_t i = 0; i < w.size(); ++i)
            w[i] = 2.0 * narrow[i] / sn - wide[i] / sw;
        return normalised(n, w);
    }
    case CascadeKernel::Aniso5:
    case CascadeKernel::Aniso7:
        return normalised(n, gaussian(n, size / 3, size / 10, at_level(opt.angle, level, 0.0f)));
    default:
        return normalised(n, gaussian(n, size / 4, size / 4, 0));
    }
}

} // namespace texsyn::detail
