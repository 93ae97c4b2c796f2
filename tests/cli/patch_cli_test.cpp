// SPDX-License-Identifier: Apache-2.0
// End-to-end runs of --patch: the image, its source map and --apply-map, the -v report, a
// guide image, recipes through the tool and the plugin, bad input.
#include <texsyn/io.h>
#include <texsyn/recipe.h>

#include "cli_fixture.h"

namespace {

constexpr const char* kQuick = "--patch:size=96x80";

} // namespace

TEST_F(Cli, PatchWritesTheImageItsSourceMapAndAReport)
{
    CliRun r
        = texsyn(std::string("-v stucco.png ") + kQuick + ":map=coords.exr -o out.exr -o out.png");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf exr = read("out.exr");
    EXPECT_EQ(exr.spec().width, 96);
    EXPECT_EQ(exr.spec().height, 80);
    EXPECT_EQ(exr.nchannels(), 3);
    EXPECT_EQ(exr.spec().get_string_attribute("synth:method"), "patch");
    const std::string options = exr.spec().get_string_attribute("synth:options");
    EXPECT_EQ(options.find("size=96x80:levels=3:patch=11,7:iterations=1,3,8:"), 0u) << options;
    // -v: the feature scale, how the levels were chosen, what the result copies.
    EXPECT_NE(r.err.find("texsyn: --patch feature size "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" px; 3 levels, the coarsest with features of "), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("% of the sample; largest verbatim copy "), std::string::npos) << r.err;
    // Every output pixel is the sample pixel the map names.
    expect_source_map("coords.exr", "out.png", "stucco.png", "patch");
}

TEST_F(Cli, PatchTakesAGuideImage)
{
    // A one-channel guide of the sample's size: a left-right ramp.
    OIIO::ImageBuf ramp(OIIO::ImageSpec(128, 128, 1, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(ramp, { 0.0f }, { 1.0f }, { 0.0f }, { 1.0f });
    ASSERT_TRUE(ramp.write((dir / "ramp.exr").string()));
    CliRun r = texsyn(std::string("stucco.png ") + kQuick + ":guide=ramp.exr -d float -o a.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    r = texsyn(std::string("stucco.png ") + kQuick + " -d float -o b.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(pixel_hash(read("a.exr")), pixel_hash(read("b.exr")));
    // A recipe keeps the guide and remakes the image.
    r = texsyn(std::string("stucco.png ") + kQuick
        + ":guide=ramp.exr -d float -o c.exr --recipe r.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    Recipe recipe;
    std::string error;
    ASSERT_TRUE(recipe_from_filename((dir / "r.texsyn").string(), recipe, error)) << error;
    EXPECT_EQ(recipe.method, "patch");
    OIIO::ImageBuf again;
    ASSERT_TRUE(run_recipe(recipe, again, nullptr, error)) << error;
    EXPECT_EQ(pixel_hash(again), pixel_hash(read("c.exr")));

    OIIO::ImageBuf small(OIIO::ImageSpec(64, 64, 1, OIIO::TypeFloat));
    ASSERT_TRUE(small.write((dir / "small.exr").string()));
    expect_failure(std::string("stucco.png ") + kQuick + ":guide=small.exr -o out.exr",
        "texsyn ERROR: --patch : guide=small.exr : the guide is 64x64 with 1 channel; it must be "
        "one channel of the sample's size (128x128)",
        { "stucco.png", "ramp.exr", "small.exr", "a.exr", "b.exr", "c.exr", "r.texsyn" });
}

TEST_F(Cli, PatchIsTheSameAtAnyThreadCount)
{
    std::string first;
    for (int threads : { 1, 2, 4 }) {
        CliRun r = texsyn("--threads " + std::to_string(threads) + " stucco.png " + kQuick
            + " -d float -o out" + std::to_string(threads) + ".exr");
        ASSERT_EQ(r.status, 0) << r.err;
        const std::string hash = pixel_hash(read("out" + std::to_string(threads) + ".exr"));
        if (first.empty())
            first = hash;
        EXPECT_EQ(hash, first) << threads;
    }
}

TEST_F(Cli, RecipeAfterPatchMakesTheSameImage)
{
    const Recipe recipe = expect_recipe_remakes_the_output(
        "--seed 3 stucco.png --patch:size=40x24:patch=7,5:repetition=1:map=coords.exr -d float "
        "-o out.exr --recipe r.texsyn",
        "patch");
    EXPECT_EQ(recipe.seed, 3u);
    EXPECT_EQ(recipe.options.value("patch"), "7,5");
    EXPECT_EQ(recipe.options.value("repetition"), "1");
}

TEST_F(Cli, BadPatchRequestsAreRefused)
{
    expect_failure("stucco.png --patch:patch=5,9 -o out.exr",
        "texsyn ERROR: --patch : patch=5,9 : list the sizes largest first");
    expect_failure(
        "stucco.png --patch:patch=6 -o out.exr", "texsyn ERROR: --patch : patch=6 : not odd");
    expect_failure("stucco.png --patch:levels=2:iterations=1,2,3 -o out.exr",
        "texsyn ERROR: --patch : iterations=1,2,3 : 3 values for levels=2 (give 1..2)");
    expect_failure("stucco.png --patch:levels=5 -o out.exr",
        "texsyn ERROR: --patch : levels=5 is too many for a 128x128 sample and a 128x128 "
        "output: level 4 would be smaller than its 11-pixel patch (use levels=4 or less)");
    expect_failure("stucco.png --patch:size=6x100:patch=11,7 -o out.exr",
        "texsyn ERROR: --patch : size=6x100 is smaller than the 7-pixel patch");
    expect_failure("stucco.png --patch:size=2x100 -o out.exr",
        "texsyn ERROR: --patch : size=2x100 is smaller than the 3-pixel patch");
    expect_failure("stucco.png --patch:repetition=-1 -o out.exr",
        "texsyn ERROR: --patch : repetition=-1 : out of range 0..10");
    expect_failure("stucco.png --patch:vote=median -o out.exr",
        "texsyn ERROR: --patch : vote=median : not one of robust|mean");
    expect_failure("stucco.png --patch:map=coords.png -o out.exr",
        "texsyn ERROR: --patch : map=coords.png : name it *.exr");
    // Two writers of one file, however it is spelled, are refused before anything runs.
    expect_failure("stucco.png --patch:map=m.exr -o ./m.exr",
        "texsyn ERROR: map=m.exr : is also written by -o ./m.exr");
    expect_failure("stucco.png --patch:size=32x32:map=m.exr --patch:map=./m.exr -o out.exr",
        "texsyn ERROR: map=./m.exr : is also written by map=m.exr");
    expect_failure("stucco.png --patch:guide=missing.exr -o out.exr",
        "texsyn ERROR: --patch : guide=missing.exr : no such file");
    expect_failure_starting("stucco.png --patch:size=60000x60000 -o out.exr",
        "texsyn ERROR: --patch : size=60000x60000 would need about ");
    OIIO::ImageBuf tiny = OIIO::ImageBufAlgo::cut(read("stucco.png"), OIIO::ROI(0, 2, 0, 40));
    ASSERT_TRUE(tiny.write((dir / "tiny.png").string(), OIIO::TypeUInt8));
    expect_failure("tiny.png --patch -o out.exr",
        "texsyn ERROR: --patch : the sample (2x40) is smaller than the 3-pixel patch (give a "
        "smaller patch=)",
        { "stucco.png", "tiny.png" });
    write_sample("nan.exr", 3, OIIO::TypeFloat, std::nanf(""));
    expect_failure("nan.exr --patch -o out.exr",
        "texsyn ERROR: nan.exr: pixel (3, 4) channel R is NaN; texsyn needs finite pixel values",
        { "stucco.png", "tiny.png", "nan.exr" });
}
