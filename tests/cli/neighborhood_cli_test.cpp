// SPDX-License-Identifier: Apache-2.0
// End-to-end runs of --neighborhood and --apply-map, bad input included.
#include <texsyn/io.h>
#include <texsyn/recipe.h>

#include "cli_fixture.h"

namespace {

constexpr const char* kQuick = "--neighborhood:size=64x48:levels=2:n=7,5:search=exhaustive";

} // namespace

TEST_F(Cli, NeighborhoodWritesTheImageAndItsSourceMap)
{
    CliRun r = texsyn(std::string("stucco.png ") + kQuick + ":map=coords.exr -o out.png");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf out = read("out.png");
    EXPECT_EQ(out.spec().width, 64);
    EXPECT_EQ(out.spec().height, 48);
    EXPECT_EQ(out.spec().get_string_attribute("synth:method"), "neighborhood");
    EXPECT_EQ(
        out.spec().get_string_attribute("synth:options").find("size=64x48:levels=2:n=7,5:"), 0u);
    // Every output pixel is the sample pixel the map names (8-bit in, 8-bit out: exact), and
    // the map re-applied to the sample gives the same picture.
    expect_source_map("coords.exr", "out.png", "stucco.png", "neighborhood");
}

TEST_F(Cli, RecipeAfterNeighborhoodMakesTheSameImage)
{
    const Recipe recipe = expect_recipe_remakes_the_output(
        "--seed 3 stucco.png --neighborhood:size=32x24:levels=2:n=7,5:search=exhaustive:"
        "map=coords.exr -d float -o out.exr --recipe r.texsyn",
        "neighborhood");
    EXPECT_EQ(recipe.seed, 3u);
    EXPECT_EQ(recipe.options.value("n"), "7,5");
}

TEST_F(Cli, ApplyMapKeepsAnAlignedMapsValues)
{
    // A "height map" aligned with the sample, stored as 16-bit data: its values come back
    // exactly where the map says, in its own encoding.
    OIIO::ImageSpec spec(128, 128, 1, OIIO::TypeFloat);
    OIIO::ImageBuf height(spec);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            const float v = float((x * 7 + y * 13) % 256) / 255.0f;
            height.setpixel(x, y, &v, 1);
        }
    ASSERT_TRUE(height.write((dir / "height.png").string(), OIIO::TypeUInt16));
    ASSERT_EQ(texsyn(std::string("stucco.png ") + kQuick + ":map=coords.exr -o out.exr").status, 0);
    CliRun r = texsyn("--iscolorspace Raw --apply-map coords.exr height.png -d float -o h.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf h = read("h.exr"), map = read("coords.exr"), in = read("height.png");
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            float xy[2], got = 0, want = 0;
            map.getpixel(x, y, xy, 2);
            h.getpixel(x, y, &got, 1);
            in.getpixel(int(xy[0]), int(xy[1]), &want, 1);
            ASSERT_EQ(got, want) << x << "," << y;
        }
}

TEST_F(Cli, NeighborhoodIsTheSameAtAnyThreadCount)
{
    ASSERT_EQ(
        texsyn(std::string("--threads 1 stucco.png ") + kQuick + " -d float -o a.exr").status, 0);
    ASSERT_EQ(
        texsyn(std::string("--threads 2 stucco.png ") + kQuick + " -d float -o b.exr").status, 0);
    EXPECT_EQ(pixel_hash(read("a.exr")), pixel_hash(read("b.exr")));
}

TEST_F(Cli, BadNeighborhoodRequestsAreRefused)
{
    expect_failure(
        "stucco.png --neighborhood:n=8 -o out.exr", "texsyn ERROR: --neighborhood : n=8 : not odd");
    expect_failure("stucco.png --neighborhood:n=65 -o out.exr",
        "texsyn ERROR: --neighborhood : n=65 : out of range 3..63");
    expect_failure("stucco.png --neighborhood:n=9,x -o out.exr",
        "texsyn ERROR: --neighborhood : n=9,x : x is not an integer (expected e.g. 9,7,5)");
    expect_failure("stucco.png --neighborhood:levels=2:n=9,7,5 -o out.exr",
        "texsyn ERROR: --neighborhood : n=9,7,5 : 3 values for levels=2 (give 1..2)");
    expect_failure("stucco.png --neighborhood:search=fast -o out.exr",
        "texsyn ERROR: --neighborhood : search=fast : not one of "
        "exhaustive|tsvq|kdtree|coherent");
    expect_failure("stucco.png --neighborhood:coarse=4 -o out.exr",
        "texsyn ERROR: --neighborhood : coarse=4 : not odd");
    expect_failure("stucco.png --neighborhood:levels=6 -o out.exr",
        "texsyn ERROR: --neighborhood : levels=6 is too many for the sample (128x128): level 4 "
        "would be 8x8, smaller than its n=9 neighbourhood (use levels=4 or less)");
    expect_failure("stucco.png --neighborhood:n=33:levels=1:size=20x20 -o out.exr",
        "texsyn ERROR: --neighborhood : size=20x20 is too small for levels=1: output level 0 "
        "would be 20x20, smaller than its n=33 neighbourhood");
    expect_failure("stucco.png --neighborhood:map=coords.png -o out.exr",
        "texsyn ERROR: --neighborhood : map=coords.png : name it *.exr");
    expect_failure("stucco.png --neighborhood:map=a.exr:map=b.exr -o out.exr",
        "texsyn ERROR: --neighborhood : map=b.exr : given twice");
    expect_failure("stucco.png --neighborhood:map=out.exr -o out.exr",
        "texsyn ERROR: map=out.exr : is also written by -o out.exr");
    expect_failure_starting("stucco.png --neighborhood:size=60000x60000 -o out.exr",
        "texsyn ERROR: --neighborhood : size=60000x60000 would need about ");
    write_sample("tiny.png", 3, OIIO::TypeUInt8);
    expect_failure("tiny.png --neighborhood:n=35:levels=1 -o out.exr",
        "texsyn ERROR: --neighborhood : the sample (32x32) is smaller than the n=35 neighbourhood",
        { "stucco.png", "tiny.png" });
}

TEST_F(Cli, BadApplyMapInputIsRefused)
{
    ASSERT_EQ(texsyn(std::string("stucco.png ") + kQuick + ":map=coords.exr -o out.exr").status, 0);
    const std::initializer_list<std::string> inputs = { "stucco.png", "coords.exr", "out.exr" };
    expect_failure("--apply-map coords.exr",
        "texsyn ERROR: --apply-map : needs two arguments, the source map and the image "
        "(--apply-map coords.exr height.png)",
        inputs);
    expect_failure("--apply-map missing.exr stucco.png -o x.png",
        "texsyn ERROR: missing.exr: no such file", inputs);
    expect_failure("--apply-map out.exr stucco.png -o x.png",
        "texsyn ERROR: --apply-map out.exr stucco.png : the source map has the channels R, G, B; "
        "expected the channels x, y (and t, m) that --neighborhood:map=, --choosy:map=, "
        "--patch:map= and --fill:map= write",
        inputs);
    write_sample("small.png", 3, OIIO::TypeUInt8);
    ASSERT_EQ(shell("oiiotool small.png --resize 48x48 -o small48.png").status, 0);
    expect_failure("--apply-map coords.exr small48.png -o x.png",
        "texsyn ERROR: --apply-map coords.exr small48.png : the image is 48x48 but the source "
        "map was made from a 128x128 sample (the image must be aligned with the sample: its "
        "size, or a whole multiple or fraction of it)",
        { "stucco.png", "coords.exr", "out.exr", "small.png", "small48.png" });
    expect_failure("--apply-map:normal=sideways coords.exr stucco.png -o x.png",
        "texsyn ERROR: --apply-map:normal=sideways : expected --apply-map:normal=opengl, "
        "normal=directx or normal=none",
        { "stucco.png", "coords.exr", "out.exr", "small.png", "small48.png" });
    // A map at a quarter of the sample's size is taken, at a quarter of the result's size.
    CliRun quarter = texsyn("--apply-map coords.exr small.png -o quarter.exr");
    ASSERT_EQ(quarter.status, 0) << quarter.err;
    OIIO::ImageBuf q((dir / "quarter.exr").string());
    ASSERT_TRUE(q.read()) << q.geterror();
    EXPECT_EQ(q.spec().width * 4, OIIO::ImageBuf((dir / "coords.exr").string()).spec().width);
    fs::remove(dir / "quarter.exr");
    write_sample("gray.png", 1, OIIO::TypeUInt8);
    expect_failure("--apply-map:normal=opengl coords.exr gray.png -o x.png",
        "texsyn ERROR: --apply-map:normal=opengl coords.exr gray.png : a normal map needs 3 "
        "channels (x, y, z); the image has 1",
        { "stucco.png", "coords.exr", "out.exr", "small.png", "small48.png", "gray.png" });
    expect_failure("--apply-map coords.exr stucco.png -o coords.exr",
        "texsyn ERROR: -o coords.exr : refusing to overwrite the input coords.exr",
        { "stucco.png", "coords.exr", "out.exr", "small.png", "small48.png", "gray.png" });
}
