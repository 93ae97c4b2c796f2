// SPDX-License-Identifier: Apache-2.0
// --material end to end: every map a copying method writes is --apply-map of its input with
// the run's source map (normal maps turned with isotropic=1), data maps keep their numbers,
// and what cannot be a material set is refused with one line and no output.
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "cli_fixture.h"

class MaterialCli : public Cli {
protected:
    void SetUp() override
    {
        Cli::SetUp();
        for (const char* name : { "bricks.png", "bricks_height.png", "bricks_normal.png" })
            fs::copy_file(sample_path(name), dir / name);
    }

    // Whether two image files hold the same numbers.
    bool same_pixels(const std::string& a, const std::string& b)
    {
        OIIO::ImageBuf ia((dir / a).string()), ib((dir / b).string());
        const auto r = OIIO::ImageBufAlgo::compare(ia, ib, 0.0f, 0.0f);
        EXPECT_FALSE(ia.has_error() || ib.has_error()) << ia.geterror() << ib.geterror();
        return ia.spec().width == ib.spec().width && ia.spec().nchannels == ib.spec().nchannels
            && r.nfail == 0 && !r.error;
    }
};

// The alignment test: each output map equals --apply-map of its input with the
// output's source map, here after isotropic=1 so that the normal map turns.
TEST_F(MaterialCli, EveryMapFollowsTheSourceMap)
{
    CliRun r = texsyn("-v --seed 3 bricks.png --material:height=bricks_height.png:normal="
                      "bricks_normal.png --patch:size=192x160:isotropic=1:map=coords.exr -o "
                      "out_{map}.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    // -v names the set and the options it was made with.
    EXPECT_NE(r.err.find("--material search=albedo,height:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" from material set of bricks.png in "), std::string::npos) << r.err;
    for (const char* map : { "albedo", "height", "normal" })
        EXPECT_TRUE(fs::exists(dir / ("out_" + std::string(map) + ".exr"))) << map;
    EXPECT_FALSE(fs::exists(dir / "out_{map}.exr"));
    ASSERT_EQ(texsyn("--iscolorspace Raw --apply-map coords.exr bricks_height.png -d half -o "
                     "height.exr")
                  .status,
        0);
    ASSERT_EQ(texsyn("--iscolorspace Raw --apply-map:normal=opengl coords.exr bricks_normal.png "
                     "-d half -o normal.exr")
                  .status,
        0);
    ASSERT_EQ(texsyn("--apply-map coords.exr bricks.png --tocolorspace scene_linear -d half -o "
                     "albedo.exr")
                  .status,
        0);
    EXPECT_TRUE(same_pixels("out_height.exr", "height.exr"));
    EXPECT_TRUE(same_pixels("out_normal.exr", "normal.exr"));
    EXPECT_TRUE(same_pixels("out_albedo.exr", "albedo.exr"));
    // Data maps are the stored numbers: the height map's values are the input's, moved.
    OIIO::ImageBuf height((dir / "out_height.exr").string());
    EXPECT_EQ(std::string(height.spec().get_string_attribute("synth:colorspace")), "Raw");
    // Turned copies turned the normals: they differ from a plain re-application.
    ASSERT_EQ(texsyn("--iscolorspace Raw --apply-map coords.exr bricks_normal.png -d half -o "
                     "unturned.exr")
                  .status,
        0);
    EXPECT_FALSE(same_pixels("out_normal.exr", "unturned.exr"));
}

TEST_F(MaterialCli, WhatCannotBeAMaterialSetIsRefused)
{
    const std::initializer_list<std::string> inputs
        = { "stucco.png", "bricks.png", "bricks_height.png", "bricks_normal.png" };
    expect_failure("bricks.png --material:height=bricks_height.png --patch -o out.exr",
        "texsyn ERROR: -o out.exr : the current item is a material set (albedo, height); put "
        "{map} in the name, e.g. out_{map}.exr",
        inputs);
    expect_failure("bricks.png --material:height=bricks_height.png --pyramid -o out_{map}.exr",
        "texsyn ERROR: --pyramid : the current item is a material set (from --material); "
        "--neighborhood, --choosy, --patch and --fill synthesize one",
        inputs);
    expect_failure("bricks.png --material:height=bricks_height.png --patch -o out_{map}.exr "
                   "--recipe m.texsyn",
        "texsyn ERROR: --recipe m.texsyn : the current item is a material set; recipes describe "
        "images",
        inputs);
    expect_failure("bricks.png --material:normal=bricks_height.png --patch -o out_{map}.exr",
        "texsyn ERROR: --material : normal=bricks_height.png : a normal map needs 3 channels (x, "
        "y, z); it has 1",
        inputs);
    expect_failure("bricks.png --material:weights=1,2,3 --patch -o out_{map}.exr",
        "texsyn ERROR: --material : weights=1.000000,2.000000,3.000000 : more weights than maps "
        "in search= (2)",
        inputs);
    ASSERT_EQ(shell("oiiotool bricks_height.png --resize 100x100 -o small_height.png").status, 0);
    expect_failure("bricks.png --material:height=small_height.png --patch -o out_{map}.exr",
        "texsyn ERROR: --material : the height map is 100x100 and the albedo 256x256: a map the "
        "search weighs must have the albedo's size",
        { "stucco.png", "bricks.png", "bricks_height.png", "bricks_normal.png",
            "small_height.png" });
}

// Issue #34: a map's values are refused when read if they are not finite, and written in a
// type that holds them (a roughness map up to 1e5 used to come out as half: infinity).
TEST_F(MaterialCli, MapValuesAreCheckedWhenReadAndKeptWhenWritten)
{
    OIIO::ImageBuf height;
    height.copy(OIIO::ImageBuf((dir / "bricks_height.png").string()), OIIO::TypeFloat);
    OIIO::ImageBuf large = OIIO::ImageBufAlgo::mul(height, 100000.0f); // up to 77255
    ASSERT_TRUE(large.write((dir / "rough.exr").string(), OIIO::TypeFloat));
    OIIO::ImageBuf nan;
    nan.copy(height);
    const float bad[1] = { std::numeric_limits<float>::quiet_NaN() };
    nan.setpixel(3, 4, bad);
    ASSERT_TRUE(nan.write((dir / "nan.exr").string(), OIIO::TypeFloat));
    const std::initializer_list<std::string> inputs = { "stucco.png", "bricks.png",
        "bricks_height.png", "bricks_normal.png", "rough.exr", "nan.exr" };

    // A NaN is refused when the map is read, naming the map's option, even in a map the
    // search does not weigh.
    expect_failure(
        "bricks.png --material:roughness=nan.exr --patch:size=64x64:flatten=1 -o out_{map}.exr",
        "texsyn ERROR: --material : roughness=nan.exr : pixel (3, 4) channel Y is NaN; texsyn "
        "needs finite pixel values",
        inputs);

    // Values beyond half's range: an EXR written as float, not as infinity.
    CliRun r = texsyn(
        "--seed 2 bricks.png --material:roughness=rough.exr --patch:size=64x64:flatten=1 -o "
        "out_{map}.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf rough((dir / "out_roughness.exr").string());
    ASSERT_TRUE(rough.read()) << rough.geterror();
    EXPECT_EQ(rough.spec().format, OIIO::TypeFloat);
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(rough);
    EXPECT_EQ(stats.infcount[0], 0u);
    EXPECT_GT(stats.max[0], 65504.0f);
    EXPECT_LE(stats.max[0], 77255.0f);
    OIIO::ImageBuf albedo((dir / "out_albedo.exr").string());
    ASSERT_TRUE(albedo.read());
    EXPECT_EQ(albedo.spec().format, OIIO::TypeHalf); // values that fit keep the default
    // ... or refused when -d asks for half, and by an integer format, which holds 0..1.
    fs::remove(dir / "out_albedo.exr");
    fs::remove(dir / "out_height.exr");
    fs::remove(dir / "out_roughness.exr");
    expect_failure_starting("bricks.png --material:roughness=rough.exr "
                            "--patch:size=64x64:flatten=1 -d half -o half_{map}.exr",
        "texsyn ERROR: -o half_roughness.exr : has values up to 7", inputs);
    expect_failure_starting("bricks.png --material:roughness=rough.exr "
                            "--patch:size=64x64:flatten=1 -o png_{map}.png",
        "texsyn ERROR: -o png_roughness.png : the roughness map's values span 3", inputs);
    const CliRun png = texsyn(
        "bricks.png --material:roughness=rough.exr --patch:size=64x64:flatten=1 -o png_{map}.png");
    EXPECT_NE(png.err.find("; a uint8 file holds 0..1: write it as .exr (or .tif with -d float)"),
        std::string::npos)
        << png.err;
}
