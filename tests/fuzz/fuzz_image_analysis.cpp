// SPDX-License-Identifier: Apache-2.0
// Images through the analysis path: the first bytes choose a size (1..48 a side), a channel
// count (1..5) and a pixel type, the rest are the pixels (NaN and Inf included). The
// pyramid analysis (what --analyze, --pyramid and every recipe of it run on a sample) must
// refuse with one line or succeed.
#include "fuzz_target.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/pyramid_synthesis.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    if (size < 4)
        return 0;
    const int width = 1 + data[0] % 48, height = 1 + data[1] % 48, nchannels = 1 + data[2] % 5;
    const OIIO::TypeDesc types[]
        = { OIIO::TypeUInt8, OIIO::TypeUInt16, OIIO::TypeHalf, OIIO::TypeFloat };
    const OIIO::TypeDesc type = types[data[3] % 4];
    OIIO::ImageSpec spec(width, height, nchannels, type);
    if (nchannels == 4)
        spec.alpha_channel = 3;
    std::vector<unsigned char> pixels(spec.image_bytes(), 0);
    std::memcpy(pixels.data(), data + 4, std::min(pixels.size(), size - 4));
    OIIO::ImageBuf image(spec);
    image.set_pixels(image.roi(), type, pixels.data());

    OIIO::ImageBuf floats;
    floats.copy(image, OIIO::TypeFloat);
    texsyn::PyramidOptions opt;
    opt.nthreads = 1;
    texsyn::TextureStatistics stats;
    std::string error;
    if (!texsyn::analyze_texture(floats, opt, stats, error))
        texsyn::fuzz::expect_one_line(error, "analysis");
    return 0;
}
