// SPDX-License-Identifier: Apache-2.0
#include <texsyn/color.h>

#include "image/planar_pvt.h"

namespace texsyn {

bool ColorConfig::convert_image(const OIIO::ImageBuf& src, const std::string& from,
    const std::string& to, bool associate, OIIO::ImageBuf& dst, std::string& error,
    int nthreads) const
{
    // Same space (or data): copied as it is where that gives the round trip's pixels.
    const std::string src_space = resolve(from), dst_space = resolve(to);
    const bool identity = !src_space.empty() && !dst_space.empty()
        && (src_space == dst_space || is_data(src_space) || is_data(dst_space));
    OIIO::ImageBuf result;
    if (!identity || !copy_without_planes(src, result)) {
        PlanarImage planes;
        if (!planes_from_imagebuf(src, planes, error)
            || !convert(planes, from, to, error, nthreads))
            return false;
        imagebuf_from_planes(planes, result, associate);
    }
    for (const OIIO::ParamValue& p : src.spec().extra_attribs)
        if (p.name() != "oiio:UnassociatedAlpha")
            result.specmod().attribute(p.name(), p.type(), p.data());
    dst = std::move(result);
    return true;
}

} // namespace texsyn
