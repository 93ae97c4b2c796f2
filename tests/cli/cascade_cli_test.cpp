// SPDX-License-Identifier: Apache-2.0
// End-to-end runs of --cascade: as a generator, as a texture transfer, with a dilation
// control image, bad input included.
#include "cli_fixture.h"

namespace {

// A one-channel control image of constant `value`.
void write_control(const fs::path& path, float value)
{
    OIIO::ImageBuf buf(OIIO::ImageSpec(16, 16, 1, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(buf, { value });
    ASSERT_TRUE(buf.write(path.string(), OIIO::TypeFloat)) << buf.geterror();
}

} // namespace

TEST_F(Cli, CascadeGeneratesAnImageWithoutInput)
{
    CliRun r = texsyn("--cascade:size=48x32:levels=2:r=3.9 -o out.exr -o out.png");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf exr = read("out.exr");
    EXPECT_EQ(exr.spec().width, 48);
    EXPECT_EQ(exr.spec().height, 32);
    EXPECT_EQ(exr.nchannels(), 1);
    EXPECT_EQ(exr.spec().get_string_attribute("synth:method"), "cascade");
    EXPECT_NE(exr.spec().get_string_attribute("synth:options").find("size=48x32:levels=2:"),
        std::string::npos);
    EXPECT_EQ(file_type("out.exr"), OIIO::TypeHalf);
    // Integer files get the space of untagged integer samples, as a float input's result does.
    EXPECT_EQ(file_type("out.png"), OIIO::TypeUInt8);
    EXPECT_EQ(read("out.png").spec().get_string_attribute("synth:colorspace"), "sRGB - Texture");
    // ramp= makes RGB.
    r = texsyn("--cascade:size=16x16:ramp=0,0,0,1,0.5,0.1 -o ramp.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read("ramp.exr").nchannels(), 3);
    // So does a preset's ramp; options after the preset override it.
    r = texsyn("--cascade:size=16x16:preset=cells:ramp=none -o preset.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read("preset.exr").nchannels(), 1);
}

// A generator names no sample: not in -v, not in the metadata or the description.
TEST_F(Cli, AGeneratorNamesNoSample)
{
    CliRun r = texsyn("-v --seed 1 --cascade:size=32x32 -o gen.tif");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("texsyn: --cascade preset=none:size=32x32:"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find(" from "), std::string::npos) << r.err;
    const OIIO::ImageSpec spec = read("gen.tif").spec();
    const std::string description = spec.get_string_attribute("ImageDescription");
    EXPECT_EQ(description.find("texsyn "), 0u) << description;
    EXPECT_NE(description.find(" seed 1, colorspace sRGB - Texture"), std::string::npos)
        << description;
    EXPECT_EQ(description.find("sample"), std::string::npos) << description;
    EXPECT_FALSE(spec.find_attribute("synth:sample"));
}

TEST_F(Cli, CascadeIsTheSameAtAnyThreadCount)
{
    write_control(dir / "ctrl.exr", 0.5f);
    const std::string command = "--cascade:size=64x48:levels=3:noise=0,0.3:kernel=aniso5:angle=30:"
                                "dmin=1:dmax=2:dilation=ctrl.exr:ramp=0,0,0,1,1,0.5,0.2,0.3,1";
    for (const char* threads : { "1", "2" })
        ASSERT_EQ(texsyn(std::string("--seed 7 --threads ") + threads + " " + command
                      + " -d float -o t" + threads + ".exr")
                      .status,
            0);
    EXPECT_EQ(pixel_hash(read("t1.exr")), pixel_hash(read("t2.exr")));
}

TEST_F(Cli, CascadeTransfersFromTheCurrentImageAtItsSize)
{
    CliRun r = texsyn("stucco.png --cascade:levels=2 -d float -o out.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf out = read("out.exr");
    EXPECT_EQ(out.spec().width, 128); // stucco_yellow.png's size
    EXPECT_EQ(out.spec().height, 128);
    EXPECT_EQ(out.nchannels(), 1);
    EXPECT_EQ(out.spec().get_string_attribute("synth:sample"), "stucco.png");
    // The start differs from noise: the result is not the generator's.
    ASSERT_EQ(texsyn("--cascade:size=128x128:levels=2 -d float -o noise.exr").status, 0);
    EXPECT_NE(pixel_hash(read("noise.exr")), pixel_hash(out));

    r = texsyn("stucco.png --cascade:size=40x24:transfer=channels -o small.exr -o small.png");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf small = read("small.exr");
    EXPECT_EQ(small.spec().width, 40);
    EXPECT_EQ(small.spec().height, 24);
    EXPECT_EQ(small.nchannels(), 3);
    // An 8-bit sample's result is written in its space, as the other commands do.
    EXPECT_EQ(read("small.png").spec().get_string_attribute("synth:colorspace"), "sRGB - Texture");
}

TEST_F(Cli, CascadeDilationOfOneEverywhereIsNoDilation)
{
    write_control(dir / "ctrl.exr", 0.0f);
    const std::string command = "--cascade:size=32x32:levels=2:kernel=gauss7";
    ASSERT_EQ(texsyn(command + ":dmin=1:dmax=4:dilation=ctrl.exr -d float -o a.exr").status, 0);
    ASSERT_EQ(texsyn(command + " -d float -o b.exr").status, 0);
    EXPECT_EQ(pixel_hash(read("a.exr")), pixel_hash(read("b.exr")));
    // The control image matters: at 1 the taps spread by dmax.
    write_control(dir / "ctrl.exr", 1.0f);
    ASSERT_EQ(texsyn(command + ":dmin=1:dmax=4:dilation=ctrl.exr -d float -o c.exr").status, 0);
    EXPECT_NE(pixel_hash(read("c.exr")), pixel_hash(read("b.exr")));
}

TEST_F(Cli, BadCascadeRequestsAreRefused)
{
    expect_failure("--cascade:map=henon -o out.exr",
        "texsyn ERROR: --cascade : map=henon : not one of logistic|sine|tent|cubic|curve");
    expect_failure(
        "--cascade:r=4.5 -o out.exr", "texsyn ERROR: --cascade : r=4.5 : out of range 0..4");
    expect_failure("--cascade:levels=2:iterations=1,2,3 -o out.exr",
        "texsyn ERROR: --cascade : iterations=1,2,3 : 3 values for levels=2 (give 1..2)");
    expect_failure("--cascade:kernel=custom:ksize=3:weights=1,2,1 -o out.exr",
        "texsyn ERROR: --cascade : weights=1,2,1 : kernel=custom with ksize=3 needs 9 weights "
        "(got 3)");
    expect_failure("--cascade:levels -o out.exr",
        "texsyn ERROR: --cascade : malformed option 'levels' (expected name=value)");
    expect_failure("--cascade:dilation=ctrl.exr -o out.exr",
        "texsyn ERROR: --cascade : dilation=ctrl.exr : no such file");
    expect_failure("--cascade:dilation=stucco.png:dilation=stucco.png -o out.exr",
        "texsyn ERROR: --cascade : dilation=stucco.png : given twice");
    // The library's checks of the control image, passed through.
    expect_failure("--cascade:size=16x16:dilation=stucco.png -o out.exr",
        "texsyn ERROR: --cascade : dilation=stucco.png : the control image has 3 channels; "
        "expected 1");
    // A failure after an -o that succeeded leaves nothing behind either.
    expect_failure("stucco.png -o first.exr --cascade:transfer=channels:ramp=0,0,0,1,1,1 "
                   "-o second.exr",
        "texsyn ERROR: --cascade : ramp=0,0,0,1,1,1 : colours one lattice; with "
        "transfer=channels there are 3");
    write_control(dir / "ctrl.exr", 0.0f);
    expect_failure("--cascade:dilation=ctrl.exr -o ctrl.exr",
        "texsyn ERROR: -o ctrl.exr : refusing to overwrite the input ctrl.exr",
        { "stucco.png", "ctrl.exr" });
}

// rotation= and palette= read their files: a rotation of 0 changes nothing; a palette
// colours the result with the palette image's colours (here one flat colour, read from an
// sRGB PNG like any input: 8-bit 128 is 0.2158 in scene-linear).
TEST_F(Cli, CascadeRotationAndPalette)
{
    write_control(dir / "zero.exr", 0.0f);
    OIIO::ImageBuf flat(OIIO::ImageSpec(8, 8, 3, OIIO::TypeUInt8));
    OIIO::ImageBufAlgo::fill(flat, { 128 / 255.0f, 128 / 255.0f, 128 / 255.0f });
    ASSERT_TRUE(flat.write((dir / "flat.png").string()));
    ASSERT_EQ(texsyn("--cascade:size=32x32:kernel=aniso5 -d float -o plain.exr").status, 0);
    CliRun r
        = texsyn("--cascade:size=32x32:kernel=aniso5:rotation=zero.exr -d float -o turned.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(pixel_hash(read("plain.exr")), pixel_hash(read("turned.exr")));
    r = texsyn("--cascade:size=32x32:palette=flat.png -o coloured.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    const OIIO::ImageBuf coloured = read("coloured.exr");
    ASSERT_EQ(coloured.nchannels(), 3);
    EXPECT_NEAR(coloured.getchannel(5, 5, 0, 0), 0.2158f, 2e-3);
    r = texsyn("--cascade:size=32x32:palette=missing.png -o x.exr");
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("palette=missing.png : no such file"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

// The shorthands: map=curve:x0,y0,…, kernel=w0,w1,… (ksize from their count) and
// ramp=FILE (a palette) give the same pixels as the spelled-out options.
TEST_F(Cli, CascadeShorthands)
{
    auto same = [&](const std::string& a, const std::string& b) {
        EXPECT_EQ(texsyn("--cascade:size=24x24:" + a + " -d float -o a.exr").status, 0) << a;
        EXPECT_EQ(texsyn("--cascade:size=24x24:" + b + " -d float -o b.exr").status, 0) << b;
        EXPECT_EQ(pixel_hash(read("a.exr")), pixel_hash(read("b.exr"))) << a;
    };
    same("map=curve:0,0,0.3,0.9,1,0.2", "map=curve:curve=0,0,0.3,0.9,1,0.2");
    same("kernel=1,2,1,2,4,2,1,2,1", "kernel=custom:ksize=3:weights=1,2,1,2,4,2,1,2,1");
    same("ramp=stucco.png", "palette=stucco.png");
}

// Options after a preset override it: palette= replaces the preset's ramp without
// ramp=none (issue #16), also through the recipe it writes, and scale= applies on top.
TEST_F(Cli, CascadePresetWithAPalette)
{
    OIIO::ImageBuf flat(OIIO::ImageSpec(8, 8, 3, OIIO::TypeUInt8));
    OIIO::ImageBufAlgo::fill(flat, { 128 / 255.0f, 128 / 255.0f, 128 / 255.0f });
    ASSERT_TRUE(flat.write((dir / "flat.png").string()));
    const std::string look = "--seed 2 --cascade:size=32x32:preset=blotches";
    CliRun r = texsyn(look + ":palette=flat.png -d float -o a.exr --recipe a.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(texsyn(look + ":ramp=none:palette=flat.png -d float -o b.exr").status, 0);
    EXPECT_EQ(pixel_hash(read("a.exr")), pixel_hash(read("b.exr")));
    EXPECT_NEAR(read("a.exr").getchannel(5, 5, 0, 0), 0.2158f, 2e-3);
    r = shell("oiiotool a.texsyn -d float -o again.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(pixel_hash(read("again.exr")), pixel_hash(read("a.exr")));
    r = texsyn("--seed 2 --cascade:size=32x32:preset=stone:palette=stucco.png:scale=2 -o c.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(read("c.exr").spec().get_string_attribute("synth:options").find(":scale=2:"),
        std::string::npos);
}
