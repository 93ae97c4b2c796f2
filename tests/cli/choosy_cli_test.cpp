// SPDX-License-Identifier: Apache-2.0
// End-to-end runs of --choosy (with map= and --apply-map, recipes), bad input included.
#include <texsyn/io.h>
#include <texsyn/recipe.h>

#include "cli_fixture.h"

namespace {

// The defaults (kd-trees, the sample in 8 orientations) but smaller, two passes at the coarser
// levels. The 8 orientations of the 128x128 sample take most of the time.
constexpr const char* kQuick = "--choosy:size=64x64:levels=3:iterations=1,2";
// The exhaustive oracle is O(sample x output): a tiny output only.
const std::string kExhaustive = "--choosy:size=24x16:levels=2:search=exhaustive:isotropic=0";
// One orientation: the cheapest run, for the cases where the method's settings do not matter.
constexpr const char* kCheap = "--choosy:size=24x16:levels=2:isotropic=0";

} // namespace

TEST_F(Cli, ChoosyWritesTheImageAndItsSourceMap)
{
    CliRun r
        = texsyn(std::string("stucco.png ") + kQuick + ":map=coords.exr -o out.exr -o out.png");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf exr = read("out.exr");
    EXPECT_EQ(exr.spec().width, 64);
    EXPECT_EQ(exr.spec().height, 64);
    EXPECT_EQ(exr.nchannels(), 3);
    EXPECT_EQ(exr.spec().get_string_attribute("synth:method"), "choosy");
    EXPECT_EQ(exr.spec().get_string_attribute("synth:sample"), "stucco.png");
    const std::string options = exr.spec().get_string_attribute("synth:options");
    EXPECT_EQ(options.find("size=64x64:levels=3:iterations=1,2:penalty=1:isotropic=0:"), 0u)
        << options;
    // Every output pixel is the sample pixel the map names (8-bit in, 8-bit out: exact), and
    // the map re-applied to the sample gives the same picture.
    expect_source_map("coords.exr", "out.png", "stucco.png", "choosy");
}

TEST_F(Cli, ChoosyMapOfACroppedSampleAppliesToTheWholeSample)
{
    // 70x66 is cropped to 68x64 (multiples of 2^(levels-1) = 4) before the synthesis; the
    // map still names positions in the file as given.
    OIIO::ImageBuf whole = read("stucco.png");
    OIIO::ImageBuf part = OIIO::ImageBufAlgo::cut(whole, OIIO::ROI(9, 79, 20, 86));
    ASSERT_TRUE(part.write((dir / "part.png").string(), OIIO::TypeUInt8)) << part.geterror();
    CliRun r = texsyn("part.png --choosy:size=32x40:levels=3:map=coords.exr -o out.png");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read("coords.exr").spec().get_string_attribute("synth:sample_size"), "70x66");
    expect_source_map("coords.exr", "out.png", "part.png", "choosy");
}

TEST_F(Cli, ChoosyIsTheSameAtAnyThreadCount)
{
    // The kd-trees in 8 orientations on a 64x64 crop (the whole sample takes longer), and
    // the exhaustive search.
    OIIO::ImageBuf crop = OIIO::ImageBufAlgo::cut(read("stucco.png"), OIIO::ROI(0, 64, 0, 64));
    ASSERT_TRUE(crop.write((dir / "crop.png").string(), OIIO::TypeUInt8)) << crop.geterror();
    const std::string commands[]
        = { "crop.png --choosy:size=48x48:levels=3:iterations=1,2", "stucco.png " + kExhaustive };
    for (const std::string& command : commands) {
        for (const char* threads : { "1", "2" })
            ASSERT_EQ(texsyn(std::string("--threads ") + threads + " " + command + " -d float -o t"
                          + threads + ".exr")
                          .status,
                0)
                << command;
        OIIO::ImageBuf a = read("t1.exr"), b = read("t2.exr");
        EXPECT_EQ(pixel_hash(a), pixel_hash(b)) << command;
        // Only the command line recorded in the metadata differs.
        for (const OIIO::ParamValue& p : a.spec().extra_attribs) {
            if (p.name() != "synth:commandline") {
                EXPECT_EQ(a.spec().metadata_val(p), b.spec().metadata_val(p)) << p.name();
            }
        }
    }
}

TEST_F(Cli, RecipeAfterChoosyMakesTheSameImage)
{
    const Recipe recipe = expect_recipe_remakes_the_output(
        "--seed 3 stucco.png --choosy:size=40x24:levels=2:iterations=1,2:isotropic=0:"
        "map=coords.exr -d float -o out.exr --recipe r.texsyn",
        "choosy");
    EXPECT_EQ(recipe.seed, 3u);
    EXPECT_EQ(recipe.options.value("iterations"), "1,2");
    EXPECT_EQ(recipe.options.value("isotropic"), "0");
}

TEST_F(Cli, BadChoosyRequestsAreRefused)
{
    expect_failure("stucco.png --choosy:size=62x64:levels=3 -o out.exr",
        "texsyn ERROR: --choosy : size=62x64: each side must be a multiple of 4 (2^(levels-1)) "
        "for levels=3; the nearest is 64x64");
    expect_failure("stucco.png --choosy:size=8x8:levels=2 -o out.exr",
        "texsyn ERROR: --choosy : size=8x8 is too small for levels=2: the coarsest output level "
        "would be 4x4, smaller than the 5x5 neighbourhood");
    expect_failure("stucco.png --choosy:levels=6 -o out.exr",
        "texsyn ERROR: --choosy : levels=6 is too many for the sample (128x128): its coarsest "
        "level would be smaller than the 5x5 neighbourhood (use levels=5 or less)");
    // Samples too thin for any level name their own size, not their crop's.
    write_sample("row.png", 3, OIIO::TypeUInt8);
    const OIIO::ImageBuf thin
        = OIIO::ImageBufAlgo::cut(read("row.png"), OIIO::ROI(0, 32, 0, 1, 0, 1, 0, 3));
    ASSERT_TRUE(thin.write((dir / "thin.png").string()));
    fs::remove(dir / "row.png");
    expect_failure("thin.png --choosy -o out.exr",
        "texsyn ERROR: --choosy : the sample (32x1) is smaller than the 5x5 neighbourhood",
        { "stucco.png", "thin.png" });
    fs::remove(dir / "thin.png");
    expect_failure("stucco.png --choosy:levels=2:iterations=1,2,3 -o out.exr",
        "texsyn ERROR: --choosy : iterations=1,2,3 : 3 values for levels=2 (give 1..2)");
    expect_failure("stucco.png --choosy:iterations=1,0 -o out.exr",
        "texsyn ERROR: --choosy : iterations=1,0 : 0 is out of range 1..64");
    expect_failure("stucco.png --choosy:search=coherent -o out.exr",
        "texsyn ERROR: --choosy : search=coherent : not one of exhaustive|kdtree");
    expect_failure("stucco.png --choosy:penalty=17 -o out.exr",
        "texsyn ERROR: --choosy : penalty=17 : out of range 0..16");
    expect_failure("stucco.png --choosy:levels -o out.exr",
        "texsyn ERROR: --choosy : malformed option 'levels' (expected name=value)");
    expect_failure("stucco.png --choosy:n=9 -o out.exr",
        "texsyn ERROR: --choosy : n=9 : unknown option (known: size, levels, iterations, "
        "penalty, isotropic, flatten, scale, search, dims, eps, map)");
    expect_failure("stucco.png --choosy:map=coords.png -o out.exr",
        "texsyn ERROR: --choosy : map=coords.png : name it *.exr");
    expect_failure("stucco.png --choosy:map=out.exr -o out.exr",
        "texsyn ERROR: map=out.exr : is also written by -o out.exr");
    expect_failure("stucco.png --analyze --choosy -o out.exr",
        "texsyn ERROR: --choosy : needs an image, not an analysis (the analysis of stucco.png; "
        "only --pyramid, --mix and --transfer take analyses)");
    expect_failure_starting("stucco.png --choosy:size=60000x60000 -o out.exr",
        "texsyn ERROR: --choosy : size=60000x60000 would need about ");
    // A failure after an -o that succeeded leaves nothing behind either (the second command
    // synthesizes from the first's 24x16 result).
    expect_failure(std::string("stucco.png ") + kCheap
            + ":map=coords.exr -o first.exr --choosy:size=31x30:levels=2 -o second.exr",
        "texsyn ERROR: --choosy : size=31x30: each side must be a multiple of 2 (2^(levels-1)) "
        "for levels=2; the nearest is 32x30");
    write_sample("nan.exr", 3, OIIO::TypeFloat, std::nanf(""));
    expect_failure("nan.exr --choosy:size=32x32:levels=2 -o out.exr",
        "texsyn ERROR: nan.exr: pixel (3, 4) channel R is NaN; texsyn needs finite pixel values",
        { "stucco.png", "nan.exr" });
}

// On images choosy keeps the sample's orientation unless asked (issue #16): the default is
// isotropic=0, as the output's synth:options and the recipe it writes say.
TEST_F(Cli, ChoosyKeepsTheSamplesOrientationByDefault)
{
    CliRun r = texsyn("stucco.png --choosy:size=24x16:levels=2 -o out.exr --recipe out.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(read("out.exr").spec().get_string_attribute("synth:options").find(":isotropic=0:"),
        std::string::npos);
    EXPECT_NE(slurp(dir / "out.texsyn").find("\"isotropic\": 0"), std::string::npos);
}
