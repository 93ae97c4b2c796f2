// SPDX-License-Identifier: Apache-2.0
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/subbands.h>

#include <filesystem>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

using namespace texsyn;

TEST(Subbands, WritesOneNamedPartPerBandWithASharedDisplayWindow)
{
    OIIO::ImageBuf sample(OIIO::ImageSpec(64, 64, 3, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::noise(sample, "uniform", 0.0f, 1.0f, false, 3);
    PyramidOptions opt;
    opt.width = 96;
    opt.height = 80;
    opt.iterations = 1;
    std::vector<NamedImage> bands;
    OIIO::ImageBuf synth = pyramid_synthesize(sample, opt, &bands);
    ASSERT_FALSE(synth.has_error()) << synth.geterror();
    // 64x64 allows 3 scales: highpass + 3x4 oriented + lowpass = 14 bands per pyramid.
    ASSERT_EQ(bands.size(), 28u);
    EXPECT_EQ(bands[0].name, "sample.highpass");
    EXPECT_EQ(bands[1].name, "sample.s0.o0");
    EXPECT_EQ(bands[14].name, "synth.highpass");
    EXPECT_EQ(bands[27].name, "synth.lowpass");
    EXPECT_EQ(bands[1].image.channel_names, (std::vector<std::string> { "pc0", "pc1", "pc2" }));

    std::string file = (std::filesystem::temp_directory_path() / "texsyn_subbands.exr").string();
    std::string error;
    ASSERT_TRUE(write_subband_exr(file, synth, bands, error)) << error;
    auto in = OIIO::ImageInput::open(file);
    ASSERT_TRUE(in);
    int parts = 0;
    for (int s = 0; in->seek_subimage(s, 0); ++s) {
        const OIIO::ImageSpec& spec = in->spec();
        std::string name = spec.get_string_attribute("oiio:subimagename");
        EXPECT_EQ(name, s == 0 ? std::string("synth") : bands[s - 1].name);
        EXPECT_EQ(spec.full_width, 96);
        EXPECT_EQ(spec.full_height, 80);
        EXPECT_EQ(spec.get_string_attribute("synth:method"), "pyramid");
        if (s == 7) { // sample.s1.o1: 32x32, values exactly as computed
            EXPECT_EQ(spec.width, 32);
            OIIO::ImageBuf part(file, s, 0);
            ASSERT_TRUE(part.read(s, 0, true, OIIO::TypeFloat));
            EXPECT_EQ(part.getchannel(5, 9, 0, 1), bands[6].image.channels[1](5, 9));
        }
        ++parts;
    }
    EXPECT_EQ(parts, 29);
    in->close();
    std::filesystem::remove(file);
}
