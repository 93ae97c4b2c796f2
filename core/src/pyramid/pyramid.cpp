// SPDX-License-Identifier: Apache-2.0
#include <texsyn/pyramid.h>

#include <algorithm>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn {

void Pyramid::transform_bands(Plane& image, std::vector<Plane>& bands, const BandFunction& modify,
    int nthreads, const StopFlag* stop) const
{
    build(image, bands, nthreads);
    // One task per band: bands differ in size, so equal static chunks would not balance.
    OIIO::parallel_for_chunked(
        int64_t(0), int64_t(bands.size()), int64_t(1),
        [&](int64_t b, int64_t) {
            if (!stop_requested(stop))
                modify(int(b), bands[size_t(b)]);
        },
        detail::split_every_item(nthreads));
    if (!stop_requested(stop))
        collapse(bands, image, nthreads);
}

const char* pyramid_kind_name(PyramidKind kind)
{
    return kind == PyramidKind::Laplacian ? "laplacian" : "steerable";
}

int max_pyramid_scales(int sample_width, int sample_height)
{
    // floor(log2(min / 8)), clamped at 0: the largest s with min >= 8 * 2^s.
    const int64_t m = std::min(sample_width, sample_height);
    int s = 0;
    while (s < 30 && m >= (int64_t(8) << (s + 1)))
        ++s;
    return s;
}

} // namespace texsyn
