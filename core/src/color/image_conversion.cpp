// SPDX-License-Identifier: Apache-2.0
// ColorConfig's conversions of pixels: planar images, and ImageBufs (packed float pixels
// converted in place in one copy, anything else through planes).
#include <texsyn/color.h>

#include <cstdint>
#include <functional>
#include <mutex>

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/parallel.h>

#include "color_config_pvt.h"
#include "image/parallel_pvt.h"
#include "image/planar_pvt.h"

namespace OCIO = OCIO_NAMESPACE;

namespace texsyn {

namespace {

// The processor from `src` to `dst`: lossless, with no fast approximations of pow/log, so
// statistics see exact values.
OCIO::ConstCPUProcessorRcPtr lossless_processor(
    const OCIO::ConstConfigRcPtr& config, const std::string& src, const std::string& dst)
{
    return config->getProcessor(src.c_str(), dst.c_str())
        ->getOptimizedCPUProcessor(
            OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_LOSSLESS);
}

std::string conversion_error(
    const std::string& src, const std::string& dst, const std::string& what)
{
    return "colour conversion '" + src + "' -> '" + dst + "': " + what;
}

// Runs fn(y0, y1) over blocks of ~16k pixels in parallel and returns the first error
// message ("" if none): exceptions must not escape a pool thread.
std::string for_row_blocks(
    int width, int height, int nthreads, const std::function<void(int64_t, int64_t)>& fn)
{
    std::mutex mutex;
    std::string error;
    OIIO::parallel_for_chunked(
        0, height, std::max<int64_t>(1, (int64_t(1) << 14) / std::max(1, width)),
        [&](int64_t y0, int64_t y1) {
            try {
                fn(y0, y1);
            } catch (const std::exception& e) {
                std::lock_guard<std::mutex> lock(mutex);
                if (error.empty())
                    error = e.what();
            }
        },
        detail::split_every_item(nthreads));
    return error;
}

std::string convert_rgb(
    const OCIO::ConstCPUProcessorRcPtr& cpu, Plane& r, Plane& g, Plane& b, int nthreads)
{
    const int w = r.width();
    return for_row_blocks(w, r.height(), nthreads, [&](int64_t y0, int64_t y1) {
        OCIO::PlanarImageDesc desc(
            r.row(int(y0)), g.row(int(y0)), b.row(int(y0)), nullptr, w, long(y1 - y0));
        cpu->apply(desc);
    });
}

// Grey is converted as the colour (g, g, g); the result's mean is the new grey.
std::string convert_grey(const OCIO::ConstCPUProcessorRcPtr& cpu, Plane& grey, int nthreads)
{
    const int w = grey.width();
    return for_row_blocks(w, grey.height(), nthreads, [&](int64_t y0, int64_t y1) {
        const size_t npix = size_t(w) * size_t(y1 - y0);
        float* g = grey.row(int(y0));
        std::vector<float> rgb(3 * npix);
        for (size_t i = 0; i < npix; ++i)
            rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = g[i];
        OCIO::PackedImageDesc desc(rgb.data(), long(npix), 1, 3);
        cpu->apply(desc);
        for (size_t i = 0; i < npix; ++i)
            g[i] = (rgb[3 * i] + rgb[3 * i + 1] + rgb[3 * i + 2]) * (1.0f / 3.0f);
    });
}

// The first three channels of `image`'s pixels (packed float, any channel count from 3)
// converted in place.
std::string convert_packed_rgb(
    const OCIO::ConstCPUProcessorRcPtr& cpu, OIIO::ImageBuf& image, int nthreads)
{
    const OIIO::ImageSpec& spec = image.spec();
    auto* pixels = static_cast<float*>(image.localpixels());
    const ptrdiff_t pixel = ptrdiff_t(spec.nchannels) * ptrdiff_t(sizeof(float));
    return for_row_blocks(spec.width, spec.height, nthreads, [&](int64_t y0, int64_t y1) {
        OCIO::PackedImageDesc desc(
            pixels + size_t(y0) * size_t(spec.width) * size_t(spec.nchannels), spec.width,
            long(y1 - y0), OCIO::CHANNEL_ORDERING_RGB, OCIO::BIT_DEPTH_F32,
            ptrdiff_t(sizeof(float)), pixel, pixel * spec.width);
        cpu->apply(desc);
    });
}

} // namespace

bool ColorConfig::convert(PlanarImage& image, const std::string& from, const std::string& to,
    std::string& error, int nthreads) const
{
    for (const std::string* name : { &from, &to }) {
        if (resolve(*name).empty()) {
            error = unknown_colorspace(*name);
            return false;
        }
    }
    const std::string src = resolve(from), dst = resolve(to);
    if (src == dst || is_data(src) || is_data(dst))
        return true;
    const int ncolor = image.ncolor();
    if (ncolor < 1 || image.width() < 1 || image.height() < 1)
        return true;
    // Converted copies are swapped in only on success: the image is untouched on failure.
    const int nconv = ncolor >= 3 ? 3 : 1;
    std::vector<Plane> planes(image.channels.begin(), image.channels.begin() + nconv);
    std::string ocio_error;
    try {
        const OCIO::ConstCPUProcessorRcPtr cpu = lossless_processor(m_impl->config, src, dst);
        ocio_error = nconv == 3 ? convert_rgb(cpu, planes[0], planes[1], planes[2], nthreads)
                                : convert_grey(cpu, planes[0], nthreads);
    } catch (const std::exception& e) {
        ocio_error = e.what();
    }
    if (!ocio_error.empty()) {
        error = conversion_error(src, dst, ocio_error);
        return false;
    }
    for (int c = 0; c < nconv; ++c)
        image.channels[size_t(c)] = std::move(planes[size_t(c)]);
    return true;
}

bool ColorConfig::convert_image(const OIIO::ImageBuf& src, const std::string& from,
    const std::string& to, bool associate, OIIO::ImageBuf& dst, std::string& error,
    int nthreads) const
{
    const std::string src_space = resolve(from), dst_space = resolve(to);
    const bool known = !src_space.empty() && !dst_space.empty();
    const bool identity
        = known && (src_space == dst_space || is_data(src_space) || is_data(dst_space));
    // Finite packed float pixels without alpha are copied once, and where the spaces differ
    // and there are three channels or more, converted as RGB in place; anything else goes
    // through planes, which handle alpha, grey and non-finite values (refused).
    OIIO::ImageBuf result;
    const bool packed = (identity || (known && src.spec().nchannels >= 3))
        && src.spec().alpha_channel < 0 && copy_without_planes(src, result);
    if (packed && !identity) {
        std::string ocio_error;
        try {
            ocio_error = convert_packed_rgb(
                lossless_processor(m_impl->config, src_space, dst_space), result, nthreads);
        } catch (const std::exception& e) {
            ocio_error = e.what();
        }
        if (!ocio_error.empty()) {
            error = conversion_error(src_space, dst_space, ocio_error);
            return false;
        }
    } else if (!packed) {
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
