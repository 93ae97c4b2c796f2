// SPDX-License-Identifier: Apache-2.0
// Colour tags of texsyn's outputs as texsyn and the stock OIIO tools read them back: every
// output type gives the same scene-linear statistics again; .tx outputs are real textures;
// -v says how each input was read and why; --colorspaces describes the config.
#include <texsyn/color.h>

#include <regex>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "cli_fixture.h"

namespace {

// Whether `text` contains `part`, for EXPECT_TRUE with a readable failure.
::testing::AssertionResult contains(const std::string& text, const std::string& part)
{
    if (text.find(part) != std::string::npos)
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "'" << part << "' not in:\n" << text;
}

} // namespace

// texsyn output -> texsyn input gives the scene-linear statistics of the float output of the
// same synthesis, for every output type, from a linear (half EXR) and an sRGB (PNG) sample.
// Before the tags, a linear 16-bit TIFF read back as sRGB: about 12 times too dark.
TEST_F(Cli, EveryOutputTypeReadsBackInItsColourSpace)
{
    ASSERT_EQ(texsyn("stucco.png -d half -o stucco_half.exr").status, 0);
    struct Output {
        std::string file, type;
        double tolerance; // of means and standard deviations, scene-linear
    };
    const std::vector<Output> outputs
        = { { "half.exr", "half", 1e-3 }, { "float.exr", "float", 1e-6 },
              { "u16.tif", "uint16", 2e-4 }, { "u16.png", "uint16", 2e-4 },
              { "u8.png", "uint8", 4e-3 }, { "u8.tif", "uint8", 4e-3 }, { "tex.tx", "", 4e-3 } };
    for (const std::string sample : { "stucco_half.exr", "stucco.png" }) {
        const std::string synthesis = sample + " --pyramid:size=64x64:iterations=1";
        CliRun r = texsyn(synthesis + " -d float -o reference.exr");
        ASSERT_EQ(r.status, 0) << r.err;
        const auto reference = OIIO::ImageBufAlgo::computePixelStats(read("reference.exr"));
        for (const Output& out : outputs) {
            const std::string what = sample + " -> " + out.file;
            r = texsyn(synthesis + (out.type.empty() ? "" : " -d " + out.type) + " -o " + out.file);
            ASSERT_EQ(r.status, 0) << what << ": " << r.err;
            r = texsyn(out.file + " -d float -o back.exr");
            ASSERT_EQ(r.status, 0) << what << ": " << r.err;
            const auto back = OIIO::ImageBufAlgo::computePixelStats(read("back.exr"));
            for (int c = 0; c < 3; ++c) {
                EXPECT_NEAR(back.avg[c], reference.avg[c], out.tolerance) << what << " " << c;
                EXPECT_NEAR(back.stddev[c], reference.stddev[c], out.tolerance) << what << " " << c;
            }
            fs::remove(dir / out.file);
            fs::remove(dir / "back.exr");
        }
    }
}

// What the stock OIIO tools see: OpenEXR chromaticities of the output space, the colour
// space name where the format keeps one (PNG), sRGB flagged where TIFF can say it.
TEST_F(Cli, OutputsAreTaggedForOiioTools)
{
    const std::string synthesis = "stucco.png --pyramid:size=32x32:iterations=1";
    ASSERT_EQ(texsyn(synthesis + " -o lin.exr").status, 0);
    ASSERT_EQ(texsyn(synthesis + " --tocolorspace ACEScg -o cg.exr").status, 0);
    ASSERT_EQ(texsyn(synthesis + " -o srgb.png").status, 0);
    ASSERT_EQ(texsyn(synthesis + " -o srgb.tif").status, 0);
    auto spec = [&](const std::string& name) {
        auto in = OIIO::ImageInput::open((dir / name).string());
        EXPECT_TRUE(in) << name;
        return in ? in->spec() : OIIO::ImageSpec();
    };
    const OIIO::TypeDesc xy_type(OIIO::TypeDesc::FLOAT, 8);
    float xy[8];
    ASSERT_TRUE(spec("lin.exr").getattribute("chromaticities", xy_type, xy));
    const float rec709[8] = { 0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f };
    for (int i = 0; i < 8; ++i)
        EXPECT_NEAR(xy[i], rec709[i], 1e-4f) << i;
    ASSERT_TRUE(spec("cg.exr").getattribute("chromaticities", xy_type, xy));
    EXPECT_NEAR(xy[0], 0.713f, 2e-3f); // AP1 red, adapted to D65 as the config adapts it
    EXPECT_NEAR(xy[6], 0.3127f, 1e-4f);
    EXPECT_EQ(spec("cg.exr").get_string_attribute("synth:colorspace"), "ACEScg");
    EXPECT_EQ(spec("srgb.png").get_string_attribute("oiio:ColorSpace"), "sRGB - Texture");
    EXPECT_EQ(spec("srgb.tif").get_string_attribute("oiio:ColorSpace"), "sRGB");
    EXPECT_TRUE(contains(
        spec("srgb.tif").get_string_attribute("ImageDescription"), ", colorspace sRGB - Texture"));
}

// A .tx output is a texture for renderers, made by OIIO's texture maker: tiled, MIP-mapped,
// wrapping periodically where the synthesis tiles.
TEST_F(Cli, TxOutputsAreTiledMipmappedTextures)
{
    CliRun r = texsyn("stucco.png --pyramid:size=128x128:iterations=1 -o tile.tx");
    ASSERT_EQ(r.status, 0) << r.err;
    r = shell("iinfo -v tile.tx");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(contains(r.out, "128 x  128, 3 channel, uint8 tiff"));
    EXPECT_TRUE(contains(r.out, "MIP-map levels: 128x128 64x64 32x32 16x16 8x8 4x4 2x2 1x1"));
    EXPECT_TRUE(contains(r.out, "tile size: 64 x 64"));
    EXPECT_TRUE(contains(r.out, "wrapmodes: \"periodic,periodic\""));
    EXPECT_TRUE(contains(r.out, "textureformat: \"Plain Texture\""));
    EXPECT_TRUE(contains(r.out, "Exif:ColorSpace: 1")); // sRGB, as the input was
    // A transfer keeps its image's borders: no periodic wrap claimed.
    r = texsyn("stucco.png stucco.png --transfer -o transfer.tx");
    ASSERT_EQ(r.status, 0) << r.err;
    r = shell("iinfo -v transfer.tx");
    EXPECT_TRUE(contains(r.out, "wrapmodes: \"black,black\""));
}

TEST_F(Cli, VerboseSaysHowEachInputWasRead)
{
    CliRun r = texsyn("-v stucco.png --pyramid:iterations=1 -o a.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "texsyn: stucco.png read as 'sRGB - Texture': "));
    EXPECT_TRUE(std::regex_search(r.err,
        std::regex("texsyn: --pyramid size=[0-9]+x[0-9]+: stucco.png's size \\(size=WxH sets "
                   "another\\)")))
        << r.err;
    r = texsyn("-v a.exr --pyramid:size=32x32:iterations=1 -o b.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(contains(r.err,
        "texsyn: a.exr read as 'Linear Rec.709 (sRGB)': its "
        "synth:colorspace tag"));
    EXPECT_FALSE(contains(r.err, "WARNING"));
    EXPECT_FALSE(contains(r.err, "'s size")) << "size= was given";

    // An OpenEXR file as any OIIO tool writes it: OIIO reads it back tagged "Linear".
    OIIO::ImageBuf plain = read("a.exr");
    plain.specmod().erase_attribute("synth:colorspace");
    plain.specmod().erase_attribute("ImageDescription");
    ASSERT_TRUE(plain.write((dir / "plain.exr").string()));
    r = texsyn("-v plain.exr --pyramid:size=32x32:iterations=1 -o c.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(contains(r.err,
        "texsyn: plain.exr read as 'Linear Rec.709 (sRGB)': its "
        "oiio:ColorSpace tag 'Linear'\n"
        "texsyn WARNING: plain.exr: the tag 'Linear' is a generic name"));
    r = texsyn("-v --iscolorspace ACEScg plain.exr --pyramid:size=32x32:iterations=1 -o d.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(contains(r.err, "texsyn: plain.exr read as 'ACEScg': as asked (--iscolorspace)"));
    EXPECT_FALSE(contains(r.err, "WARNING"));
    // Without -v, nothing: pipelines stay quiet.
    r = texsyn("plain.exr --pyramid:size=32x32:iterations=1 -o e.exr");
    EXPECT_EQ(r.err, "");
}

TEST_F(Cli, ColorspacesDescribesTheConfig)
{
    CliRun r = texsyn("--colorspaces");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out.rfind("Colour config texsyn://bundled (default)\nColour spaces:\n", 0), 0u)
        << r.out;
    EXPECT_TRUE(contains(r.out,
        "  ACEScg (aliases: aces_cg, lin_ap1) — family Scene-linear, "
        "encoding scene-linear\n"));
    EXPECT_TRUE(contains(r.out,
        "  Raw (aliases: raw_data) — family Data, encoding data, data: "
        "never converted\n"));
    EXPECT_TRUE(contains(r.out, "Roles:\n"));
    EXPECT_TRUE(contains(r.out, "  scene_linear: Linear Rec.709 (sRGB)\n"));

    // The config the run would use: --colorconfig (before or after), else $OCIO.
    std::string text = slurp(TEXSYN_BUNDLED_OCIO_CONFIG);
    text.replace(text.find("scene_linear: Linear Rec.709 (sRGB)"),
        std::string("scene_linear: Linear Rec.709 (sRGB)").size(), "scene_linear: ACEScg");
    spit(dir / "cg.ocio", text);
    r = texsyn("--colorspaces --colorconfig cg.ocio");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.rfind("Colour config cg.ocio (--colorconfig)\n", 0), 0u) << r.out;
    EXPECT_TRUE(contains(r.out, "  scene_linear: ACEScg\n"));
    r = texsyn("--colorspaces", "OCIO=cg.ocio");
    EXPECT_EQ(r.out.rfind("Colour config cg.ocio ($OCIO)\n", 0), 0u) << r.out;
}

TEST_F(Cli, UnknownColourSpacesListTheKnownOnes)
{
    expect_failure("stucco.png --iscolorspace acescg_ --pyramid -o out.exr",
        "texsyn ERROR: --iscolorspace : unknown colour space 'acescg_', did you mean 'ACEScg'? "
        "(known: Linear Rec.709 (sRGB), sRGB - Texture, ACEScg, Raw, CIE-XYZ-D65; texsyn "
        "--colorspaces describes them)");
}
