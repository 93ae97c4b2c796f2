// SPDX-License-Identifier: Apache-2.0
// Synthesizes a 64x48 texture from noise through the installed library, and checks that the
// version macros match the library loaded; exit 0 on success.
#include <cstdio>
#include <string>

#include <OpenImageIO/imagebufalgo.h>

#include <texsyn/synthesis.h>

int main()
{
    OIIO::ImageBuf sample(OIIO::ImageSpec(32, 32, 3, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::noise(sample, "gaussian", 0.5f, 0.1f, false, 1);
    texsyn::PyramidOptions opt;
    opt.width = 64;
    opt.height = 48;
    opt.iterations = 1;
    OIIO::ImageBuf out = texsyn::pyramid_synthesize(sample, opt);
    if (out.has_error() || out.spec().width != 64 || out.spec().height != 48) {
        std::fprintf(stderr, "downstream: %s\n", out.geterror().c_str());
        return 1;
    }
    // The headers built against and the library loaded agree.
    if (texsyn::version_number() != TEXSYN_VERSION
        || std::string(texsyn::version()) != TEXSYN_VERSION_STRING
        || texsyn::gpl_components().empty() == bool(TEXSYN_GPL_BUILD)) {
        std::fprintf(stderr, "downstream: headers %s, library %s\n", TEXSYN_VERSION_STRING,
            texsyn::version());
        return 1;
    }
    std::printf("downstream: texsyn %s synthesized %dx%d\n", texsyn::version(), out.spec().width,
        out.spec().height);
    return 0;
}
