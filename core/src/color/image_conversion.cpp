// SPDX-License-Identifier: Apache-2.0
#include <texsyn/color.h>

namespace texsyn {

bool ColorConfig::convert_image(const OIIO::ImageBuf& src, const std::string& from,
    const std::string& to, bool associate, OIIO::ImageBuf& dst, std::string& error,
    int nthreads) const
{
    PlanarImage planes;
    if (!planes_from_imagebuf(src, planes, error) || !convert(planes, from, to, error, nthreads))
        return false;
    OIIO::ImageBuf result;
    imagebuf_from_planes(planes, result, associate);
    for (const OIIO::ParamValue& p : src.spec().extra_attribs)
        if (p.name() != "oiio:UnassociatedAlpha")
            result.specmod().attribute(p.name(), p.type(), p.data());
    dst = std::move(result);
    return true;
}

} // namespace texsyn
