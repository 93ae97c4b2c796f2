// SPDX-License-Identifier: Apache-2.0
#include "homogeneity_pvt.h"

#include <algorithm>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn::homogeneity {

int for_each_row_block(int height, int nthreads, const std::function<void(int, int, int)>& fn)
{
    const int nblocks = (std::max(height, 0) + rows_per_block - 1) / rows_per_block;
    OIIO::parallel_for_chunked(
        int64_t(0), int64_t(nblocks), int64_t(1),
        [&](int64_t begin, int64_t end) {
            for (int64_t b = begin; b < end; ++b) {
                const int y0 = int(b) * rows_per_block;
                fn(int(b), y0, std::min(height, y0 + rows_per_block));
            }
        },
        detail::split_every_item(nthreads));
    return nblocks;
}

} // namespace texsyn::homogeneity
