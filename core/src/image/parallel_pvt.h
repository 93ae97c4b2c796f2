// SPDX-License-Identifier: Apache-2.0
// The options texsyn's parallel loops run with.
#pragma once

#include <OpenImageIO/parallel.h>

namespace texsyn::detail {

/// OIIO loop options that let every item of a loop (a row, a block of rows, a point) go to
/// another thread, on up to `nthreads` threads (0 = every core). OIIO's own default runs a
/// range of fewer than 16384 items, such as the rows of a 1024 x 1024 image, on the calling
/// thread alone (and parallel_for_chunked with a chunk size of 0 likewise), which is right
/// for cheap items and wrong for every loop in texsyn.
inline OIIO::paropt split_every_item(int nthreads)
{
    return OIIO::paropt(nthreads, OIIO::paropt::SplitDir::Y, 1);
}

} // namespace texsyn::detail
