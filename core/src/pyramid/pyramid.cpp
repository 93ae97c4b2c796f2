// SPDX-License-Identifier: Apache-2.0
#include <texsyn/pyramid.h>

#include <algorithm>

namespace texsyn {

const char* pyramid_kind_name(PyramidKind kind)
{
    return kind == PyramidKind::Laplacian ? "laplacian" : "steerable";
}

int max_pyramid_scales(int sample_width, int sample_height)
{
    // floor(log2(min / 8)), clamped at 0: the largest s with min >= 8 * 2^s.
    const int64_t m = std::min(sample_width, sample_height);
    int s           = 0;
    while (s < 30 && m >= (int64_t(8) << (s + 1)))
        ++s;
    return s;
}

}  // namespace texsyn
