// SPDX-License-Identifier: Apache-2.0
// Periodic (wrap-around) indexing, the boundary rule of every tiling synthesis.
#pragma once

namespace texsyn::detail {

/// i mod n in [0, n) for any i (n >= 1); no division in the common case of i inside.
inline int wrap(int i, int n)
{
    if (i >= 0 && i < n)
        return i;
    const int r = i % n;
    return r < 0 ? r + n : r;
}

} // namespace texsyn::detail
