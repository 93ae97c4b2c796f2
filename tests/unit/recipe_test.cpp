// SPDX-License-Identifier: Apache-2.0
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/recipe.h>
#include <texsyn/stats.h>

#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

using namespace texsyn;
namespace fs = std::filesystem;

namespace {

// The pyramid method's options of a recipe.
const PyramidOptions& pyramid_options(const Recipe& r)
{
    const PyramidOptions* o = r.options.get<PyramidOptions>();
    EXPECT_TRUE(o) << r.method;
    static const PyramidOptions none;
    return o ? *o : none;
}

Recipe with_sample(const std::string& sample, const std::string& method = "pyramid")
{
    Recipe r;
    r.samples = { sample };
    r.method = method;
    r.options = find_method(method)->defaults();
    return r;
}

// recipe_to_json's text of a recipe it can write.
std::string json_of(const Recipe& r, const std::string& base_dir)
{
    std::string json, error;
    EXPECT_TRUE(recipe_to_json(r, base_dir, json, error)) << error;
    return json;
}

} // namespace

TEST(Recipe, NamesThatAreNotUtf8AreRefusedNotThrown)
{
    Recipe r = with_sample("/shows/a/bark\xff.png");
    std::string json = "unchanged", error;
    EXPECT_FALSE(recipe_to_json(r, "/shows/a", json, error));
    EXPECT_EQ(json, "unchanged");
    EXPECT_NE(error.find("not valid UTF-8"), std::string::npos) << error;
    r.samples = { "/shows/a/bark.png" };
    EXPECT_NE(json_of(r, "/shows/a").find("\"sample\": \"bark.png\""), std::string::npos);
}

TEST(Recipe, ParsesEveryKeyAndResolvesPathsAgainstTheRecipesFolder)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(parse_recipe(R"({ "texsyn_recipe": 1, "sample": "maps/rust.png",
        "method": "pyramid", "seed": 12, "size": [640, 480], "iterations": "3",
        "pyramid": "laplacian", "scales": 2, "orientations": 6, "histogram": "bins256",
        "iscolorspace": "sRGB", "tocolorspace": "ACEScg", "colorconfig": "cfg.ocio",
        "subbands": true })",
        "/shows/a", r, error))
        << error;
    EXPECT_EQ(r.samples, (std::vector<std::string> { "/shows/a/maps/rust.png" }));
    EXPECT_EQ(r.colorconfig, "/shows/a/cfg.ocio");
    EXPECT_EQ(r.seed, 12u);
    const PyramidOptions& o = pyramid_options(r);
    EXPECT_EQ(o.width, 640);
    EXPECT_EQ(o.height, 480);
    EXPECT_EQ(o.iterations, 3);
    EXPECT_EQ(o.pyramid, PyramidKind::Laplacian);
    EXPECT_EQ(o.scales, 2);
    EXPECT_EQ(o.orientations, 6);
    EXPECT_EQ(o.histogram, HistogramMode::Bins256);
    EXPECT_EQ(r.iscolorspace, (std::vector<std::string> { "sRGB" }));
    EXPECT_EQ(r.tocolorspace, "ACEScg");
    EXPECT_TRUE(r.subbands);
    ASSERT_TRUE(parse_recipe(R"({ "sample": "/abs/rust.png" })", "/shows/a", r, error));
    EXPECT_EQ(r.samples, (std::vector<std::string> { "/abs/rust.png" }));
}

TEST(Recipe, RejectsBadRecipesNamingTheProblem)
{
    Recipe r;
    std::string error;
    EXPECT_FALSE(parse_recipe("{ \"sample\": ", "", r, error));
    EXPECT_EQ(error.find("malformed JSON (parse error"), 0u) << error;
    EXPECT_FALSE(parse_recipe("[1, 2]", "", r, error));
    EXPECT_EQ(error, "a recipe is a JSON object ({ \"sample\": ..., ... })");
    EXPECT_TRUE(parse_recipe("{ \"size\": \"8x8\" }", "", r, error)) << error;
    EXPECT_FALSE(r.validate(error));
    EXPECT_EQ(
        error, "the recipe names no sample (\"sample\": \"file.png\"); method pyramid takes 1");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "octaves": 3 })", "", r, error));
    EXPECT_EQ(error.find("unknown key 'octaves' (known: texsyn_recipe, sample"), 0u) << error;
    EXPECT_NE(error.find("subbands, size, iterations,"), std::string::npos) << error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "texsyn_recipe": 2 })", "", r, error));
    EXPECT_EQ(error, "texsyn_recipe=2 : newer than this texsyn reads (version 1)");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "method": "quilting" })", "", r, error));
    EXPECT_EQ(error, "method=quilting : not one of " + method_names());
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "seed": -1 })", "", r, error));
    EXPECT_EQ(error, "seed=-1 : out of range 0..2147483647");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "size": 3.5 })", "", r, error));
    EXPECT_EQ(error.find("size: expected a string"), 0u) << error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "subbands": "maybe" })", "", r, error));
    EXPECT_FALSE(parse_recipe(R"({ "sample": 5 })", "", r, error));
    EXPECT_EQ(error, "sample: expected a string or an array of strings, not 5");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "seed": true })", "", r, error));
    EXPECT_EQ(error, "seed: expected an integer or a string, not true");
    EXPECT_FALSE(
        parse_recipe(R"({ "sample": "a.png", "seed": 18446744073709551615 })", "", r, error));
    EXPECT_EQ(error, "seed=18446744073709551615 : out of range 0..2147483647");
}

// A key given twice is refused, as a REST name with a repeated option is: silently keeping
// the last value would run something the user did not read.
TEST(Recipe, DuplicateKeysAreRefused)
{
    Recipe r;
    std::string error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "seed": 1, "seed": 2 })", "", r, error));
    EXPECT_EQ(error, "malformed JSON (duplicate key \"seed\")");
    EXPECT_FALSE(
        parse_recipe(R"({ "sample": "a.png", "iterations": 2, "size": "64x64", "iterations": 2 })",
            "", r, error));
    EXPECT_EQ(error, "malformed JSON (duplicate key \"iterations\")");
}

// A NUL byte ended the parse and what followed was ignored ("{...}\0junk" was read, while
// "{...} {}" was refused).
TEST(Recipe, NulBytesAreRefused)
{
    Recipe r;
    std::string error;
    EXPECT_FALSE(parse_recipe(std::string("{ \"sample\": \"a.png\" }\0junk", 26), "", r, error));
    EXPECT_EQ(error, "malformed JSON (a NUL byte at offset 21)");
}

// A NUL escaped inside a string ("a.png\u0000.exr") cut the file name where the C library
// read it, so another file was read: control characters in a key or value are refused, in
// JSON and in REST arguments.
TEST(Recipe, ControlCharactersInNamesAndValuesAreRefused)
{
    Recipe r;
    std::string error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png\u0000.exr", "size": "8x8" })", "", r, error));
    EXPECT_EQ(error,
        "sample: contains a control character (\"a.png\\x00.exr\"); a recipe's names and "
        "values cannot");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "size": "8x8\n" })", "", r, error));
    EXPECT_EQ(error.rfind("size: contains a control character", 0), 0u) << error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "si\u0001ze": "8x8" })", "", r, error));
    r = with_sample("a.png");
    EXPECT_FALSE(apply_recipe_arguments("size=8x8%0A", "", r, error));
    EXPECT_EQ(error.rfind("size: contains a control character", 0), 0u) << error;
    EXPECT_TRUE(parse_recipe(R"({ "sample": "a b\u00e9.png", "size": "8x8" })", "", r, error))
        << error;
}

// A REST name may hold a million keys (Python takes names of any length): the check for a
// key given twice took quadratic time (80 000 keys: 12 s; a million: hours).
TEST(Recipe, ManyRestKeysAreCheckedInLinearTime)
{
    std::string args;
    for (int i = 0; i < 200000; ++i)
        args += (i ? "&k" : "k") + std::to_string(i) + "=1";
    Recipe r = with_sample("a.png");
    std::string error;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_FALSE(apply_recipe_arguments(args, "", r, error));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20)); // a hang guard
    EXPECT_NE(error.find("k0"), std::string::npos) << error.substr(0, 200);
}

// Deeply nested JSON is refused before the parser recurses into it (it would overflow the
// stack of the process reading the recipe: stock oiiotool, through the plugin).
TEST(Recipe, DeepNestingIsRefusedBeforeParsing)
{
    Recipe r;
    std::string error;
    EXPECT_FALSE(parse_recipe(std::string(1000000, '['), "", r, error));
    EXPECT_EQ(error, "malformed JSON (nested more than 64 deep)");
    // Brackets inside strings are text.
    EXPECT_TRUE(parse_recipe(
        R"({ "sample": "[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[.png" })",
        "", r, error))
        << error;
}

// A recipe that is a FIFO or a device is refused without reading it.
TEST(Recipe, SpecialFilesAreRefused)
{
    const std::string fifo = (std::filesystem::temp_directory_path()
        / ("texsyn_recipe_fifo_" + std::to_string(::getpid()) + ".texsyn"))
                                 .string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    Recipe r;
    std::string error;
    EXPECT_FALSE(recipe_from_filename(fifo, r, error));
    EXPECT_EQ(error, fifo + ": is not a regular file (a FIFO, device or socket), not a recipe");
    std::filesystem::remove(fifo);
}

TEST(Recipe, RestArgumentsOverrideFields)
{
    Recipe r = with_sample("a.png");
    std::string error;
    ASSERT_TRUE(
        apply_recipe_arguments("seed=9&size=32x16&tocolorspace=sRGB%20-%20Texture", "", r, error))
        << error;
    EXPECT_EQ(r.seed, 9u);
    EXPECT_EQ(pyramid_options(r).width, 32);
    EXPECT_EQ(r.tocolorspace, "sRGB - Texture");
    Recipe unchanged = r;
    EXPECT_FALSE(apply_recipe_arguments("seed=1&size", "", r, error));
    EXPECT_EQ(error, "malformed argument 'size' (expected name=value)");
    EXPECT_EQ(r.seed, unchanged.seed); // nothing applied on failure
    EXPECT_FALSE(apply_recipe_arguments("size=8x8&size=16x16", "", r, error));
    EXPECT_EQ(error, "size=16x16 : given twice");
    ASSERT_TRUE(apply_recipe_arguments("sample=other.png", "/shows/a", r, error)) << error;
    EXPECT_EQ(r.samples, (std::vector<std::string> { "/shows/a/other.png" }));
    // Several samples, comma-separated; a comma in a name is %2C.
    ASSERT_TRUE(apply_recipe_arguments("sample=a.png,b%2Cc.png", "/shows/a", r, error)) << error;
    EXPECT_EQ(r.samples, (std::vector<std::string> { "/shows/a/a.png", "/shows/a/b,c.png" }));
}

TEST(Recipe, FileNamesNameARecipeFileOrASample)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(recipe_from_filename("/no/such/rust.png.texsyn?size=8x8&seed=2", r, error))
        << error;
    EXPECT_EQ(r.samples, (std::vector<std::string> { "/no/such/rust.png" }));
    EXPECT_EQ(r.seed, 2u);
    EXPECT_FALSE(recipe_from_filename("rust.png?size=8x8", r, error));
    EXPECT_EQ(error, "rust.png: a recipe's name ends in .texsyn");

    fs::path dir = fs::temp_directory_path() / "texsyn_recipe_test";
    fs::create_directories(dir);
    std::ofstream(dir / "r.texsyn") << R"({ "sample": "s.png", "seed": 4 })";
    ASSERT_TRUE(recipe_from_filename((dir / "r.texsyn").string() + "?seed=5", r, error)) << error;
    EXPECT_EQ(r.samples, (std::vector<std::string> { (dir / "s.png").string() }));
    EXPECT_EQ(r.seed, 5u);
    std::ofstream(dir / "bad.texsyn") << R"({ "sample": "s.png", "orientations": 0 })";
    EXPECT_FALSE(recipe_from_filename((dir / "bad.texsyn").string(), r, error));
    EXPECT_EQ(error, (dir / "bad.texsyn").string() + ": orientations=0 : out of range 1..8");
    fs::remove_all(dir);
}

TEST(Recipe, WrittenRecipesReadBackToTheSameRecipe)
{
    Recipe r = with_sample("/shows/a/maps/rust.png");
    std::string error;
    ASSERT_TRUE(r.options.apply("size=300x200:orientations=5", error)) << error;
    r.seed = 77;
    r.iscolorspace = { "sRGB - Texture" };
    const std::string json = json_of(r, "/shows/a");
    EXPECT_NE(json.find("\"sample\": \"maps/rust.png\""), std::string::npos) << json;
    // Outside the recipe's folder: relative all the same, and normalised.
    const std::string moved = json_of(r, "/shows/b/x/../recipes");
    EXPECT_NE(moved.find("\"sample\": \"../../a/maps/rust.png\""), std::string::npos) << moved;
    Recipe back;
    ASSERT_TRUE(parse_recipe(json, "/shows/a", back, error)) << error;
    EXPECT_EQ(back.samples, r.samples);
    EXPECT_EQ(back.iscolorspace, r.iscolorspace);
    EXPECT_EQ(back.seed, r.seed);
    EXPECT_EQ(back.options.format(), r.options.format());
}

std::string read_source_file(const std::string& path)
{
    std::ifstream in(std::string(TEXSYN_SOURCE_DIR) + "/" + path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

TEST(Recipe, TheExamplesInTheDocsParse)
{
    const std::string doc = read_source_file("docs/recipes.md");
    std::vector<Recipe> examples;
    for (size_t begin = doc.find("```json\n"); begin != std::string::npos;
         begin = doc.find("```json\n", begin + 8)) {
        const size_t end = doc.find("```", begin + 8);
        std::string json = doc.substr(begin + 8, end - begin - 8);
        Recipe r;
        std::string error;
        ASSERT_TRUE(parse_recipe(json, "", r, error)) << error << "\n" << json;
        EXPECT_TRUE(r.validate(error)) << error << "\n" << json;
        examples.push_back(r);
    }
    ASSERT_GE(examples.size(), 2u);
    EXPECT_EQ(examples[0].method, "pyramid");
    EXPECT_EQ(examples[0].options.value("size"), "2048x2048");
    EXPECT_EQ(examples[1].method, "neighborhood");
    EXPECT_EQ(examples[1].options.value("n"), "9,7,5,5");
}

TEST(Recipe, ParsesNeighborhoodRecipes)
{
    Recipe r;
    std::string error;
    // JSON objects are read in key order, here "levels" and "n" before "method": the method
    // counts wherever it stands.
    ASSERT_TRUE(parse_recipe(R"({ "sample": "grass.png", "levels": 4, "n": [9, 7, 5, 5],
        "method": "neighborhood", "size": [256, 128], "seed": 5, "search": "exhaustive",
        "eps": 0.25, "coarse": "3", "tile": 0, "shape": "square" })",
        "", r, error))
        << error;
    EXPECT_EQ(r.method, "neighborhood");
    EXPECT_EQ(r.seed, 5u);
    EXPECT_EQ(r.options.format(),
        "size=256x128:levels=4:n=9,7,5,5:coarse=3:search=exhaustive:candidates=4:dims=8:"
        "eps=0.25:coherence=1:merge=0:tile=0:flatten=0:scale=1:shape=square");
    EXPECT_TRUE(r.validate(error)) << error;
    // A list as a string or as one number, as on the command line.
    ASSERT_TRUE(parse_recipe(
        R"({ "sample": "g.png", "method": "neighborhood", "levels": 4, "n": "9,7,5,5" })", "", r,
        error))
        << error;
    EXPECT_EQ(r.options.value("n"), "9,7,5,5");
    ASSERT_TRUE(
        parse_recipe(R"({ "sample": "g.png", "method": "neighborhood", "n": 7 })", "", r, error))
        << error;
    EXPECT_EQ(r.options.value("n"), "7");
    // Lists of the pyramid method as arrays and fractional numbers too.
    ASSERT_TRUE(
        parse_recipe(R"({ "sample": "g.png", "gain": [1, 1.5], "balance": -0.5 })", "", r, error))
        << error;
    EXPECT_EQ(pyramid_options(r).gain, (std::vector<float> { 1.0f, 1.5f }));
    EXPECT_EQ(pyramid_options(r).balance, (std::vector<float> { -0.5f }));
}

TEST(Recipe, ParsesChoosyRecipes)
{
    Recipe r;
    std::string error;
    // iterations is an integer for the pyramid method and a list for choosy: the recipe's
    // method decides how an array reads, wherever "method" stands.
    ASSERT_TRUE(parse_recipe(R"({ "sample": "grass.png", "iterations": [1, 8], "levels": 3,
        "method": "choosy", "size": [256, 128], "seed": 5, "search": "exhaustive",
        "penalty": 0.5, "isotropic": 0, "dims": 12, "eps": 0.25 })",
        "", r, error))
        << error;
    EXPECT_EQ(r.method, "choosy");
    EXPECT_EQ(r.options.format(),
        "size=256x128:levels=3:iterations=1,8:penalty=0.5:isotropic=0:flatten=0:scale=1:"
        "search=exhaustive:"
        "dims=12:"
        "eps=0.25");
    EXPECT_TRUE(r.validate(error)) << error;
    EXPECT_NE(json_of(r, "").find("\"iterations\": \"1,8\""), std::string::npos);
    // The pyramid's iterations stay an integer.
    EXPECT_FALSE(parse_recipe(R"({ "sample": "g.png", "iterations": [1, 8] })", "", r, error));
    EXPECT_TRUE(parse_recipe(
        R"({ "sample": "g.png", "method": "choosy", "iterations": "1,2,3", "levels": 2 })", "", r,
        error));
    EXPECT_FALSE(r.validate(error));
    EXPECT_EQ(error, "iterations=1,2,3 : 3 values for levels=2 (give 1..2)");
    ASSERT_TRUE(apply_recipe_arguments("iterations=2&method=choosy&isotropic=0", "", r, error))
        << error;
    EXPECT_EQ(r.options.value("iterations"), "2");
}

TEST(Recipe, KeysOfAnotherMethodAreRefusedByName)
{
    Recipe r;
    std::string error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "levels": 3 })", "", r, error));
    EXPECT_EQ(error,
        "key 'levels' is an option of method neighborhood, not of this recipe's method pyramid "
        "(give method=neighborhood)");
    EXPECT_FALSE(parse_recipe(
        R"({ "sample": "a.png", "method": "neighborhood", "iterations": 3 })", "", r, error));
    EXPECT_EQ(error,
        "key 'iterations' is an option of method pyramid, not of this recipe's method "
        "neighborhood (give method=pyramid)");
    // Unknown keys list the recipe's method's options.
    EXPECT_FALSE(parse_recipe(
        R"({ "sample": "a.png", "method": "neighborhood", "octaves": 3 })", "", r, error));
    EXPECT_EQ(error.find("unknown key 'octaves' (known: texsyn_recipe, sample, method, seed, "
                         "iscolorspace, tocolorspace, colorconfig, subbands, size, levels, n,"),
        0u)
        << error;
    // The files a method writes are the tool's, not a recipe's.
    EXPECT_FALSE(parse_recipe(
        R"({ "sample": "a.png", "method": "neighborhood", "map": "m.exr" })", "", r, error));
    EXPECT_EQ(error.find("key 'map' names a file the tool writes"), 0u) << error;
    // Bad values name the key.
    const std::pair<const char*, const char*> bad[] = {
        { R"("n": [9, "x"])",
            "n: expected a number, a string \"a,b,c\" or an array of numbers, not [9,\"x\"]" },
        { R"("n": [9, 7.5])",
            "n: expected a number, a string \"a,b,c\" or an array of numbers, not [9,7.5]" },
        { R"("n": [1])", "n=1 : out of range 3..63" },
        { R"("levels": 2.5)", "levels: expected an integer or a string, not 2.5" },
        { R"("eps": true)", "eps: expected a number or a string, not true" },
        { R"("search": 1)", "search: expected a string, not 1" },
        { R"("search": "brute")", "search=brute : not one of exhaustive|tsvq|kdtree|coherent" },
        { R"("size": [64, 48.5])",
            "size: expected a string \"WxH\" or [width, height], not "
            "[64,48.5]" },
    };
    for (auto [json, message] : bad) {
        EXPECT_FALSE(parse_recipe(
            std::string(R"({ "sample": "a.png", "method": "neighborhood", )") + json + " }", "", r,
            error))
            << json;
        EXPECT_EQ(error, message);
    }
}

TEST(Recipe, RestArgumentsTakeTheMethodFirstWhereverItStands)
{
    Recipe r = with_sample("grass.png");
    std::string error;
    ASSERT_TRUE(apply_recipe_arguments(
        "size=64x48&levels=2&n=7,5&search=exhaustive&method=neighborhood&seed=4", "", r, error))
        << error;
    EXPECT_EQ(r.method, "neighborhood");
    EXPECT_EQ(r.options.value("size"), "64x48");
    EXPECT_EQ(r.options.value("levels"), "2");
    EXPECT_EQ(r.options.value("n"), "7,5");
    EXPECT_EQ(r.seed, 4u);
    // On top of a neighbourhood recipe, its options need no method=.
    ASSERT_TRUE(apply_recipe_arguments("n=9&coarse=3", "", r, error)) << error;
    EXPECT_EQ(r.options.value("n"), "9");
    Recipe unchanged = r;
    EXPECT_FALSE(apply_recipe_arguments("seed=1&iterations=2", "", r, error));
    EXPECT_EQ(error,
        "key 'iterations' is an option of method pyramid, not of this recipe's method "
        "neighborhood (give method=pyramid)");
    EXPECT_EQ(r.seed, unchanged.seed); // nothing applied on failure
    EXPECT_FALSE(apply_recipe_arguments("method=pyramid&method=neighborhood", "", r, error));
    EXPECT_EQ(error, "method=neighborhood : given twice");
    // Changing the method keeps what both methods have (size, seed); the neighbourhood
    // options are left unused.
    ASSERT_TRUE(apply_recipe_arguments("iterations=2&method=pyramid", "", r, error)) << error;
    EXPECT_EQ(r.method, "pyramid");
    EXPECT_EQ(pyramid_options(r).width, 64);
    EXPECT_EQ(pyramid_options(r).height, 48);
    EXPECT_EQ(r.seed, 4u);
    EXPECT_EQ(pyramid_options(r).iterations, 2);
    EXPECT_EQ(json_of(r, "").find("\"levels\""), std::string::npos);
    // A value only the old method takes stays behind (choosy's iterations list).
    r = with_sample("grass.png", "choosy");
    ASSERT_TRUE(apply_recipe_arguments("iterations=1,8&levels=2", "", r, error)) << error;
    ASSERT_TRUE(apply_recipe_arguments("method=pyramid", "", r, error)) << error;
    EXPECT_EQ(pyramid_options(r).iterations, 5);
}

TEST(Recipe, MethodsRefuseSubbandsAndAnalysisFilesTheyDoNotTake)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(recipe_from_filename(
        "/no/such/grass.png.texsyn?method=neighborhood&size=256x256", r, error))
        << error;
    EXPECT_EQ(r.method, "neighborhood");
    EXPECT_EQ(r.options.value("size"), "256x256");
    EXPECT_FALSE(
        recipe_from_filename("/no/such/g.png.texsyn?method=neighborhood&subbands=1", r, error));
    EXPECT_EQ(error,
        "/no/such/g.png.texsyn: subbands=1 : method neighborhood has no subbands (only "
        "pyramid, mix, transfer do)");
    EXPECT_FALSE(recipe_from_filename("/no/such/g.tsa.texsyn?method=neighborhood", r, error));
    EXPECT_EQ(error,
        "/no/such/g.tsa.texsyn: sample=/no/such/g.tsa : an analysis file (.tsa) is for the "
        "pyramid methods' samples; method neighborhood needs an image here");
    // The method's validate() runs on the whole recipe.
    EXPECT_FALSE(recipe_from_filename("/no/such/g.png.texsyn?method=neighborhood&n=8", r, error));
    EXPECT_EQ(error, "/no/such/g.png.texsyn: n=8 : not odd");
    // run_recipe checks as well, before reading anything.
    r = with_sample(std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png", "neighborhood");
    r.subbands = true;
    OIIO::ImageBuf out;
    EXPECT_FALSE(run_recipe(r, out, nullptr, error));
    EXPECT_EQ(
        error, "subbands=1 : method neighborhood has no subbands (only pyramid, mix, transfer do)");
}

TEST(Recipe, RunsANeighborhoodRecipe)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(recipe_from_filename(std::string(TEXSYN_TEST_DATA)
            + "/stucco_yellow.png.texsyn?method=neighborhood&size=24x16&levels=2&n=5,3"
              "&search=exhaustive&seed=2",
        r, error))
        << error;
    OIIO::ImageBuf out;
    std::vector<NamedImage> bands;
    ASSERT_TRUE(run_recipe(r, out, &bands, error)) << error;
    EXPECT_EQ(out.spec().width, 24);
    EXPECT_EQ(out.spec().height, 16);
    EXPECT_EQ(out.spec().get_string_attribute("synth:method"), "neighborhood");
    EXPECT_EQ(out.spec().get_int_attribute("synth:seed"), 2);
    EXPECT_EQ(out.spec().get_string_attribute("synth:sample"), "stucco_yellow.png");
    EXPECT_TRUE(bands.empty());
}

TEST(Recipe, WrittenNeighborhoodRecipesReadBackToTheSameRecipe)
{
    Recipe r = with_sample("/shows/a/grass.png", "neighborhood");
    std::string error;
    ASSERT_TRUE(r.options.apply("size=300x200:levels=3:n=9,7,5:coarse=3:search=exhaustive:"
                                "eps=0.25:tile=0:shape=square",
        error))
        << error;
    r.seed = 77;
    const std::string json = json_of(r, "/shows/a");
    EXPECT_NE(json.find("\"method\": \"neighborhood\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"seed\": 77"), std::string::npos) << json;
    EXPECT_NE(json.find("\"n\": \"9,7,5\""), std::string::npos) << json;
    EXPECT_EQ(json.find("\"iterations\""), std::string::npos) << json; // the pyramid's only
    EXPECT_EQ(json.find("\"map\""), std::string::npos) << json;        // the tool's
    Recipe back;
    ASSERT_TRUE(parse_recipe(json, "/shows/a", back, error)) << error;
    EXPECT_TRUE(back.validate(error)) << error;
    EXPECT_EQ(back.method, "neighborhood");
    EXPECT_EQ(back.samples, r.samples);
    EXPECT_EQ(back.seed, 77u);
    EXPECT_EQ(back.options.format(), r.options.format());
}

// Every method that makes images or volumes is a recipe: no sample (a generator), one, an
// image and a sample, or a list of samples.
TEST(Recipe, EveryMethodReadsItsSamples)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(parse_recipe(
        R"({ "method": "cascade", "preset": "cells", "size": [64, 32] })", "/shows/a", r, error))
        << error;
    EXPECT_TRUE(r.samples.empty());
    EXPECT_TRUE(r.validate(error)) << error;
    ASSERT_TRUE(parse_recipe(R"({ "method": "mix", "sample": ["rust.png", "marble.tsa"],
        "palette": 0, "pattern": 1, "iscolorspace": ["sRGB", ""] })",
        "/shows/a", r, error))
        << error;
    EXPECT_EQ(r.samples, (std::vector<std::string> { "/shows/a/rust.png", "/shows/a/marble.tsa" }));
    EXPECT_EQ(r.iscolorspace, (std::vector<std::string> { "sRGB", "" }));
    EXPECT_TRUE(r.validate(error)) << error;
    const std::string json = json_of(r, "/shows/a");
    EXPECT_NE(
        json.find("\"sample\": [\n    \"rust.png\",\n    \"marble.tsa\"\n  ]"), std::string::npos)
        << json;
    // The count of samples follows the options: weights= takes one per weight.
    ASSERT_TRUE(apply_recipe_arguments("palette=none&pattern=none&weights=1,1,1", "", r, error))
        << error;
    EXPECT_FALSE(r.validate(error));
    EXPECT_EQ(error,
        "method mix takes 3 samples, the recipe names 2 (\"sample\": [\"a.png\", \"b.png\", "
        "...])");
    ASSERT_TRUE(parse_recipe(
        R"({ "method": "transfer", "sample": ["photo.tsa", "rust.png"] })", "", r, error))
        << error;
    EXPECT_FALSE(r.validate(error));
    EXPECT_EQ(error,
        "sample=photo.tsa : an analysis file (.tsa) is for the pyramid methods' samples; "
        "method transfer needs an image here");
    ASSERT_TRUE(parse_recipe(R"({ "method": "transfer", "sample": "photo.png", "size": "8x8" })",
                    "", r, error)
        == false);
    EXPECT_EQ(error.find("key 'size' is an option of method pyramid"), 0u) << error;
    ASSERT_TRUE(parse_recipe(R"({ "method": "solid", "sample": "marble.png",
        "size": [32, 32, 16] })",
        "", r, error))
        << error;
    EXPECT_TRUE(r.validate(error)) << error;
}

// A generator's REST name need not exist; the cascade takes the named image if there is one.
TEST(Recipe, GeneratorNamesNeedNoSample)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(recipe_from_filename("/no/such/noise.texsyn?method=cascade&preset=stone", r, error))
        << error;
    EXPECT_TRUE(r.samples.empty());
    const std::string sample = std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png";
    ASSERT_TRUE(recipe_from_filename(sample + ".texsyn?method=cascade", r, error)) << error;
    EXPECT_EQ(r.samples, (std::vector<std::string> { sample }));
    OIIO::ImageBuf out;
    ASSERT_TRUE(run_recipe(r, out, nullptr, error)) << error;
    EXPECT_EQ(out.spec().width, 128); // the image's size
    EXPECT_EQ(out.spec().get_string_attribute("synth:sample"), "stucco_yellow.png");
}

// Files an option reads are resolved against the recipe's folder and written relative to it.
TEST(Recipe, OptionFilesAreRelativeToTheRecipe)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(parse_recipe(R"({ "method": "cascade", "dilation": "maps/ctrl.exr",
        "palette": "/abs/rust.png" })",
        "/shows/a", r, error))
        << error;
    EXPECT_EQ(r.options.value("dilation"), "/shows/a/maps/ctrl.exr");
    EXPECT_EQ(r.options.value("palette"), "/abs/rust.png");
    const std::string json = json_of(r, "/shows/a/recipes");
    EXPECT_NE(json.find("\"dilation\": \"../maps/ctrl.exr\""), std::string::npos) << json;
    EXPECT_EQ(json.find("\"rotation\""), std::string::npos) << json; // none given
}

// recipe_spec() announces what run_recipe() makes, without running it: size, depth,
// channels and metadata (synth:options as given), for every method that makes images,
// grey, RGB and RGBA samples, an analysis as a sample, and the default sizes.
TEST(Recipe, SpecIsWhatTheRunMakes)
{
    const fs::path dir = fs::temp_directory_path() / "texsyn_recipe_spec";
    fs::create_directories(dir);
    const std::string stucco = std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png";
    OIIO::ImageBuf rgb(stucco);
    OIIO::ImageBuf small = OIIO::ImageBufAlgo::resize(rgb, "", 0, OIIO::ROI(0, 61, 0, 45));
    const std::string rgb_file = (dir / "rgb.png").string();
    const std::string grey_file = (dir / "grey.png").string();
    const std::string rgba_file = (dir / "rgba.exr").string();
    ASSERT_TRUE(small.write(rgb_file));
    ASSERT_TRUE(OIIO::ImageBufAlgo::channels(small, 1, {}).write(grey_file));
    const int rgba_order[] = { 0, 1, 2, -1 };
    const float alpha[] = { 0, 0, 0, 0.5f };
    ASSERT_TRUE(OIIO::ImageBufAlgo::channels(small, 4, rgba_order, alpha).write(rgba_file));
    const std::string tsa = (dir / "rgb.tsa").string();
    {
        TextureStatistics stats;
        OIIO::ImageBuf linear(rgb_file);
        PyramidOptions opt;
        std::string error;
        ASSERT_TRUE(analyze_texture(linear, opt, stats, error)) << error;
        if (stats.colorspace.empty())
            stats.colorspace = "Linear Rec.709 (sRGB)";
        ASSERT_TRUE(write_statistics(tsa, stats, error)) << error;
    }
    struct Case {
        std::string method;
        std::vector<std::string> samples;
        std::string options;
    };
    const std::vector<Case> cases = {
        { "pyramid", { rgb_file }, "iterations=1" },
        { "pyramid", { rgba_file }, "iterations=1:size=40x24" },
        { "pyramid", { tsa }, "iterations=1" },
        { "solid", { grey_file }, "iterations=1" },
        { "mix", { rgba_file, rgba_file }, "weights=1,1:iterations=1" },
        { "mix", { rgb_file, rgb_file }, "palette=1:pattern=0:iterations=1:size=32x32" },
        { "transfer", { grey_file, grey_file }, "iterations=1" },
        { "neighborhood", { rgba_file }, "levels=2:size=24x20" },
        { "neighborhood", { rgb_file }, "levels=2:tile=0" },
        { "choosy", { rgb_file }, "levels=2" },
        { "patch", { grey_file }, "size=32x32" },
        { "cascade", {}, "size=32x16" },
        { "cascade", { rgb_file }, "ramp=0,0,0,1,1,1" },
        { "cascade", { rgba_file }, "transfer=channels" },
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.method + " " + c.options + " " + (c.samples.empty() ? "" : c.samples[0]));
        Recipe r = with_sample(c.samples.empty() ? "" : c.samples[0], c.method);
        r.samples = c.samples;
        r.seed = 3;
        std::string error;
        ASSERT_TRUE(r.options.apply(c.options, error)) << error;
        OIIO::ImageSpec announced;
        ASSERT_TRUE(recipe_spec(r, announced, error)) << error;
        OIIO::ImageBuf made;
        ASSERT_TRUE(run_recipe(r, made, nullptr, error)) << error;
        const OIIO::ImageSpec& got = made.spec();
        EXPECT_EQ(announced.width, got.width);
        EXPECT_EQ(announced.height, got.height);
        EXPECT_EQ(announced.depth, got.depth);
        EXPECT_EQ(announced.channelnames, got.channelnames);
        EXPECT_EQ(announced.alpha_channel, got.alpha_channel);
        EXPECT_EQ(announced.format, OIIO::TypeFloat);
        for (const OIIO::ParamValue& p : announced.extra_attribs) {
            if (p.name() != "synth:options") {
                EXPECT_EQ(
                    announced.get_string_attribute(p.name()), got.get_string_attribute(p.name()))
                    << p.name();
            }
        }
        for (const OIIO::ParamValue& p : got.extra_attribs)
            EXPECT_TRUE(announced.find_attribute(p.name()))
                << p.name() << " = " << got.get_string_attribute(p.name());
    }
    fs::remove_all(dir);
}

// recipe_spec() refuses what a run would refuse from the recipe and the headers alone.
TEST(Recipe, SpecRefusesWhatTheRunWould)
{
    const std::string stucco = std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png";
    Recipe r = with_sample(stucco, "choosy");
    std::string error;
    OIIO::ImageSpec spec;
    ASSERT_TRUE(r.options.apply("size=62x62:levels=3", error)) << error;
    EXPECT_FALSE(recipe_spec(r, spec, error));
    EXPECT_NE(error.find("each side must be a multiple of 4"), std::string::npos) << error;
    r = with_sample("/no/such.png");
    EXPECT_FALSE(recipe_spec(r, spec, error));
    EXPECT_NE(error.find("/no/such.png: no such file"), std::string::npos) << error;
    r = with_sample(stucco, "cascade");
    ASSERT_TRUE(r.options.apply("palette=/no/palette.png", error)) << error;
    EXPECT_FALSE(recipe_spec(r, spec, error));
    EXPECT_NE(error.find("palette=/no/palette.png : no such file"), std::string::npos) << error;
}
