// SPDX-License-Identifier: Apache-2.0
// Random vector sets for the search tests.
#pragma once

#include <cstdint>
#include <vector>

#include <texsyn/random.h>

namespace texsyn::test {

/// count x dim floats, uniform in [0, 1), a pure function of (seed, index).
inline std::vector<float> random_vectors(size_t count, int dim, uint64_t seed)
{
    std::vector<float> v(count * size_t(dim));
    for (size_t i = 0; i < v.size(); ++i)
        v[i] = random_uniform(seed, 0, i);
    return v;
}

} // namespace texsyn::test
