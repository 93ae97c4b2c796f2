// SPDX-License-Identifier: Apache-2.0
// Samples for unit tests, as the tool sees them.
#pragma once

#include <cmath>
#include <string>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include <texsyn/color.h>
#include <texsyn/image.h>
#include <texsyn/io.h>

namespace texsyn::test {

/// A bundled sample (data/samples/<name>) read and converted from sRGB to scene-linear float.
inline OIIO::ImageBuf linear_sample(const std::string& name)
{
    OIIO::ImageBuf file;
    std::string error;
    EXPECT_TRUE(read_image(std::string(TEXSYN_TEST_DATA) + "/" + name, file, error)) << error;
    PlanarImage planes;
    EXPECT_TRUE(planes_from_imagebuf(file, planes, error)) << error;
    auto cc = ColorConfig::load(TEXSYN_BUNDLED_OCIO_CONFIG, error);
    EXPECT_TRUE(cc) << error;
    EXPECT_TRUE(cc->convert(planes, "sRGB - Texture", cc->scene_linear(), error)) << error;
    OIIO::ImageBuf buf;
    imagebuf_from_planes(planes, buf);
    return buf;
}

/// The top-left w x h of linear_sample(name).
inline OIIO::ImageBuf linear_crop(const std::string& name, int w, int h)
{
    return OIIO::ImageBufAlgo::cut(linear_sample(name), OIIO::ROI(0, w, 0, h));
}

/// The planes of an image (test fails on error).
inline PlanarImage planes_of(const OIIO::ImageBuf& buf)
{
    PlanarImage p;
    std::string error;
    EXPECT_TRUE(planes_from_imagebuf(buf, p, error)) << error;
    return p;
}

/// stucco_yellow.png (scene-linear) with a smooth alpha channel "A" (returned in `alpha`).
inline OIIO::ImageBuf stucco_with_alpha(Plane& alpha)
{
    PlanarImage s = planes_of(linear_sample("stucco_yellow.png"));
    alpha = Plane(s.width(), s.height());
    for (int y = 0; y < alpha.height(); ++y)
        for (int x = 0; x < alpha.width(); ++x)
            alpha(x, y) = 0.5f + 0.5f * std::sin(0.3f * x) * std::cos(0.2f * y);
    s.channels.push_back(alpha);
    s.channel_names.push_back("A");
    s.alpha_channel = 3;
    OIIO::ImageBuf sample;
    imagebuf_from_planes(s, sample);
    return sample;
}

} // namespace texsyn::test
