// SPDX-License-Identifier: Apache-2.0
// The OIIO format plugin, driven through the STOCK Debian tools (oiiotool, iinfo, maketx,
// idiff) and Python, with OIIO_LIBRARY_PATH pointing at the built plugin.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include <sys/stat.h>
#include <sys/wait.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imagecache.h>

#include <gtest/gtest.h>

#include "../cli/png_bomb.h"

#include <texsyn/recipe.h>

namespace fs = std::filesystem;

namespace {

struct ToolRun {
    int status = -1;
    std::string out; // stdout and stderr together
};

class Plugin : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() / (std::string("texsyn_plugin_") + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        fs::copy_file(std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png", dir / "s.png");
    }
    void TearDown() override { fs::remove_all(dir); }

    // Runs a shell command in the test directory with the plugin on OIIO's search path.
    ToolRun sh(const std::string& cmd)
    {
        std::string full = "cd '" + dir.string() + "' && export OCIO= OIIO_LIBRARY_PATH='"
            + TEXSYN_PLUGIN_DIR + "' && (" + cmd + ") > out.txt 2>&1";
        int rc = std::system(full.c_str());
        ToolRun r;
        r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
        std::ifstream in(dir / "out.txt");
        std::stringstream ss;
        ss << in.rdbuf();
        r.out = ss.str();
        return r;
    }

    void write(const std::string& name, const std::string& text)
    {
        std::ofstream(dir / name) << text;
    }

    // `texsyn --seed 5 SAMPLE --METHOD:OPTIONS -d float -o cli.exr --recipe r.texsyn`, then
    // stock oiiotool opens that recipe, and SAMPLE.texsyn?OPTIONS as REST arguments (the
    // method last), to the tool's pixels. Returns the REST image's synth:options.
    std::string expect_recipes_give_the_tools_pixels(
        const std::string& sample, const std::string& method, const std::string& options);

    fs::path dir;
};

const std::string texsyn_exe = TEXSYN_EXE;

std::string Plugin::expect_recipes_give_the_tools_pixels(
    const std::string& sample, const std::string& method, const std::string& options)
{
    ToolRun r = sh("'" + texsyn_exe + "' --seed 5 " + sample + " --" + method + ":" + options
        + " -d float -o cli.exr --recipe r.texsyn");
    EXPECT_EQ(r.status, 0) << r.out;
    r = sh("oiiotool r.texsyn -d float -o plugin.exr && idiff -fail 0 cli.exr plugin.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    std::string rest = options;
    std::replace(rest.begin(), rest.end(), ':', '&');
    r = sh("oiiotool '" + sample + ".texsyn?" + rest + "&seed=5&method=" + method
        + "' -d float -o rest.exr && idiff -fail 0 cli.exr rest.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    OIIO::ImageBuf image((dir / "rest.exr").string());
    EXPECT_EQ(image.spec().get_string_attribute("synth:method"), method);
    return image.spec().get_string_attribute("synth:options");
}

} // namespace

TEST_F(Plugin, RecipeFromTheToolGivesTheToolsPixels)
{
    ASSERT_EQ(sh("'" + texsyn_exe
                  + "' --seed 7 s.png --pyramid:size=80x64:iterations=2 -d float -o cli.exr "
                    "--recipe r.texsyn")
                  .status,
        0);
    ToolRun r = sh("oiiotool r.texsyn -d float -o plugin.exr && idiff -fail 0 cli.exr plugin.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    // And in sRGB, through the recipe's tocolorspace, against the tool's PNG.
    ASSERT_EQ(sh("'" + texsyn_exe + "' --seed 7 s.png --pyramid:size=80x64:iterations=2 -o cli.png")
                  .status,
        0);
    r = sh(
        "oiiotool 'r.texsyn?tocolorspace=sRGB' -o plugin.png && idiff -fail 0 cli.png plugin.png");
    EXPECT_EQ(r.status, 0) << r.out;
}

TEST_F(Plugin, NeighborhoodRecipesGiveTheToolsPixels)
{
    // A 64x64 crop keeps the exhaustive search quick.
    ASSERT_EQ(sh("oiiotool s.png --cut 64x64+0+0 -o c.png").status, 0);
    const std::string written = expect_recipes_give_the_tools_pixels(
        "c.png", "neighborhood", "size=48x40:levels=2:n=7,5:search=exhaustive");
    EXPECT_EQ(written.find("size=48x40:levels=2:n=7,5:"), 0u) << written;
    EXPECT_NE(written.find(":search=exhaustive:"), std::string::npos) << written;
}

TEST_F(Plugin, ChoosyRecipesGiveTheToolsPixels)
{
    const std::string written = expect_recipes_give_the_tools_pixels(
        "s.png", "choosy", "size=48x40:levels=3:iterations=1,2:search=kdtree:isotropic=0");
    EXPECT_EQ(written.find("size=48x40:levels=3:iterations=1,2:"), 0u) << written;
    EXPECT_NE(written.find(":isotropic=0:flatten=0:scale=1:search=kdtree:"), std::string::npos)
        << written;
    // And as JSON, iterations an array.
    write("a.texsyn",
        R"({"sample": "s.png", "size": [48, 40], "levels": 3, "iterations": [1, 2],)"
        R"( "isotropic": 0, "seed": 5, "method": "choosy"})");
    ToolRun r = sh("oiiotool a.texsyn -d float -o json.exr && idiff -fail 0 cli.exr json.exr");
    EXPECT_EQ(r.status, 0) << r.out;
}

TEST_F(Plugin, AnAnalysisFileIsARecipesSample)
{
    ASSERT_EQ(sh("'" + texsyn_exe + "' s.png --analyze -o s.tsa").status, 0);
    ASSERT_EQ(sh("'" + texsyn_exe
                  + "' --seed 4 s.png --pyramid:size=160x144:iterations=2 -d float -o cli.exr")
                  .status,
        0);
    write("t.texsyn", R"({"sample": "s.tsa", "size": "160x144", "iterations": 2, "seed": 4})");
    ToolRun r = sh("oiiotool t.texsyn -d float -o a.exr && idiff -fail 0 cli.exr a.exr && "
                   "oiiotool 's.tsa.texsyn?size=160x144&iterations=2&seed=4' -d float -o b.exr "
                   "&& idiff -fail 0 cli.exr b.exr");
    EXPECT_EQ(r.status, 0) << r.out;
}

TEST_F(Plugin, SampleNamePlusRestArgumentsAndMetadata)
{
    ToolRun r = sh("iinfo -v 's.png.texsyn?size=96x40&seed=3&iterations=1'");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("96 x   40, 3 channel, float texsyn"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("synth:method: \"pyramid\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("synth:seed: 3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("synth:sample: \"s.png\""), std::string::npos) << r.out;
    r = sh("oiiotool 's.png.texsyn?size=96x40&seed=3&iterations=1' -o a.exr");
    ASSERT_EQ(r.status, 0) << r.out;
    OIIO::ImageBuf a((dir / "a.exr").string());
    EXPECT_EQ(a.spec().width, 96);
    EXPECT_EQ(a.spec().get_string_attribute("synth:options").find("size=96x40:iterations=1:"), 0u);
}

TEST_F(Plugin, RestArgumentsOverrideARecipeFile)
{
    write("r.texsyn", R"({ "sample": "s.png", "size": [48, 32], "seed": 1, "iterations": 1 })");
    ToolRun r = sh("oiiotool r.texsyn -o a.exr && oiiotool 'r.texsyn?seed=9&size=40x40' -o b.exr");
    ASSERT_EQ(r.status, 0) << r.out;
    OIIO::ImageBuf a((dir / "a.exr").string()), b((dir / "b.exr").string());
    EXPECT_EQ(a.spec().width, 48);
    EXPECT_EQ(a.spec().get_int_attribute("synth:seed"), 1);
    EXPECT_EQ(b.spec().width, 40);
    EXPECT_EQ(b.spec().get_int_attribute("synth:seed"), 9);
}

TEST_F(Plugin, MaketxMakesATiledMipmappedTexture)
{
    write("m.texsyn", R"({ "sample": "s.png", "size": "128x128", "iterations": 1 })");
    ToolRun r = sh("maketx m.texsyn -o m.tx && iinfo -v m.tx");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("MIP-map levels: 128x128 64x64 32x32"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("tile size: 64 x 64"), std::string::npos) << r.out;
}

TEST_F(Plugin, SubbandsAreFurtherSubimages)
{
    const std::string name = "'s.png.texsyn?size=64x64&iterations=1&subbands=1'";
    ToolRun r = sh("iinfo " + name + " && oiiotool " + name
        + " --subimage synth.s1.o2 -o band.exr && oiiotool " + name + " -o all.exr");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("(29 subimages)"), std::string::npos) << r.out; // 1 + 2 x 14 bands
    OIIO::ImageBuf band((dir / "band.exr").string());
    EXPECT_EQ(band.spec().width, 32);
    EXPECT_EQ(band.spec().channelnames, (std::vector<std::string> { "pc0", "pc1", "pc2" }));
    EXPECT_EQ(band.spec().get_string_attribute("synth:method"), "pyramid");
    // All parts share one display window, so stock oiiotool writes them as one OpenEXR.
    OIIO::ImageBuf all((dir / "all.exr").string());
    EXPECT_EQ(all.nsubimages(), 29);
}

// Every bad recipe fails with the plugin's message and exit status 1 — never a crash
// (stock oiiotool 2.4.7 crashes for plugins that claim "procedural" and then fail open).
TEST_F(Plugin, BadRecipesFailCleanly)
{
    write("malformed.texsyn", R"({ "sample": )");
    write("unknown_key.texsyn", R"({ "sample": "s.png", "octaves": 3 })");
    write("other_method.texsyn", R"({ "sample": "s.png", "levels": 3 })");
    write("unknown_method.texsyn", R"({ "sample": "s.png", "method": "quilting" })");
    write("missing_sample.texsyn", R"({ "sample": "nope.png" })");
    write("bad_value.texsyn", R"({ "sample": "s.png", "orientations": 99 })");
    write("self.texsyn", R"({ "sample": "self.texsyn", "size": "16x16" })");
    write("loop_a.texsyn", R"({ "sample": "loop_b.texsyn", "size": "16x16" })");
    write("loop_b.texsyn", R"({ "sample": "loop_a.texsyn", "size": "16x16" })");
    // A recipe FILE's error reaches every tool. For a name with REST arguments that is no
    // file, stock oiiotool reports only "File does not exist"; iinfo (and Python) show the
    // plugin's message.
    struct Case {
        std::string name, message, oiiotool_message;
    };
    const Case cases[] = {
        { "malformed.texsyn", "malformed.texsyn: malformed JSON", "" },
        { "unknown_key.texsyn", "unknown_key.texsyn: unknown key 'octaves'", "" },
        { "other_method.texsyn",
            "other_method.texsyn: key 'levels' is an option of method neighborhood, not of this "
            "recipe's method pyramid",
            "" },
        { "unknown_method.texsyn", "method=quilting : not one of pyramid", "" },
        { "missing_sample.texsyn", "nope.png: no such file", "" },
        { "bad_value.texsyn", "orientations=99 : out of range 1..8", "" },
        { "self.texsyn", "self.texsyn: the recipe uses itself as its sample", "" },
        { "loop_a.texsyn", "recipes nest more than 8 deep", "" },
        { "'s.png.texsyn?size=abc'", "size=abc : not a size", "File does not exist" },
        { "'s.png.texsyn?bogus=1'", "unknown key 'bogus'", "File does not exist" },
        { "'s.png.texsyn?iterations=1&method=neighborhood'",
            "key 'iterations' is an option of method pyramid", "File does not exist" },
        { "'s.png.texsyn?size=64x64&seed'", "malformed filename", "File does not exist" },
        { "'s.png.texsyn?size=62x62&levels=3&method=choosy'",
            "size=62x62: each side must be a multiple of 4 (2^(levels-1)) for levels=3",
            "File does not exist" },
    };
    for (const Case& c : cases) {
        for (bool oiiotool : { true, false }) {
            std::string cmd = oiiotool ? "oiiotool " + c.name + " -o x.exr" : "iinfo " + c.name;
            const std::string& expected
                = oiiotool && !c.oiiotool_message.empty() ? c.oiiotool_message : c.message;
            ToolRun r = sh(cmd);
            EXPECT_EQ(r.status, 1) << cmd << "\n" << r.out; // 134/139 would be a crash
            EXPECT_NE(r.out.find(expected), std::string::npos) << cmd << "\n" << r.out;
        }
        EXPECT_FALSE(fs::exists(dir / "x.exr"));
    }
}

// What the host tools print stays readable and cannot end them: a recipe naming a 10 MB
// sample used to reach OIIO's 16 MB limit on error text and abort maketx and Python; a
// colour config whose LUT is a FIFO used to hang every host.
TEST_F(Plugin, HostsGetShortErrorsAndNeverBlock)
{
    write("huge.texsyn",
        "{\"texsyn_recipe\":1,\"sample\":\"" + std::string(900000, 'a') + "\",\"size\":\"32x32\"}");
    ToolRun r = sh("timeout 120 maketx huge.texsyn -o x.tx");
    EXPECT_EQ(r.status, 1) << r.out.substr(0, 300);
    EXPECT_LT(r.out.size(), 1000u) << r.out.substr(0, 300);
    EXPECT_NE(r.out.find("...(900000 characters): no such file"), std::string::npos)
        << r.out.substr(0, 300);
    r = sh(
        "timeout 120 /usr/bin/python3 -c \"import OpenImageIO as o; b = o.ImageBuf('huge.texsyn'); "
        "print(b.read(), len(b.geterror()))\"");
    EXPECT_EQ(r.status, 0) << r.out.substr(0, 300);
    EXPECT_EQ(r.out.rfind("False ", 0), 0u) << r.out.substr(0, 300);

    ASSERT_EQ(::mkfifo((dir / "lut.spi1d").c_str(), 0644), 0);
    std::ifstream bundled(TEXSYN_BUNDLED_OCIO_CONFIG);
    std::stringstream config;
    config << bundled.rdbuf();
    write("fifo.ocio",
        std::regex_replace(config.str(), std::regex("search_path:[^\n]*"), "search_path: \".\"")
            + "\n  - !<ColorSpace>\n    name: evil\n    isdata: false\n"
              "    to_scene_reference: !<FileTransform> {src: lut.spi1d, interpolation: linear}\n");
    r = sh("timeout 60 iinfo 's.png.texsyn?size=16x16&colorconfig=fifo.ocio&iscolorspace=evil'");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(
        r.out.find("colour config 'fifo.ocio': its FileTransform 'lut.spi1d': "), std::string::npos)
        << r.out;
}

// A recipe's sample that is a decompression bomb, or a recipe beyond the memory limit
// ($TEXSYN_MAX_MEMORY), is refused before allocating: the host tool gets an error, not a
// crash or minutes of work.
TEST_F(Plugin, MemoryLimitsHoldInsideTheHostTools)
{
    std::ofstream(dir / "bomb.png", std::ios::binary)
        << texsyn::test::png_bomb((dir / "s.png").string(), 100000);
    write("bomb.texsyn", R"({ "sample": "bomb.png", "size": "64x64" })");
    for (const std::string tool : { "iinfo", "oiiotool" }) {
        ToolRun r = sh(tool + " bomb.texsyn" + (tool == "oiiotool" ? " -o x.exr" : ""));
        EXPECT_EQ(r.status, 1) << r.out;
        EXPECT_NE(
            r.out.find("bomb.png: its 100000x100000 pixels would need about"), std::string::npos)
            << r.out;
    }
    // open() refuses a result the host could not hold beside the synthesis's own copy...
    ToolRun r = sh("TEXSYN_MAX_MEMORY=200M iinfo 's.png.texsyn?size=4096x4096'");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("s.png.texsyn: a 4096x4096 result and the host's copy of it would need "
                         "about 384.0 MB of memory"),
        std::string::npos)
        << r.out;
    // ...and without synthesizing it answers one that fits: the synthesis's own estimate
    // refuses it with the first pixels.
    r = sh("TEXSYN_MAX_MEMORY=1G iinfo 's.png.texsyn?size=4096x4096' && "
           "TEXSYN_MAX_MEMORY=1G oiiotool 's.png.texsyn?size=4096x4096' -o x.exr");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("size=4096x4096 would need about"), std::string::npos) << r.out;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

// Sizes no host can hold are refused when the recipe is opened, as the command line
// refuses them, in every host: stock iinfo (also with --stats), oiiotool and maketx, and
// Python's ImageBuf. They used to abort
// the hosts (std::bad_alloc, the ImageCache's check_max_mem assertion) or segfault Python.
TEST_F(Plugin, AbsurdSizesAreRefusedWhenOpenedAndNoHostAborts)
{
    for (const std::string size : { "65536x65536", "46341x46341", "32768x32768" }) {
        write("big.texsyn",
            R"({ "sample": "s.png", "method": "pyramid", "size": ")" + size + R"(" })");
        for (const std::string tool : { "iinfo -v big.texsyn", "iinfo --stats big.texsyn",
                 "oiiotool big.texsyn -o x.exr", "maketx big.texsyn -o x.tx",
                 "/usr/bin/python3 -c \"import OpenImageIO as oiio; b = "
                 "oiio.ImageBuf('big.texsyn'); "
                 "print(b.read(), b.geterror())\"" }) {
            const ToolRun r = sh(tool);
            EXPECT_LT(r.status, 128) << size << ", " << tool << ": " << r.out;
            EXPECT_NE(r.out.find("would need about"), std::string::npos)
                << size << ", " << tool << ": " << r.out;
        }
    }
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
    EXPECT_FALSE(fs::exists(dir / "x.tx"));
}

// The same under an address-space limit (ulimit -v): 16384² fits in memory but not in 3 GB
// of address space. (Not under AddressSanitizer, which reserves terabytes of address space:
// scripts/sanitize.sh leaves out the AddressSpaceLimit tests.)
TEST_F(Plugin, AnAddressSpaceLimitIsKeptWhenARecipeIsOpened)
{
    write("big.texsyn", R"({ "sample": "s.png", "method": "pyramid", "size": "16384x16384" })");
    const ToolRun r = sh("ulimit -v 3000000 && oiiotool big.texsyn -o x.exr");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("a 16384x16384 result and the host's copy of it would need about"),
        std::string::npos)
        << r.out;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

// A recipe is a few hundred bytes: a file over 1 MB is refused from its size, before it is
// read (a 10 GB sparse one used to be read whole, 20 GB resident), by the command line
// (Python: tests/python/test_errors.py). (Stock hosts then try OIIO's other readers, whose DICOM
// reader reads the file through: docs/robustness.md.)
TEST_F(Plugin, RecipeFilesOverAMegabyteAreRefusedFromTheirSize)
{
    write("huge.texsyn", "");
    fs::resize_file(dir / "huge.texsyn", uintmax_t(2) << 20);
    for (const std::string& cmd : { "'" + texsyn_exe + "' huge.texsyn -o x.exr",
             std::string("timeout 60 maketx huge.texsyn -o x.exr") }) {
        const ToolRun r = sh(cmd);
        EXPECT_EQ(r.status, 1) << cmd << ": " << r.out;
        EXPECT_NE(r.out.find("huge.texsyn: is 2.0 MB, more than a recipe can be (1.0 MB)"),
            std::string::npos)
            << cmd << ": " << r.out;
    }
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

// Recipes that nest recipes are counted before anything runs (issue #34): five files of
// mixes of 16, a million syntheses, used to run for hours in every host.
TEST_F(Plugin, NestedRecipesAreBoundedBeforeAnyWork)
{
    write("level4.texsyn", R"({ "sample": "s.png", "size": "16x16", "iterations": 1 })");
    for (int level = 3; level >= 0; --level) {
        std::string samples;
        for (int k = 0; k < 16; ++k)
            samples
                += std::string(k ? "," : "") + "\"level" + std::to_string(level + 1) + ".texsyn\"";
        write("level" + std::to_string(level) + ".texsyn",
            R"({ "method": "mix", "sample": [)" + samples
                + R"(], "weights": "1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1", "size": "16x16",)"
                + R"( "iterations": 1 })");
    }
    // Depth first: the 65th is the 11th level4 under the first level1, level2 and the
    // fourth level3.
    const std::string message = "level4.texsyn: would be synthesis 65 of one recipe, which may "
                                "run at most 64 with the recipes it nests "
                                "($TEXSYN_MAX_RECIPE_SYNTHESES raises the limit)";
    for (const std::string& cmd : { std::string("timeout 60 iinfo --stats level0.texsyn"),
             std::string("timeout 60 oiiotool level0.texsyn -o x.exr"),
             std::string("timeout 60 maketx level0.texsyn -o x.exr"),
             "timeout 60 '" + texsyn_exe + "' level0.texsyn -o x.exr" }) {
        const auto start = std::chrono::steady_clock::now();
        const ToolRun r = sh(cmd);
        const double seconds
            = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(r.status, 1) << cmd << ": " << r.out;
        EXPECT_NE(r.out.find(message), std::string::npos) << cmd << ": " << r.out;
        EXPECT_LT(seconds, 20) << cmd; // refused from the files, not after the work
    }
    EXPECT_FALSE(fs::exists(dir / "x.exr"));

    // 1 + 16 + 16 x 16 = 273 syntheses pass a raised limit; 272 does not.
    ToolRun r = sh("TEXSYN_MAX_RECIPE_SYNTHESES=273 iinfo level2.texsyn");
    EXPECT_EQ(r.status, 0) << r.out;
    r = sh("TEXSYN_MAX_RECIPE_SYNTHESES=272 iinfo level2.texsyn");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("level4.texsyn: would be synthesis 273 of one recipe, which may run at "
                         "most 272 "),
        std::string::npos)
        << r.out;
    // A mix of 16 runs by default (17 syntheses), and pixels come out.
    r = sh("oiiotool level3.texsyn -o x.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    for (const char* bad : { "0", "many", "2000000" }) {
        r = sh(std::string("TEXSYN_MAX_RECIPE_SYNTHESES=") + bad + " iinfo level3.texsyn");
        EXPECT_EQ(r.status, 1) << r.out;
        EXPECT_NE(r.out.find(std::string("TEXSYN_MAX_RECIPE_SYNTHESES=") + bad
                      + ": expected a whole number from 1 to 1000000"),
            std::string::npos)
            << r.out;
    }
    // The depth limit: a chain of 3 under TEXSYN_MAX_RECIPE_DEPTH=1.
    r = sh("TEXSYN_MAX_RECIPE_DEPTH=1 iinfo level2.texsyn");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("level4.texsyn: recipes nest more than 1 deep"), std::string::npos)
        << r.out;
}

// An OBJ whose mtllib names a FIFO hung every host through OpenMesh (issue #34): texsyn's
// reader opens no file a mesh names. A bake recipe on such a mesh, through every host.
TEST_F(Plugin, MeshesNamingFifosDoNotBlockTheHosts)
{
    ASSERT_EQ(::mkfifo((dir / "skin.mtl").c_str(), 0644), 0);
    std::ifstream torus(fs::path(TEXSYN_TEST_DATA).parent_path() / "meshes" / "torus_uv.obj");
    std::stringstream obj;
    obj << "mtllib skin.mtl\nmtllib ../../../../../dev/zero\nusemtl skin\n" << torus.rdbuf();
    write("torus.obj", obj.str());
    write("bake.texsyn",
        R"({ "sample": "s.png", "method": "choosy-surface", "mesh": "torus.obj", "levels": 2,)"
        R"( "bake": "32x32" })");
    for (const char* cmd : { "timeout 120 iinfo --stats bake.texsyn",
             "timeout 120 oiiotool bake.texsyn -o a.exr", "timeout 120 maketx bake.texsyn -o a.tx",
             "timeout 120 /usr/bin/python3 -c \"import OpenImageIO as o; "
             "b = o.ImageBuf('bake.texsyn'); print(b.read(), b.spec().width)\"" }) {
        const ToolRun r = sh(cmd);
        EXPECT_EQ(r.status, 0) << cmd << ": " << r.out; // 124: the timeout, a hang
    }
    EXPECT_TRUE(fs::exists(dir / "a.exr"));
    EXPECT_TRUE(fs::exists(dir / "a.tx"));
}

// One OIIO ImageCache shared by 16 threads, as a renderer uses it: each opens recipes
// through the plugin, four different ones and each of them by four threads at once, and
// gets exactly the pixels of the recipe run alone. (The ThreadSanitizer build runs this
// test: scripts/sanitize.sh.)
TEST_F(Plugin, SixteenThreadsOpenRecipesThroughOneImageCache)
{
    OIIO::attribute("plugin_searchpath", TEXSYN_PLUGIN_DIR);
    std::vector<std::string> names;
    std::vector<std::string> expected;
    for (int i = 0; i < 4; ++i) {
        names.push_back(
            (dir / "s.png.texsyn").string() + "?size=32x24&iterations=1&seed=" + std::to_string(i));
        texsyn::Recipe recipe;
        std::string error;
        ASSERT_TRUE(texsyn::recipe_from_filename(names.back(), recipe, error)) << error;
        OIIO::ImageBuf direct;
        ASSERT_TRUE(texsyn::run_recipe(recipe, direct, nullptr, error)) << error;
        expected.push_back(OIIO::ImageBufAlgo::computePixelHashSHA1(direct));
    }
    auto cache = OIIO::ImageCache::create(false); // private: other tests' state stays out
    std::vector<std::string> got(16);
    std::vector<std::thread> threads;
    for (int t = 0; t < 16; ++t)
        threads.emplace_back([&, t] {
            const std::string& name = names[size_t(t % 4)];
            OIIO::ImageSpec spec;
            if (!cache->get_imagespec(OIIO::ustring(name), spec))
                return;
            spec.format = OIIO::TypeFloat;
            OIIO::ImageBuf buf(spec);
            if (cache->get_pixels(OIIO::ustring(name), 0, 0, 0, spec.width, 0, spec.height, 0, 1,
                    OIIO::TypeFloat, buf.localpixels()))
                got[size_t(t)] = OIIO::ImageBufAlgo::computePixelHashSHA1(buf);
        });
    for (std::thread& t : threads)
        t.join();
    for (int t = 0; t < 16; ++t)
        EXPECT_EQ(got[size_t(t)], expected[size_t(t % 4)]) << "thread " << t;
    OIIO::ImageCache::destroy(cache);
}

TEST_F(Plugin, PythonOpensARecipe)
{
    ToolRun r = sh("/usr/bin/python3 -c \"import OpenImageIO as oiio; "
                   "b = oiio.ImageBuf('s.png.texsyn?size=24x16&iterations=1'); "
                   "a = b.get_pixels(oiio.FLOAT); "
                   "print(a.shape, b.spec().get_string_attribute('synth:method'))\"");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("(16, 24, 3) pyramid"), std::string::npos) << r.out;
}

TEST_F(Plugin, LibraryRecipesMatchTheFormatPlugin)
{
    // The C++ path (run_recipe) and the plugin agree; plugins load in-process too.
    OIIO::attribute("plugin_searchpath", TEXSYN_PLUGIN_DIR);
    const std::string name = (dir / "s.png.texsyn").string() + "?size=40x24&iterations=1";
    OIIO::ImageBuf viaplugin(name);
    ASSERT_TRUE(viaplugin.read(0, 0, true, OIIO::TypeFloat)) << viaplugin.geterror();
    texsyn::Recipe recipe;
    std::string error;
    ASSERT_TRUE(texsyn::recipe_from_filename(name, recipe, error)) << error;
    OIIO::ImageBuf direct;
    ASSERT_TRUE(texsyn::run_recipe(recipe, direct, nullptr, error)) << error;
    EXPECT_EQ(OIIO::ImageBufAlgo::computePixelHashSHA1(viaplugin),
        OIIO::ImageBufAlgo::computePixelHashSHA1(direct));
}

// Every method of the registry is a recipe that stock tools open: a generator with no
// sample, methods with several samples, a solid texture as its z slices.
TEST_F(Plugin, GeneratorRecipesNeedNoSample)
{
    ToolRun r = sh("'" + texsyn_exe
        + "' --seed 5 --cascade:preset=stone:size=64x48 -d float -o cli.exr --recipe r.texsyn");
    ASSERT_EQ(r.status, 0) << r.out;
    r = sh("oiiotool r.texsyn -d float -o plugin.exr && idiff -fail 0 cli.exr plugin.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    // A REST name that is no file, for a method that takes no sample.
    r = sh("oiiotool 'noise.texsyn?method=cascade&preset=stone&size=64x48&seed=5' -d float -o "
           "rest.exr && idiff -fail 0 cli.exr rest.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    r = sh("iinfo -v r.texsyn && maketx r.texsyn -o r.tx && iinfo -v r.tx");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("r.texsyn :   64 x   48, 3 channel, float texsyn"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("synth:method: \"cascade\""), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("synth:sample"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("MIP-map levels: 64x48 32x24"), std::string::npos) << r.out;
}

TEST_F(Plugin, MixAndTransferRecipesTakeSeveralSamples)
{
    fs::copy_file(std::string(TEXSYN_TEST_DATA) + "/rust.png", dir / "r.png");
    ToolRun r = sh("'" + texsyn_exe
        + "' --seed 5 s.png r.png --mix:palette=0:pattern=1:size=48x48:iterations=1 -d float -o "
          "mix.exr --recipe mix.texsyn");
    ASSERT_EQ(r.status, 0) << r.out;
    r = sh("oiiotool mix.texsyn -d float -o a.exr && idiff -fail 0 mix.exr a.exr && oiiotool "
           "'s.png.texsyn?method=mix&sample=s.png,r.png&palette=0&pattern=1&size=48x48&"
           "iterations=1&seed=5' -d float -o b.exr && idiff -fail 0 mix.exr b.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    r = sh("'" + texsyn_exe
        + "' --seed 5 s.png r.png --transfer:iterations=1 -d float -o transfer.exr --recipe "
          "transfer.texsyn && oiiotool transfer.texsyn -d float -o c.exr && idiff -fail 0 "
          "transfer.exr c.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    r = sh("iinfo -v transfer.texsyn && maketx mix.texsyn -o mix.tx && iinfo mix.tx");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("synth:image: \"s.png\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("synth:sample: \"r.png\""), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("mix.tx :   48 x   48, 3 channel"), std::string::npos) << r.out;
}

TEST_F(Plugin, SolidRecipesAreTheirZSlices)
{
    ToolRun r = sh("'" + texsyn_exe
        + "' --seed 5 s.png --solid:size=24x16x6:iterations=1 -d float -o slices.exr --recipe "
          "solid.texsyn");
    ASSERT_EQ(r.status, 0) << r.out;
    // The slice EXR and the recipe's subimages: the same parts, the same pixels.
    r = sh("iinfo solid.texsyn && oiiotool solid.texsyn -a -d float -o plugin.exr && idiff -a "
           "-fail 0 slices.exr plugin.exr && oiiotool solid.texsyn --subimage z0003 -o z3.exr");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("24 x   16, 3 channel, float texsyn (6 subimages)"), std::string::npos)
        << r.out;
    OIIO::ImageBuf z3((dir / "z3.exr").string());
    EXPECT_EQ(z3.spec().width, 24);
    EXPECT_EQ(z3.spec().get_string_attribute("synth:method"), "solid");
    r = sh("maketx solid.texsyn -o solid.tx && iinfo -v solid.tx");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("MIP-map levels: 24x16 12x8"), std::string::npos) << r.out;
}

// A recipe pins a colour config only when the user named one (the bundled config by name,
// never by a path): written with $OCIO set, moved with its sample to another tree, it still
// opens in stock oiiotool, and follows $OCIO where it is opened.
TEST_F(Plugin, RecipesArePortableAndFollowOcio)
{
    std::ifstream bundled(TEXSYN_BUNDLED_OCIO_CONFIG);
    std::stringstream config;
    config << bundled.rdbuf();
    fs::create_directories(dir / "cfg");
    write("cfg/config.ocio", config.str());
    write("cfg/acescg.ocio",
        std::regex_replace(
            config.str(), std::regex("scene_linear: [^\n]*"), "scene_linear: ACEScg"));
    fs::create_directories(dir / "shot");
    fs::copy_file(dir / "s.png", dir / "shot/s.png");
    ToolRun r = sh("cd shot && OCIO=../cfg/config.ocio '" + texsyn_exe
        + "' s.png --pyramid:size=48x32 --recipe env.texsyn -d float -o env.exr && '" + texsyn_exe
        + "' --colorconfig ../cfg/config.ocio s.png --pyramid:size=48x32 --recipe named.texsyn "
          "-o named.exr && '"
        + texsyn_exe
        + "' --colorconfig ../cfg/acescg.ocio s.png --pyramid:size=48x32 --recipe own.texsyn -o "
          "own.exr");
    ASSERT_EQ(r.status, 0) << r.out;
    auto slurp = [&](const std::string& name) {
        std::ifstream in(dir / name);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    };
    EXPECT_EQ(slurp("shot/env.texsyn").find("colorconfig"), std::string::npos)
        << slurp("shot/env.texsyn");
    EXPECT_NE(
        slurp("shot/named.texsyn").find("\"colorconfig\": \"texsyn://bundled\""), std::string::npos)
        << slurp("shot/named.texsyn");
    EXPECT_NE(
        slurp("shot/own.texsyn").find("\"colorconfig\": \"../cfg/acescg.ocio\""), std::string::npos)
        << slurp("shot/own.texsyn");

    // Moved to another tree, with the configs gone: the same pixels from stock oiiotool.
    fs::create_directories(dir / "elsewhere/deep");
    fs::rename(dir / "shot", dir / "elsewhere/deep/shot");
    fs::remove(dir / "cfg/config.ocio");
    r = sh("cd elsewhere/deep/shot && oiiotool env.texsyn -d float -o moved.exr && idiff -fail 0 "
           "env.exr moved.exr && iinfo -v named.texsyn");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("synth:colorspace: \"Linear Rec.709 (sRGB)\""), std::string::npos)
        << r.out;
    // $OCIO at open time: a config whose scene_linear is ACEScg makes the result ACEScg;
    // a recipe pinned to the bundled config ignores it.
    r = sh("cd elsewhere/deep/shot && OCIO=../../../cfg/acescg.ocio iinfo -v env.texsyn "
           "named.texsyn");
    EXPECT_EQ(r.status, 0) << r.out;
    const size_t named = r.out.find("named.texsyn");
    ASSERT_NE(named, std::string::npos) << r.out;
    EXPECT_NE(r.out.substr(0, named).find("synth:colorspace: \"ACEScg\""), std::string::npos)
        << r.out;
    EXPECT_NE(
        r.out.substr(named).find("synth:colorspace: \"Linear Rec.709 (sRGB)\""), std::string::npos)
        << r.out;
    // A pinned config that moved away is named in the error.
    r = sh("cd elsewhere/deep/shot && iinfo own.texsyn");
    EXPECT_EQ(r.status, 1) << r.out;
    EXPECT_NE(r.out.find("acescg.ocio"), std::string::npos) << r.out;
}

// open() answers from the recipe and its samples' headers; the synthesis runs on the first
// read of pixels. iinfo on a 4096x4096 recipe (a synthesis of a minute) returns at once,
// with the spec the pixels then have, wrapmodes included, which oiiotool carries on.
// (Stock maketx 2.4 writes "black,black" unless given --wrap: it ignores its input's.)
TEST_F(Plugin, OpeningARecipeDoesNotSynthesizeIt)
{
    for (const std::string method : { "pyramid", "choosy", "patch", "neighborhood" }) {
        const auto start = std::chrono::steady_clock::now();
        ToolRun r = sh("timeout 20 iinfo -v 's.png.texsyn?size=4096x4096&method=" + method + "'");
        const double seconds
            = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ASSERT_EQ(r.status, 0) << r.out;
        EXPECT_LT(seconds, 2.0) << method;
        EXPECT_NE(r.out.find("4096 x 4096, 3 channel, float texsyn"), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("wrapmodes: \"periodic,periodic\""), std::string::npos) << r.out;
        EXPECT_NE(r.out.find("synth:method: \"" + method + "\""), std::string::npos) << r.out;
    }
    write("r.texsyn", R"({ "sample": "s.png", "size": "64x64", "iterations": 1 })");
    ToolRun r = sh("oiiotool r.texsyn -o s.tif && iinfo -v s.tif");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("wrapmodes: \"periodic,periodic\""), std::string::npos) << r.out;
    // A transfer keeps its image's layout, which need not tile: no wrapmodes.
    r = sh("iinfo -v 's.png.texsyn?method=transfer&sample=s.png,s.png'");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(r.out.find("wrapmodes"), std::string::npos) << r.out;
}
