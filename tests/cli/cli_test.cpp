// SPDX-License-Identifier: Apache-2.0
// End-to-end runs of the built `texsyn` tool: good runs, colour policy, outputs, and every
// bad-input case (exit code, first stderr line, no output written, input unchanged).
#include <texsyn/color.h>
#include <texsyn/io.h>
#include <texsyn/methods.h>
#include <texsyn/recipe.h>
#include <texsyn/version.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <sys/stat.h>
#include <sys/wait.h>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "cli_fixture.h"

TEST_F(Cli, SynthesizesAnExrWithMetadata)
{
    CliRun r = texsyn("stucco.png --pyramid:size=96x64:iterations=1 -o out.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, ""); // quiet in pipelines
    OIIO::ImageBuf out = read("out.exr");
    EXPECT_EQ(out.spec().width, 96);
    EXPECT_EQ(out.spec().height, 64);
    EXPECT_EQ(out.nchannels(), 3);
    const OIIO::ImageSpec& s = out.spec();
    EXPECT_EQ(s.get_string_attribute("synth:method"), "pyramid");
    EXPECT_EQ(s.get_string_attribute("synth:sample"), "stucco.png");
    EXPECT_EQ(s.get_string_attribute("synth:colorspace"), "Linear Rec.709 (sRGB)");
    EXPECT_EQ(s.get_int_attribute("synth:seed"), 0);
    EXPECT_NE(s.get_string_attribute("synth:version"), "");
    EXPECT_EQ(s.get_string_attribute("synth:options").find("size=96x64:iterations=1:"), 0u);
    EXPECT_EQ(file_type("out.exr"), OIIO::TypeHalf);
}

TEST_F(Cli, StatisticsAreTakenInSceneLinear)
{
    CliRun r = texsyn("stucco.png --pyramid:size=128x128:iterations=2 -d float -o out.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageBuf file = read("stucco.png");
    PlanarImage lin;
    std::string error;
    ASSERT_TRUE(planes_from_imagebuf(file, lin, error));
    PlanarImage encoded = lin;
    auto cc = ColorConfig::load(TEXSYN_BUNDLED_OCIO_CONFIG, error);
    ASSERT_TRUE(cc->convert(lin, "sRGB - Texture", cc->scene_linear(), error)) << error;
    auto out = OIIO::ImageBufAlgo::computePixelStats(read("out.exr"));
    for (int c = 0; c < 3; ++c) {
        double lin_mean = 0.0, enc_mean = 0.0;
        for (size_t i = 0; i < lin.channels[c].size(); ++i) {
            lin_mean += lin.channels[c].data()[i];
            enc_mean += encoded.channels[c].data()[i];
        }
        lin_mean /= double(lin.channels[c].size());
        enc_mean /= double(lin.channels[c].size());
        // Exact histogram matching gives the sample's linear mean up to quantile spacing.
        EXPECT_NEAR(out.avg[c], lin_mean, 2e-3) << c;
        // ... and not the mean of the encoded values, which differs by far more.
        EXPECT_GT(std::abs(out.avg[c] - enc_mean), 0.05) << c;
    }
}

TEST_F(Cli, IntegerOutputsAreInTheInputsSpace)
{
    CliRun r = texsyn("stucco.png --pyramid:size=128x128:iterations=2 -o out.png");
    ASSERT_EQ(r.status, 0) << r.err;
    auto in = OIIO::ImageBufAlgo::computePixelStats(read("stucco.png"));
    auto out = OIIO::ImageBufAlgo::computePixelStats(read("out.png"));
    for (int c = 0; c < 3; ++c) // 8-bit quantisation and rounding: within 2 code values
        EXPECT_NEAR(out.avg[c], in.avg[c], 2.0 / 255.0) << c;
    EXPECT_EQ(file_type("out.png"), OIIO::TypeUInt8);
}

TEST_F(Cli, ColourSpaceOptionsBehaveAsInOiiotool)
{
    ASSERT_EQ(texsyn("stucco.png --pyramid:size=64x64:iterations=1 -d float -o lin.exr").status, 0);
    CliRun r = texsyn("stucco.png --pyramid:size=64x64:iterations=1 --tocolorspace ACEScg "
                      "-d float -o cg.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read("cg.exr").spec().get_string_attribute("synth:colorspace"), "ACEScg");
    // ACEScg of a linear Rec.709 pixel: the Bradford-adapted Rec.709 -> AP1 matrix.
    OIIO::ImageBuf lin = read("lin.exr"), cg = read("cg.exr");
    float a[3], b[3];
    lin.getpixel(10, 20, a);
    cg.getpixel(10, 20, b);
    EXPECT_NEAR(b[0], 0.6130974f * a[0] + 0.3395231f * a[1] + 0.0473795f * a[2], 1e-4f);

    // Declaring the PNG as Raw data skips the sRGB decode: the output mean is the encoded one.
    r = texsyn(
        "stucco.png --iscolorspace Raw --pyramid:size=64x64:iterations=1 -d float -o raw.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    auto raw = OIIO::ImageBufAlgo::computePixelStats(read("raw.exr"));
    auto png = OIIO::ImageBufAlgo::computePixelStats(read("stucco.png"));
    EXPECT_NEAR(raw.avg[1], png.avg[1], 3e-3);
    // --iscolorspace before the input applies to the next input.
    r = texsyn(
        "--iscolorspace Raw stucco.png --pyramid:size=64x64:iterations=1 -d float -o raw2.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(OIIO::ImageBufAlgo::computePixelHashSHA1(read("raw.exr")),
        OIIO::ImageBufAlgo::computePixelHashSHA1(read("raw2.exr")));
}

TEST_F(Cli, OcioEnvironmentAndColorconfigAreHonoured)
{
    fs::copy_file(TEXSYN_BUNDLED_OCIO_CONFIG, dir / "my.ocio");
    std::string base = "stucco.png --pyramid:size=64x64:iterations=1 -o ";
    ASSERT_EQ(texsyn(base + "a.exr", "OCIO=my.ocio").status, 0);
    ASSERT_EQ(texsyn("--colorconfig my.ocio " + base + "b.exr").status, 0);
    CliRun r = texsyn(base + "c.exr", "OCIO=missing.ocio");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.first_err_line().find("texsyn ERROR: colour config 'missing.ocio'"), 0u) << r.err;
    r = texsyn("--colorconfig stucco.png " + base + "d.exr");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.first_err_line().find("texsyn ERROR: colour config 'stucco.png'"), 0u) << r.err;
    EXPECT_FALSE(fs::exists(dir / "c.exr") || fs::exists(dir / "d.exr"));
}

TEST_F(Cli, SameSeedSameBitsAtAnyThreadCount)
{
    ASSERT_EQ(
        texsyn(
            "--threads 1 --seed 4 stucco.png --pyramid:size=80x80:iterations=2 -d float -o a.exr")
            .status,
        0);
    ASSERT_EQ(
        texsyn(
            "--threads 2 --seed 4 stucco.png --pyramid:size=80x80:iterations=2 -d float -o b.exr")
            .status,
        0);
    ASSERT_EQ(
        texsyn(
            "--threads 2 --seed 5 stucco.png --pyramid:size=80x80:iterations=2 -d float -o c.exr")
            .status,
        0);
    auto hash = [&](const char* f) { return OIIO::ImageBufAlgo::computePixelHashSHA1(read(f)); };
    EXPECT_EQ(hash("a.exr"), hash("b.exr"));
    EXPECT_NE(hash("a.exr"), hash("c.exr"));
    EXPECT_EQ(read("c.exr").spec().get_int_attribute("synth:seed"), 5);
}

TEST_F(Cli, SubbandsEXRCanBeTakenApartWithStockOiiotool)
{
    CliRun r = texsyn("--subbands stucco.png --pyramid:size=128x96:iterations=1 -o bands.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    std::string cmd = "cd " + quote(dir.string())
        + " && oiiotool bands.exr --subimage synth.s2.o1 --fullpixels -o band.exr"
          " && oiiotool bands.exr --subimage sample.lowpass --fullpixels -o low.exr";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    OIIO::ImageBuf band = read("band.exr");
    EXPECT_EQ(band.spec().width, 32); // scale 2 of a 128-wide synthesis
    EXPECT_EQ(band.spec().height, 24);
    EXPECT_EQ(band.spec().channelnames, (std::vector<std::string> { "pc0", "pc1", "pc2" }));
    // 3 scales: the most that keeps the 96-pixel side of the output >= 8 pixels.
    EXPECT_EQ(read("low.exr").spec().width, 16);
    OIIO::ImageBuf synth((dir / "bands.exr").string());
    EXPECT_EQ(synth.spec().get_string_attribute("oiio:subimagename"), "synth");
    EXPECT_EQ(synth.nsubimages(), 1 + 2 * (1 + 3 * 4 + 1));
}

TEST_F(Cli, AllChannelCountsAndPixelTypesWork)
{
    const OIIO::TypeDesc types[]
        = { OIIO::TypeUInt8, OIIO::TypeUInt16, OIIO::TypeHalf, OIIO::TypeFloat };
    for (int nc = 1; nc <= 4; ++nc)
        for (OIIO::TypeDesc t : types) {
            std::string ext = (t == OIIO::TypeHalf || t == OIIO::TypeFloat) ? ".exr" : ".tif";
            std::string in = "in" + std::to_string(nc) + t.c_str() + ext;
            std::string out = "out" + std::to_string(nc) + t.c_str() + ".exr";
            write_sample(in, nc, t);
            CliRun r = texsyn(in + " --pyramid:size=40x40:iterations=1 -o " + out);
            ASSERT_EQ(r.status, 0) << in << ": " << r.err;
            EXPECT_EQ(read(out).nchannels(), nc) << in;
        }
}

TEST_F(Cli, HelpVersionAndMethodList)
{
    CliRun r = texsyn("--help");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("--pyramid"), std::string::npos);
    EXPECT_NE(r.out.find("orientations"), std::string::npos);
    EXPECT_NE(r.out.find("--check"), std::string::npos);
    EXPECT_NE(r.out.find("--choosy"), std::string::npos);
    EXPECT_NE(r.out.find("penalty"), std::string::npos);
    r = texsyn("--version");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, std::string("texsyn ") + TEXSYN_VERSION_STRING + "\n"); // Apache-2.0 build
    r = texsyn("--list-methods");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out.find("pyramid"), 0u);
    EXPECT_NE(r.out.find("\nchoosy "), std::string::npos);
}

TEST_F(Cli, VerboseReportsTheRun)
{
    CliRun r = texsyn("-v stucco.png --pyramid:size=32x32:iterations=1 -o out.exr");
    ASSERT_EQ(r.status, 0);
    EXPECT_NE(r.err.find("texsyn: --pyramid size=32x32"), std::string::npos) << r.err;
}

TEST_F(Cli, BadFilesAreRefused)
{
    expect_failure("missing.png --pyramid -o out.exr", "texsyn ERROR: missing.png: no such file");
    std::ofstream(dir / "notes.png") << "this is not a PNG file\n";
    expect_failure("notes.png --pyramid -o out.exr",
        "texsyn ERROR: notes.png: cannot read image (Not a PNG file)",
        { "stucco.png", "notes.png" });
    std::string png = slurp(dir / "stucco.png");
    std::ofstream(dir / "cut.png", std::ios::binary)
        .write(png.data(), std::streamsize(png.size() / 3));
    CliRun r = texsyn("cut.png --pyramid -o out.exr");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.first_err_line().find("texsyn ERROR: cut.png: cannot read image"), 0u) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.exr"));
    fs::create_directory(dir / "folder");
    expect_failure("folder --pyramid -o out.exr",
        "texsyn ERROR: folder: is a directory, not an image",
        { "stucco.png", "folder", "cut.png", "notes.png" });
    // FIFOs and devices are refused before any library reads them (reading would block, or
    // never end).
    ASSERT_EQ(::mkfifo((dir / "pipe.png").c_str(), 0600), 0);
    const auto inputs = { std::string("stucco.png"), std::string("folder"), std::string("cut.png"),
        std::string("notes.png"), std::string("pipe.png") };
    expect_failure("pipe.png --pyramid -o out.exr",
        "texsyn ERROR: pipe.png: is not a regular file (a FIFO, device or socket), not an image",
        inputs);
    expect_failure("/dev/zero --pyramid -o out.exr",
        "texsyn ERROR: /dev/zero: is not a regular file (a FIFO, device or socket), not an "
        "image",
        inputs);
    expect_failure("--colorconfig pipe.png stucco.png --pyramid -o out.exr",
        "texsyn ERROR: colour config 'pipe.png': is not a regular file (a FIFO, device or "
        "socket), not an OCIO config",
        inputs);
}

// What the tool prints must reach stdout: a full disk is an error, not a success.
TEST_F(Cli, AFullStdoutIsAnError)
{
    for (const std::string args : { "--help", "--list-methods", "stucco.png --check" }) {
        const std::string cmd = "cd " + quote(dir.string()) + " && " + quote(TEXSYN_EXE) + " "
            + args + " > /dev/full 2> err.txt";
        const int rc = std::system(cmd.c_str());
        EXPECT_EQ(WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, 1) << args;
        EXPECT_EQ(slurp(dir / "err.txt").find("texsyn ERROR: standard output: write error"), 0u)
            << args;
    }
}

// An output name as long as a file name may be (255 bytes) is written: the temporary name
// beside it stays within that limit too.
TEST_F(Cli, LongOutputNamesAreWritten)
{
    const std::string name = std::string(250, 'n') + ".exr";
    CliRun r = texsyn("stucco.png --pyramid:size=16x16:iterations=1 -o " + name);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / name));
    EXPECT_EQ(outputs().size(), 1u); // no temporary left beside it
}

TEST_F(Cli, NonFinitePixelsAreRefused)
{
    write_sample("nan.exr", 3, OIIO::TypeFloat, std::nanf(""));
    write_sample("inf.exr", 3, OIIO::TypeHalf, INFINITY);
    expect_failure("nan.exr --pyramid -o out.exr",
        "texsyn ERROR: nan.exr: pixel (3, 4) channel R is NaN; texsyn needs finite "
        "pixel values",
        { "stucco.png", "nan.exr", "inf.exr" });
    expect_failure("inf.exr --pyramid -o out.exr",
        "texsyn ERROR: inf.exr: pixel (3, 4) channel R is infinite; texsyn needs "
        "finite pixel values",
        { "stucco.png", "nan.exr", "inf.exr" });
}

TEST_F(Cli, MalformedCommandsAndOptionsAreRefused)
{
    expect_failure("stucco.png --frobnicate -o out.exr",
        "texsyn ERROR: unknown command or option '--frobnicate' (see texsyn --help)");
    expect_failure("stucco.png --pyramid:levels=3 -o out.exr",
        "texsyn ERROR: --pyramid : levels=3 : unknown option (known: size, iterations, "
        "pyramid, scales, orientations, histogram, fft, gain, balance, flatten)");
    expect_failure("stucco.png --pyramid:size=abc -o out.exr",
        "texsyn ERROR: --pyramid : size=abc : not a size (expected WxH, e.g. 1024x1024)");
    expect_failure("stucco.png --pyramid:size=0x10 -o out.exr",
        "texsyn ERROR: --pyramid : size=0x10 : out of range 1..1048576 (each side)");
    expect_failure("stucco.png --pyramid:iterations=-1 -o out.exr",
        "texsyn ERROR: --pyramid : iterations=-1 : out of range 0..100");
    expect_failure("stucco.png --pyramid:orientations=99 -o out.exr",
        "texsyn ERROR: --pyramid : orientations=99 : out of range 1..8");
    expect_failure("stucco.png --pyramid:iterations -o out.exr",
        "texsyn ERROR: --pyramid : malformed option 'iterations' (expected name=value)");
    expect_failure(
        "--seed abc stucco.png --pyramid -o out.exr", "texsyn ERROR: --seed=abc : not an integer");
    expect_failure("--threads -2 stucco.png --pyramid -o out.exr",
        "texsyn ERROR: --threads=-2 : out of range 0..1024");
    expect_failure("-d int7 stucco.png --pyramid -o out.exr",
        "texsyn ERROR: -d : unknown data format 'int7' (use uint8, uint16, half or float)");
    expect_failure("stucco.png --pyramid -o", "texsyn ERROR: -o : missing argument");
    expect_failure(
        "stucco.png --pyramid", "texsyn ERROR: nothing to do: no -o FILE (see texsyn --help)");
    expect_failure("--pyramid -o out.exr",
        "texsyn ERROR: --pyramid : no current image (give an input file before it)");
    expect_failure("stucco.png --tocolorspace Nope --pyramid -o out.exr",
        "texsyn ERROR: --tocolorspace : unknown colour space 'Nope' (known: Linear Rec.709 "
        "(sRGB), sRGB - Texture, ACEScg, Raw, CIE-XYZ-D65; texsyn --colorspaces describes them)");
}

// Every command of the method registry reports an option out of its range the same way,
// through the same path: "--NAME : option=value : out of range lo..hi".
TEST_F(Cli, EveryCommandReportsARangeErrorTheSameWay)
{
    int commands = 0;
    for (const texsyn::Method* m : texsyn::methods()) {
        const texsyn::MethodOptions defaults = m->defaults();
        const texsyn::OptionField* f = nullptr;
        for (const texsyn::OptionField& field : defaults.table().fields())
            if (!f
                && (field.type == texsyn::OptionType::Integer
                    || field.type == texsyn::OptionType::Real))
                f = &field;
        if (!f) // e.g. --check takes no options, --material files, names and lists
            continue;
        const bool two = m->inputs == texsyn::MethodInputs::ImageAndSample
            || m->inputs == texsyn::MethodInputs::Samples;
        const bool none = m->inputs == texsyn::MethodInputs::None
            || m->inputs == texsyn::MethodInputs::OptionalImage;
        const std::string inputs = none ? "" : two ? "stucco.png stucco.png " : "stucco.png ";
        const std::string out = m->output == texsyn::MethodOutput::Volume ? "out.vdb"
            : m->output == texsyn::MethodOutput::Analysis                 ? "out.tsa"
                                                                          : "out.exr";
        const bool integer = f->type == texsyn::OptionType::Integer;
        auto number = [&](double x) {
            return integer ? std::to_string(int64_t(x)) : texsyn::format_number_list({ float(x) });
        };
        const std::string value = number(f->hi + 1.0);
        expect_failure(inputs + "--" + m->name + ":" + f->name + "=" + value + " -o " + out,
            "texsyn ERROR: --" + m->name + " : " + f->name + "=" + value + " : out of range "
                + number(f->lo) + ".." + number(f->hi));
        ++commands;
    }
    // Every row with a number option: all but --check and --material when this was written
    // (a new row without one is left out, not miscounted).
    EXPECT_GE(commands, 12);
}

TEST_F(Cli, ImpossibleSizesAreRefusedBeforeAllocating)
{
    expect_failure_starting("stucco.png --pyramid:size=200000x200000 -o out.exr",
        "texsyn ERROR: --pyramid : size=200000x200000 would need about ");
    write_sample("tiny.exr", 3, OIIO::TypeFloat);
    expect_failure("tiny.exr --pyramid:scales=4 -o out.exr",
        "texsyn ERROR: --pyramid : scales=4 is too many for a 32x32 sample (at most 2)",
        { "stucco.png", "tiny.exr" });
}

TEST_F(Cli, OutputsAreCheckedBeforeAnyWork)
{
    expect_failure("stucco.png --pyramid -o stucco.png",
        "texsyn ERROR: -o stucco.png : refusing to overwrite the input stucco.png");
    expect_failure("stucco.png --pyramid -o ./stucco.png",
        "texsyn ERROR: -o ./stucco.png : refusing to overwrite the input stucco.png");
    expect_failure("stucco.png --pyramid -o no/such/dir/out.exr",
        "texsyn ERROR: -o no/such/dir/out.exr : directory no/such/dir does not exist");
    expect_failure("stucco.png --pyramid -o out.unknownext",
        "texsyn ERROR: -o out.unknownext : no image format writes '.unknownext' files");
    expect_failure("--subbands stucco.png --pyramid:size=32x32:iterations=1 -o out.png",
        "texsyn ERROR: -o out.png : --subbands writes a multi-part OpenEXR; name the "
        "output *.exr");
}

TEST_F(Cli, ColourUnderZeroOrPartialAlphaSurvives)
{
    // 8-bit PNG colour is stored un-associated: it must not be lost where alpha is 0, nor
    // rounded down where alpha is 0.5.
    for (float alpha : { 0.0f, 0.5f }) {
        std::string in = "alpha" + std::to_string(int(alpha * 10)) + ".png";
        OIIO::ImageBuf rgba = OIIO::ImageBufAlgo::channels(read("stucco.png"), 4, { 0, 1, 2, -1 },
            { 0.0f, 0.0f, 0.0f, alpha }, { "R", "G", "B", "A" });
        rgba.specmod().alpha_channel = 3;
        rgba.specmod().attribute("oiio:UnassociatedAlpha", 1); // store the colour as is
        ASSERT_TRUE(rgba.write((dir / in).string(), OIIO::TypeUInt8)) << rgba.geterror();
        CliRun r = texsyn(in + " --pyramid:size=128x128:iterations=2 -o out.png");
        ASSERT_EQ(r.status, 0) << r.err;
        // read_image() asks for un-associated colour, as stored in the PNG.
        OIIO::ImageBuf sample = read("stucco.png");
        OIIO::ImageBuf out = read("out.png");
        auto s = OIIO::ImageBufAlgo::computePixelStats(sample);
        auto o = OIIO::ImageBufAlgo::computePixelStats(out);
        ASSERT_EQ(out.nchannels(), 4);
        for (int c = 0; c < 3; ++c) // histogram matched: same mean within a code value
            EXPECT_NEAR(o.avg[c], s.avg[c], 1.0 / 255.0) << "alpha " << alpha << " channel " << c;
        EXPECT_NEAR(o.avg[3], alpha, 1.0 / 255.0);
    }
}

TEST_F(Cli, ChannelsAfterAlphaAreNeitherAssociatedNorColourConverted)
{
    OIIO::ImageSpec spec(32, 32, 5, OIIO::TypeFloat);
    spec.channelnames = { "R", "G", "B", "A", "Z" };
    spec.alpha_channel = 3;
    spec.z_channel = 4;
    OIIO::ImageBuf buf(spec);
    OIIO::ImageBufAlgo::noise(buf, "uniform", 0.1f, 0.9f, false, 5);
    OIIO::ImageBufAlgo::fill(
        buf, { 0.0f, 0.0f, 0.0f, 0.5f, 3.0f }, OIIO::ROI(0, 32, 0, 32, 0, 1, 3, 5));
    ASSERT_TRUE(buf.write((dir / "rgbaz.exr").string()));
    CliRun r = texsyn("rgbaz.exr --pyramid:size=48x48:iterations=1 --tocolorspace sRGB -o out.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    auto o = OIIO::ImageBufAlgo::computePixelStats(read("out.exr"));
    EXPECT_NEAR(o.min[3], 0.5, 1e-3); // half precision
    EXPECT_NEAR(o.max[4], 3.0, 1e-3);
    EXPECT_NEAR(o.min[4], 3.0, 1e-3);
}

TEST_F(Cli, PixelTypesFollowTheInputAndTheFormat)
{
    std::string cmd = "cd " + quote(dir.string()) + " && oiiotool stucco.png -d uint16 -o s16.png";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    ASSERT_EQ(texsyn("s16.png --pyramid:size=32x32:iterations=1 -o o16.png").status, 0);
    EXPECT_EQ(file_type("o16.png"), OIIO::TypeUInt16);
    ASSERT_EQ(texsyn("s16.png --pyramid:size=32x32:iterations=1 -o o16.tif").status, 0);
    EXPECT_EQ(file_type("o16.tif"), OIIO::TypeUInt16);
    // The description carries the recipe where a format drops unknown attributes.
    EXPECT_NE(read("o16.tif")
                  .spec()
                  .get_string_attribute("ImageDescription")
                  .find("--pyramid:size=32x32"),
        std::string::npos);
    expect_failure("-d float stucco.png --pyramid -o x.jpg",
        "texsyn ERROR: -d float : .jpg files hold uint8",
        { "stucco.png", "s16.png", "o16.png", "o16.tif" });
    expect_failure("-d uint8 stucco.png --pyramid -o x.exr",
        "texsyn ERROR: -d uint8 : .exr files hold half, float",
        { "stucco.png", "s16.png", "o16.png", "o16.tif" });
}

TEST_F(Cli, AFailedRunLeavesNoOutputAtAll)
{
    // The first -o succeeds before the second input fails: nothing may be left.
    expect_failure("stucco.png --pyramid:size=32x32:iterations=1 -o a.png missing.png "
                   "--pyramid -o b.png",
        "texsyn ERROR: missing.png: no such file");
    expect_failure("stucco.png --pyramid:size=32x32:iterations=1 -o a.png --iscolorspace Raw",
        "texsyn ERROR: --iscolorspace : has no effect, nothing is written after it (add -o FILE)");
    expect_failure("stucco.png --pyramid:size=32x32:iterations=1 -o a.png stucco.png "
                   "--pyramid:bogus=1 -o b.png",
        "texsyn ERROR: --pyramid : bogus=1 : unknown option (known: size, iterations, "
        "pyramid, scales, orientations, histogram, fft, gain, balance, flatten)");
    expect_failure("stucco.png --pyramid:size=32x32:size=64x64 -o a.png",
        "texsyn ERROR: --pyramid : size=64x64 : given twice");
    fs::create_directory(dir / "taken.png");
    expect_failure("stucco.png --pyramid -o taken.png",
        "texsyn ERROR: -o taken.png : is a directory", { "stucco.png", "taken.png" });
}

TEST_F(Cli, SmallOutputsUseFewerScales)
{
    CliRun r = texsyn("stucco.png --pyramid:size=16x16 -o small.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(read("small.exr").spec().get_string_attribute("synth:options").find(":scales=1:"),
        std::string::npos);
}

// Farm logs (issue #16): with -v and stderr not a terminal, plain progress lines with the
// elapsed time and an estimate come every $TEXSYN_PROGRESS_INTERVAL seconds (here 0.05 s,
// on a run of 0.3 s or more) and once at 100%, before the timing line; no live line
// ('\r'). Without -v a pipeline stays quiet.
TEST_F(Cli, VerboseOutputIntoAFileHasProgressLines)
{
    const std::string run = "--cascade:size=1024x1024:iterations=40 -o out.exr";
    CliRun r = texsyn("-v " + run, "TEXSYN_PROGRESS_INTERVAL=0.05");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.find('\r'), std::string::npos);
    const std::regex progress(R"(texsyn: --cascade +(\d+)% elapsed \d+:\d\d eta \d+:\d\d)");
    std::vector<int> percents;
    std::istringstream lines(r.err);
    std::string timing;
    for (std::string line; std::getline(lines, line);) {
        std::smatch m;
        if (std::regex_match(line, m, progress))
            percents.push_back(std::stoi(m[1]));
        else
            timing = line;
    }
    ASSERT_GE(percents.size(), 2u) << r.err;
    EXPECT_LT(percents.front(), 100) << r.err;
    EXPECT_EQ(percents.back(), 100) << r.err;
    EXPECT_EQ(std::count(percents.begin(), percents.end(), 100), 1) << r.err;
    EXPECT_EQ(timing.find("texsyn: --cascade preset=none:size=1024x1024:"), 0u) << r.err;
    r = texsyn(run, "TEXSYN_PROGRESS_INTERVAL=0.05");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    r = texsyn("-v --cascade:size=16x16 -o bad.exr", "TEXSYN_PROGRESS_INTERVAL=soon");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.first_err_line(),
        "texsyn ERROR: TEXSYN_PROGRESS_INTERVAL=soon : expected seconds between progress lines, "
        "0.01..3600");
    EXPECT_FALSE(fs::exists(dir / "bad.exr"));
}

// A synthesis of a synthesis names what it was made from, not the file at the start.
TEST_F(Cli, ChainedSynthesesNameTheirRealSample)
{
    CliRun r = texsyn("-v stucco.png --pyramid:size=64x64:iterations=1 "
                      "--pyramid:size=32x32:iterations=1 -d float -o out.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read("out.exr").spec().get_string_attribute("synth:sample"),
        "pyramid synthesis of stucco.png");
    EXPECT_NE(r.err.find(" from stucco.png in "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(" from pyramid synthesis of stucco.png in "), std::string::npos) << r.err;
}

TEST_F(Cli, RecipesAreWrittenForSynthesesOfFiles)
{
    CliRun r = texsyn("--seed 3 stucco.png --pyramid:size=40x30:iterations=1 --recipe r.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    texsyn::Recipe recipe;
    std::string error;
    ASSERT_TRUE(texsyn::recipe_from_filename((dir / "r.texsyn").string(), recipe, error)) << error;
    EXPECT_EQ(recipe.samples, (std::vector<std::string> { (dir / "stucco.png").string() }));
    EXPECT_EQ(recipe.seed, 3u);
    EXPECT_EQ(recipe.options.value("size"), "40x30");
    expect_failure("stucco.png --recipe r2.texsyn",
        "texsyn ERROR: --recipe r2.texsyn : the current item, the stucco.png, has no recipe: it "
        "was read from a file, not made by a method",
        { "stucco.png", "r.texsyn" });
    expect_failure("stucco.png --pyramid:size=32x32 --pyramid:size=16x16 --recipe r2.texsyn",
        "texsyn ERROR: --recipe r2.texsyn : the current item, the pyramid synthesis of pyramid "
        "synthesis of stucco.png, has no recipe: its input, the pyramid synthesis of "
        "stucco.png, is not a file (recipes name their samples' files: write it first and "
        "read that)",
        { "stucco.png", "r.texsyn" });
    expect_failure("stucco.png --pyramid --recipe r2.json",
        "texsyn ERROR: --recipe r2.json : name the recipe *.texsyn", { "stucco.png", "r.texsyn" });
}

TEST_F(Cli, AnAnalysisFileSynthesizesWhatTheSampleWould)
{
    CliRun r = texsyn("stucco.png --analyze -o stucco.tsa");
    ASSERT_EQ(r.status, 0) << r.err;
    r = texsyn("--seed 3 stucco.tsa --pyramid:size=300x200:iterations=2 -o from_tsa.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    r = texsyn("--seed 3 stucco.png --pyramid:size=300x200:iterations=2 -o from_png.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(OIIO::ImageBufAlgo::computePixelHashSHA1(read("from_tsa.exr")),
        OIIO::ImageBufAlgo::computePixelHashSHA1(read("from_png.exr")));
    // Integer outputs go back to the sample's colour space and pixel type, as from the png.
    r = texsyn("--seed 3 stucco.tsa --pyramid:size=64x64:iterations=1 -o a.png "
               "--recipe a.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(file_type("a.png"), OIIO::TypeUInt8);
    EXPECT_EQ(read("a.png").spec().get_string_attribute("synth:colorspace"), "sRGB - Texture");
    EXPECT_NE(slurp(dir / "a.texsyn").find("\"sample\": \"stucco.tsa\""), std::string::npos);
    // A Laplacian analysis synthesizes with pyramid=laplacian, and says so otherwise.
    r = texsyn("stucco.png --analyze:pyramid=laplacian:scales=3 -o lap.tsa");
    ASSERT_EQ(r.status, 0) << r.err;
    r = texsyn("lap.tsa --pyramid:pyramid=laplacian:size=64x64:iterations=1 -o lap.exr");
    EXPECT_EQ(r.status, 0) << r.err;
    r = texsyn("lap.tsa --pyramid:size=64x64 -o bad.exr");
    EXPECT_EQ(r.first_err_line(),
        "texsyn ERROR: --pyramid : pyramid=steerable : differs from the analysis "
        "(pyramid=laplacian)");
}

TEST_F(Cli, BadAnalysisCommandsAndFilesAreRefused)
{
    expect_failure("stucco.png --analyze:iterations=3 -o a.tsa",
        "texsyn ERROR: --analyze : iterations=3 : unknown option (known: pyramid, scales, "
        "orientations, fft, flatten)");
    expect_failure("stucco.png --analyze -o a.exr",
        "texsyn ERROR: -o a.exr : the current item is an analysis; write it as *.tsa, or "
        "synthesize from it first (--pyramid, --mix and --transfer take analyses)");
    expect_failure("stucco.png --pyramid:size=32x32 -o a.tsa",
        "texsyn ERROR: -o a.tsa : .tsa holds analyses (from --analyze); the current item is an "
        "image");
    expect_failure("--subbands stucco.png --analyze -o a.tsa",
        "texsyn ERROR: -o a.tsa : --subbands writes images, not analysis files");
    expect_failure("stucco.png --analyze:scales=9 -o a.tsa",
        "texsyn ERROR: --analyze : scales=9 is too many for a 128x128 sample (at most 4)");
    std::ofstream(dir / "junk.tsa") << "not an analysis";
    expect_failure("junk.tsa --pyramid -o a.exr",
        "texsyn ERROR: junk.tsa: not a texsyn analysis file (no texsyn-analysis signature)",
        { "stucco.png", "junk.tsa" });
    ASSERT_EQ(texsyn("stucco.png --analyze -o good.tsa").status, 0);
    const std::string good = slurp(dir / "good.tsa");
    std::ofstream(dir / "cut.tsa", std::ios::binary) << good.substr(0, good.size() / 3);
    expect_failure("cut.tsa --pyramid -o a.exr",
        "texsyn ERROR: cut.tsa: corrupted or truncated analysis file (checksum mismatch)",
        { "stucco.png", "junk.tsa", "good.tsa", "cut.tsa" });
    expect_failure("--iscolorspace Raw good.tsa --pyramid -o a.exr",
        "texsyn ERROR: --iscolorspace : good.tsa is an analysis, its statistics are already "
        "scene-linear",
        { "stucco.png", "junk.tsa", "good.tsa", "cut.tsa" });
    expect_failure("good.tsa -o good.tsa",
        "texsyn ERROR: -o good.tsa : refusing to overwrite the input good.tsa",
        { "stucco.png", "junk.tsa", "good.tsa", "cut.tsa" });
}

namespace {

// A copy of stucco.png lit by a ramp from 0.5 (left) to 1.5 (right), in scene-linear, as a
// float EXR (which texsyn reads as scene-linear).
void write_gradient_sample(const fs::path& dir, const std::string& name)
{
    OIIO::ImageBuf file;
    std::string error;
    ASSERT_TRUE(read_image((dir / "stucco.png").string(), file, error)) << error;
    PlanarImage lin;
    ASSERT_TRUE(planes_from_imagebuf(file, lin, error)) << error;
    auto cc = ColorConfig::load(TEXSYN_BUNDLED_OCIO_CONFIG, error);
    ASSERT_TRUE(cc->convert(lin, "sRGB - Texture", cc->scene_linear(), error)) << error;
    for (Plane& p : lin.channels)
        for (int y = 0; y < p.height(); ++y)
            for (int x = 0; x < p.width(); ++x)
                p(x, y) *= 0.5f + (float(x) + 0.5f) / float(p.width());
    OIIO::ImageBuf out;
    imagebuf_from_planes(lin, out);
    ASSERT_TRUE(out.write((dir / name).string(), OIIO::TypeFloat)) << out.geterror();
}

} // namespace

TEST_F(Cli, CheckReportsOnAHomogeneousSampleWithoutAnOutput)
{
    CliRun r = texsyn("stucco.png --check");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(r.out.find("stucco.png (128x128)\n  homogeneity score "), 0u) << r.out;
    EXPECT_NE(r.out.find("   good (1 = homogeneous; poor below 0.50)\n"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\n  illumination gradient "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n  local mean variation "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\n  local contrast variation "), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("warning:"), std::string::npos) << r.out;
    EXPECT_TRUE(outputs().empty());
}

TEST_F(Cli, CheckWarnsAboutALightingGradientAndPyramidTakesFlatten)
{
    write_gradient_sample(dir, "grad.exr");
    CliRun r = texsyn("grad.exr --check");
    ASSERT_EQ(r.status, 0) << r.err; // a poor sample is reported, not an error
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("   poor (1 = homogeneous; poor below 0.50)\n"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\nwarning: the lighting varies by "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("brighter towards the right"), std::string::npos) << r.out;

    r = texsyn("grad.exr --pyramid:size=128x128:iterations=2:flatten=1 -d float -o flat.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(read("flat.exr").spec().get_string_attribute("synth:options").find(":flatten=1"),
        std::string::npos);
    // An analysis is flattened when it is made; a synthesis from one cannot flatten.
    r = texsyn("grad.exr --analyze:flatten=1 -o flat.tsa");
    ASSERT_EQ(r.status, 0) << r.err;
    r = texsyn("flat.tsa --pyramid:size=128x128:iterations=2 -d float -o from_tsa.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(OIIO::ImageBufAlgo::computePixelHashSHA1(read("from_tsa.exr")),
        OIIO::ImageBufAlgo::computePixelHashSHA1(read("flat.exr")));
    const std::initializer_list<std::string> files
        = { "stucco.png", "grad.exr", "flat.exr", "flat.tsa", "from_tsa.exr" };
    expect_failure("grad.exr --pyramid:flatten=2 -o out.exr",
        "texsyn ERROR: --pyramid : flatten=2 : out of range 0..1", files);
    expect_failure("flat.tsa --pyramid:flatten=1 -o out.exr",
        "texsyn ERROR: --pyramid : flatten=1 : needs a sample, and flat.tsa is an analysis "
        "(flatten "
        "when analysing: --analyze:flatten=1)",
        files);
}

TEST_F(Cli, CheckLeavesTheStackAsItWas)
{
    const std::string synth = " --pyramid:size=48x48:iterations=1 -d float -o ";
    ASSERT_EQ(texsyn("stucco.png" + synth + "a.exr").status, 0);
    CliRun r = texsyn("stucco.png --check" + synth + "b.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.find("stucco.png (128x128)\n"), 0u) << r.out; // stdout even without -v
    EXPECT_EQ(OIIO::ImageBufAlgo::computePixelHashSHA1(read("a.exr")),
        OIIO::ImageBufAlgo::computePixelHashSHA1(read("b.exr")));
    // After an -o: the report is on the synthesis.
    r = texsyn("stucco.png" + synth + "c.exr --check");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.find("pyramid synthesis of stucco.png (48x48)\n"), 0u) << r.out;
}

TEST_F(Cli, CheckNeedsAnImageAndTakesNoOptions)
{
    expect_failure(
        "--check", "texsyn ERROR: --check : no current image (give an input file before it)");
    expect_failure("stucco.png --check:tiles=8",
        "texsyn ERROR: --check : tiles=8 : unknown option (it takes none)");
    expect_failure("stucco.png --check stucco.png",
        "texsyn ERROR: stucco.png : has no effect, nothing is written after it (add -o FILE)");
    expect_failure("stucco.png --analyze --check",
        "texsyn ERROR: --check : needs an image, not an analysis (the analysis of stucco.png; "
        "only --pyramid, --mix and --transfer take analyses)");
}

TEST_F(Cli, SolidTexturesAreWrittenAsVdbAndAsSliceExr)
{
    const std::string before = slurp(dir / "stucco.png");
    CliRun r = texsyn("stucco.png --solid:size=32x24x16:iterations=1 -o out.vdb -o out.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(slurp(dir / "stucco.png"), before);
    // Stock oiiotool reads the VDB (its display size is the block's) and takes a z slice
    // out of the EXR by name.
    std::string cmd = "cd " + quote(dir.string())
        + " && oiiotool --info -v out.vdb > info.txt"
          " && oiiotool out.exr --subimage z0005 -o slice.png";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string info = slurp(dir / "info.txt");
    EXPECT_NE(info.find("channel list: Cd.r, Cd.g, Cd.b"), std::string::npos) << info;
    EXPECT_NE(info.find("full/display size: 32 x 24 x 16"), std::string::npos) << info;
    OIIO::ImageBuf slice = read("slice.png");
    EXPECT_EQ(slice.spec().width, 32);
    EXPECT_EQ(slice.spec().height, 24);
    auto in = OIIO::ImageInput::open((dir / "out.exr").string());
    ASSERT_TRUE(in);
    int parts = 0;
    while (in->seek_subimage(parts, 0)) {
        EXPECT_EQ(in->spec().get_string_attribute("synth:method"), "solid");
        EXPECT_EQ(in->spec().get_string_attribute("synth:sample"), "stucco.png");
        EXPECT_EQ(in->spec().format, OIIO::TypeHalf); // EXR's default, as for images
        ++parts;
    }
    EXPECT_EQ(parts, 16);
    EXPECT_EQ(in->spec(0, 0).get_string_attribute("synth:options"),
        "size=32x24x16:iterations=1:pyramid=combined:scales=1:orientations=4:histogram=exact:"
        "fft=kiss:flatten=0");
}

TEST_F(Cli, BadSolidRequestsAreRefused)
{
    expect_failure("stucco.png --solid:size=64x64 -o out.vdb",
        "texsyn ERROR: --solid : size=64x64 : not a size (expected WxHxD, e.g. 128x128x128)");
    expect_failure("stucco.png --solid:size=0x1x1 -o out.vdb",
        "texsyn ERROR: --solid : size=0x1x1 : out of range 1..16384 (each side)");
    expect_failure("stucco.png --solid:pyramid=steerable -o out.vdb",
        "texsyn ERROR: --solid : pyramid=steerable : not one of combined|laplacian");
    expect_failure("stucco.png --solid:size=64x64x8:scales=4 -o out.vdb",
        "texsyn ERROR: --solid : size=64x64x8 is too small for 4 scales (each side at least 16)");
    expect_failure("stucco.png --solid:size=32x32x32 -o out.png",
        "texsyn ERROR: -o out.png : a solid texture is written as .vdb (OpenVDB) or .exr (one "
        "part per z slice), not '.png'");
    expect_failure("stucco.png --pyramid:size=32x32 -o out.vdb",
        "texsyn ERROR: -o out.vdb : .vdb holds solid textures (from --solid); the current "
        "item is an image");
    expect_failure("stucco.png --solid:size=16x16x16 --pyramid -o out.exr",
        "texsyn ERROR: --pyramid : the current image is a solid texture (from --solid); it "
        "needs a 2-D image");
    expect_failure("--subbands stucco.png --solid:size=16x16x16 -o out.exr",
        "texsyn ERROR: --subbands : does not apply to --solid (solid textures have no "
        "inspection EXR)");
    expect_failure("-d half stucco.png --solid:size=16x16x16 -o out.vdb",
        "texsyn ERROR: -d half : .vdb files hold float");
    expect_failure("stucco.png --analyze --recipe out.texsyn",
        "texsyn ERROR: --recipe out.texsyn : the current item is an analysis; recipes describe "
        "images");

    expect_failure_starting("stucco.png --solid:size=16384x16384x16384 -o out.vdb",
        "texsyn ERROR: --solid : size=16384x16384x16384 would need about ");

    OIIO::ImageBuf tiny(OIIO::ImageSpec(8, 8, 3, OIIO::TypeFloat));
    ASSERT_TRUE(tiny.write((dir / "tiny.exr").string()));
    expect_failure("tiny.exr --solid:size=16x16x16 -o out.vdb",
        "texsyn ERROR: --solid : sample is 8x8: the pyramid method needs at least 16x16",
        { "stucco.png", "tiny.exr" });
}

// --mix and --transfer: oiiotool stack semantics (sample 0 is pushed first; --transfer's
// sample is on top of the image), synth:* metadata naming the inputs.
TEST_F(Cli, MixAndTransferTakeTheirInputsFromTheStack)
{
    fs::copy_file(sample_path("rust.png"), dir / "rust.png");
    fs::copy_file(sample_path("paper_crinkled.png"), dir / "paper.png");
    const std::string fast = "size=64x64:iterations=1";
    CliRun r
        = texsyn("stucco.png rust.png paper.png --mix:palette=0:pattern=1:" + fast + " -o pp.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    OIIO::ImageSpec s = read("pp.exr").spec();
    EXPECT_EQ(s.width, 64);
    EXPECT_EQ(s.get_string_attribute("synth:method"), "mix");
    EXPECT_EQ(s.get_string_attribute("synth:sample"), "rust.png,paper.png"); // stucco stays
    EXPECT_EQ(s.get_string_attribute("synth:options"),
        "size=64x64:iterations=1:pyramid=steerable:scales=3:orientations=4:histogram=exact:"
        "fft=kiss:gain=1:balance=0:flatten=0:palette=0:pattern=1:split=none:weights=none");

    r = texsyn("paper.png rust.png --mix:split=2:" + fast + " -o split.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(read("split.exr")
                  .spec()
                  .get_string_attribute("synth:options")
                  .find(":palette=0:pattern=none:split=2:weights=none"),
        std::string::npos);

    r = texsyn("rust.png stucco.png paper.png --mix:weights=0.5,0.3,0.2:" + fast + " -o w.png");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(file_type("w.png"), OIIO::TypeUInt8);
    EXPECT_EQ(
        read("w.png").spec().get_string_attribute("synth:sample"), "rust.png,stucco.png,paper.png");

    r = texsyn("paper.png rust.png --transfer:iterations=2 -o t.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    s = read("t.exr").spec();
    EXPECT_EQ(s.width, 128); // the image's size (rust is 256x256)
    EXPECT_EQ(s.get_string_attribute("synth:method"), "transfer");
    EXPECT_EQ(s.get_string_attribute("synth:sample"), "rust.png");
    EXPECT_EQ(s.get_string_attribute("synth:image"), "paper.png");
    EXPECT_EQ(s.get_string_attribute("synth:options").find("size=128x128:iterations=2:"), 0u);

    r = texsyn("-v --subbands rust.png paper.png --mix:palette=1:pattern=0:" + fast + " -o b.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("texsyn: --mix size=64x64"), std::string::npos) << r.err;
    OIIO::ImageBuf bands((dir / "b.exr").string());
    EXPECT_EQ(bands.nsubimages(), 1 + 1 + 3 * 4 + 1); // synth + its bands (no sample's)
}

// Analysis files are samples of --mix (palette/pattern, split) and --transfer too: the
// same pixels as the images they were made from when analysed with the same pyramid, and
// recipes that name them.
TEST_F(Cli, MixAndTransferTakeAnalysisFiles)
{
    fs::copy_file(sample_path("rust.png"), dir / "rust.png");
    ASSERT_EQ(texsyn("rust.png --analyze:scales=3 -o rust.tsa").status, 0);
    const std::string mix
        = " --mix:palette=0:pattern=1:size=64x64:iterations=1:scales=3 -d float -o ";
    ASSERT_EQ(texsyn("--seed 2 stucco.png rust.png" + mix + "a.exr").status, 0);
    CliRun r = texsyn("--seed 2 stucco.png rust.tsa" + mix + "b.exr --recipe b.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(pixel_hash(read("a.exr")), pixel_hash(read("b.exr")));
    EXPECT_EQ(read("b.exr").spec().get_string_attribute("synth:sample"), "stucco.png,rust.tsa");
    Recipe recipe;
    std::string error;
    ASSERT_TRUE(recipe_from_filename((dir / "b.texsyn").string(), recipe, error)) << error;
    EXPECT_EQ(recipe.samples,
        (std::vector<std::string> { (dir / "stucco.png").string(), (dir / "rust.tsa").string() }));
    EXPECT_EQ(recipe.iscolorspace, (std::vector<std::string> { "sRGB - Texture", "" }));
    OIIO::ImageBuf again;
    ASSERT_TRUE(run_recipe(recipe, again, nullptr, error)) << error;
    EXPECT_EQ(pixel_hash(again), pixel_hash(read("b.exr")));

    const std::string transfer = " --transfer:iterations=1:scales=3 -d float -o ";
    ASSERT_EQ(texsyn("stucco.png rust.png" + transfer + "c.exr").status, 0);
    ASSERT_EQ(texsyn("stucco.png rust.tsa" + transfer + "d.exr").status, 0);
    EXPECT_EQ(pixel_hash(read("c.exr")), pixel_hash(read("d.exr")));

    // An analysis made with another pyramid is refused, naming it.
    expect_failure("stucco.png rust.tsa --mix:palette=0:pattern=1:scales=2 -o e.exr",
        "texsyn ERROR: --mix : sample 1: scales=2 : differs from the analysis (scales=3) "
        "(sample 0 = stucco.png, sample 1 = rust.tsa)",
        { "stucco.png", "rust.png", "rust.tsa", "a.exr", "b.exr", "b.texsyn", "c.exr", "d.exr" });
    // An analysis keeps no pixels to flatten.
    expect_failure("stucco.png rust.tsa --transfer:flatten=1:scales=3 -o e.exr",
        "texsyn ERROR: --transfer : flatten=1 : needs a sample, and rust.tsa is an analysis "
        "(flatten when analysing: --analyze:flatten=1) (image = stucco.png, sample = rust.tsa)",
        { "stucco.png", "rust.png", "rust.tsa", "a.exr", "b.exr", "b.texsyn", "c.exr", "d.exr" });
}

TEST_F(Cli, BadMixAndTransferInputIsRefused)
{
    fs::copy_file(sample_path("rust.png"), dir / "rust.png");
    write_sample("rgba.exr", 4, OIIO::TypeHalf);
    write_sample("tiny.exr", 3, OIIO::TypeHalf);
    OIIO::ImageBuf small
        = OIIO::ImageBufAlgo::resize(read("rust.png"), "", 0, OIIO::ROI(0, 12, 0, 12, 0, 1, 0, 3));
    ASSERT_TRUE(small.write((dir / "small.png").string()));
    const auto inputs = { std::string("stucco.png"), std::string("rust.png"),
        std::string("rgba.exr"), std::string("tiny.exr"), std::string("small.png") };
    auto refused = [&](const std::string& args, const std::string& line) {
        expect_failure(args, "texsyn ERROR: " + line, inputs);
    };
    // Too few images on the stack: found before anything is read.
    refused("rust.png --mix:palette=0:pattern=1 -o out.exr",
        "--mix : needs 2 images on the stack, there is 1");
    refused("rust.png stucco.png --mix:weights=1,1,1 -o out.exr",
        "--mix : needs 3 images on the stack, there are 2");
    refused(
        "stucco.png --transfer -o out.exr", "--transfer : needs 2 images on the stack, there is 1");
    refused(
        "missing.png --mix:split=1 -o out.exr", "--mix : needs 2 images on the stack, there is 1");
    // Options.
    refused("rust.png stucco.png --mix -o out.exr",
        "--mix : no mix mode given (choose one mode: palette=I:pattern=J, split=S or "
        "weights=W0,W1,...)");
    refused("rust.png stucco.png --mix:palette=0:pattern=2 -o out.exr",
        "--mix : pattern=2 : out of range 0..1: the mix has 2 samples");
    refused("rust.png stucco.png --mix:pattern=1 -o out.exr",
        "--mix : pattern=1 : needs palette= (the sample giving the colour)");
    refused("rust.png stucco.png --mix:palette=0:palette=1 -o out.exr",
        "--mix : palette=1 : given twice");
    refused("rust.png stucco.png --mix:weights=0,0 -o out.exr",
        "--mix : weights=0,0 : the weights must not all be 0");
    refused("rust.png stucco.png --mix:weights=1,-1 -o out.exr",
        "--mix : weights=1,-1 : -1 is out of range 0..1000");
    refused(
        "rust.png stucco.png --mix:split=17 -o out.exr", "--mix : split=17 : out of range 1..16");
    refused("rust.png stucco.png --mix:split=5 -o out.exr",
        "--mix : split=5 : out of range 1..4: the pyramid has 4 scales");
    refused("rust.png stucco.png --mix:palette=0:pattern=1:split=2 -o out.exr",
        "--mix : pattern=1 : does not go with split=2 (choose one mode: palette=I:pattern=J, "
        "split=S or weights=W0,W1,...)");
    refused("stucco.png rust.png --transfer:size=64x64 -o out.exr",
        "--transfer : size=64x64 : unknown option (known: iterations, pyramid, scales, "
        "orientations, histogram, fft, gain, balance, flatten)");
    // Samples.
    refused("stucco.png rgba.exr --mix:weights=1,1 -o out.exr",
        "--mix : sample 1 has 4 channels (R,G,B,A), sample 0 3 channels (R,G,B): the samples of "
        "a mix need the same channels (sample 0 = stucco.png, sample 1 = rgba.exr)");
    refused("small.png stucco.png --mix:split=1 -o out.exr",
        "--mix : sample 0 is 12x12: the pyramid method needs at least 16x16 (sample 0 = "
        "small.png, sample 1 = stucco.png)");
    refused("rgba.exr stucco.png --transfer -o out.exr",
        "--transfer : the image has 4 channels, the sample 3: a transfer needs the same "
        "channels (image = rgba.exr, sample = stucco.png)");
    refused("stucco.png tiny.exr --transfer:scales=3 -o out.exr",
        "--transfer : scales=3 is too many for a 32x32 sample (at most 2) (image = stucco.png, "
        "sample = tiny.exr)");
    // Analyses: a transfer's image must be an image; the weights mode needs pixels.
    refused("stucco.png --analyze rust.png --transfer -o out.exr",
        "--transfer : needs an image, not an analysis (the analysis of stucco.png; only "
        "--pyramid, --mix and --transfer take analyses)");
    refused("stucco.png --analyze rust.png --mix:weights=1,1 -o out.exr",
        "--mix : weights=1,1 : averages the samples' colours in one basis, which needs their "
        "pixels, and sample 0 is an analysis (give the image) (sample 0 = analysis of "
        "stucco.png, sample 1 = rust.png)");
}
