// SPDX-License-Identifier: Apache-2.0
// --fill end to end: a float EXR plate keeps its unmasked pixels bit for bit through the
// tool, the same seed gives the same file at any thread count, and bad masks are refused
// with one line, exit 1 and no output.
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "cli_fixture.h"

class FillCli : public Cli {
protected:
    void SetUp() override
    {
        Cli::SetUp();
        fs::copy_file(sample_path("bricks.png"), dir / "bricks.png");
        fs::copy_file(
            fs::path(TEXSYN_TEST_DATA).parent_path() / "masks/bricks_hole.png", dir / "hole.png");
        ASSERT_EQ(shell("oiiotool bricks.png --colorconvert sRGB linear -d float -o plate.exr "
                        "&& oiiotool hole.png --cut 128x256+0+0 -o narrow.png "
                        "&& oiiotool bricks.png -o rgb_mask.png")
                      .status,
            0);
    }
};

TEST_F(FillCli, KeepsTheUnmaskedPixelsOfAFloatPlate)
{
    CliRun r = texsyn("--seed 4 -v plate.exr --fill:mask=hole.png -o filled.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("filled 4463 px in 1 hole"), std::string::npos) << r.err;
    // -v names the schedule that ran where the options say iterations=auto.
    EXPECT_NE(r.err.find("iterations=auto"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" levels, iterations 4,6,"), std::string::npos) << r.err;
    OIIO::ImageBuf plate((dir / "plate.exr").string()), filled((dir / "filled.exr").string()),
        mask((dir / "hole.png").string());
    ASSERT_TRUE(filled.read()) << filled.geterror();
    EXPECT_EQ(filled.spec().get_string_attribute("synth:method"), "fill");
    EXPECT_EQ(filled.spec().get_string_attribute("wrapmodes"), "");
    size_t same = 0, changed = 0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            bool equal = true;
            for (int c = 0; c < 3; ++c)
                equal = equal && plate.getchannel(x, y, 0, c) == filled.getchannel(x, y, 0, c);
            if (mask.getchannel(x, y, 0, 0) == 0.0f)
                same += equal;
            else
                changed += !equal;
        }
    EXPECT_EQ(same, size_t(256 * 256 - 4463));
    EXPECT_GT(changed, size_t(4000));
    // The same seed at another thread count: the same file.
    ASSERT_EQ(texsyn("--seed 4 --threads 1 plate.exr --fill:mask=hole.png -o one.exr").status, 0);
    EXPECT_EQ(
        OIIO::ImageBufAlgo::compare(OIIO::ImageBuf((dir / "one.exr").string()), filled, 0, 0).nfail,
        0u);
}

TEST_F(FillCli, BadMasksAreRefusedWithOneLine)
{
    struct Case {
        std::string args, message;
    };
    for (const Case& c : std::vector<Case> {
             { "bricks.png --fill -o out.png", "--fill : mask= : give the mask image" },
             { "bricks.png --fill:mask=missing.png -o out.png",
                 "--fill : mask=missing.png : no such file" },
             { "bricks.png --fill:mask=narrow.png -o out.png",
                 "mask=narrow.png : the mask is 128x256 with 1 channel; it must be one channel "
                 "of the image's size (256x256)" },
             { "bricks.png --fill:mask=rgb_mask.png -o out.png", "with 3 channels" },
             { "bricks.png --fill:mask=hole.png:patch=7,9 -o out.png",
                 "patch=7,9 : list the sizes largest first" },
             { "bricks.png --fill:mask=hole.png:sample=narrow.png -o out.png",
                 "the sample has 1 channel and the image 3 channels" },
         }) {
        CliRun r = texsyn(c.args);
        EXPECT_EQ(r.status, 1) << c.args;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_FALSE(fs::exists(dir / "out.png")) << c.args;
    }
}

// --tileable: the result is marked as tiling, -v reports the band and the changed fraction,
// and a band too wide is refused with one line and no output.
TEST_F(FillCli, TileableMarksItsResultAndRefusesTooWideABand)
{
    CliRun r = texsyn("--seed 1 -v plate.exr --tileable -o tile.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("re-synthesized a 48 px band across the seams; changed 34.0% of the "
                         "pixels"),
        std::string::npos)
        << r.err;
    OIIO::ImageBuf tile((dir / "tile.exr").string());
    ASSERT_TRUE(tile.read()) << tile.geterror();
    EXPECT_EQ(tile.spec().get_string_attribute("wrapmodes"), "periodic,periodic");
    EXPECT_EQ(tile.spec().get_string_attribute("synth:method"), "tileable");

    r = texsyn("bricks.png --tileable:band=90 -o out.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.first_err_line(),
        "texsyn ERROR: --tileable : band=90 : too wide for a 256x256 image (at most a third of "
        "its shorter side, 85)")
        << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}
