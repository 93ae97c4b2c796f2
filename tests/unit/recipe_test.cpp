// SPDX-License-Identifier: Apache-2.0
#include <texsyn/recipe.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "recipe/recipe_pvt.h"

using namespace texsyn;
namespace fs = std::filesystem;

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
    EXPECT_EQ(r.sample, "/shows/a/maps/rust.png");
    EXPECT_EQ(r.colorconfig, "/shows/a/cfg.ocio");
    EXPECT_EQ(r.pyramid.seed, 12u);
    EXPECT_EQ(r.pyramid.width, 640);
    EXPECT_EQ(r.pyramid.height, 480);
    EXPECT_EQ(r.pyramid.iterations, 3);
    EXPECT_EQ(r.pyramid.pyramid, PyramidKind::Laplacian);
    EXPECT_EQ(r.pyramid.scales, 2);
    EXPECT_EQ(r.pyramid.orientations, 6);
    EXPECT_EQ(r.pyramid.histogram, HistogramMode::Bins256);
    EXPECT_EQ(r.iscolorspace, "sRGB");
    EXPECT_EQ(r.tocolorspace, "ACEScg");
    EXPECT_TRUE(r.subbands);
    ASSERT_TRUE(parse_recipe(R"({ "sample": "/abs/rust.png" })", "/shows/a", r, error));
    EXPECT_EQ(r.sample, "/abs/rust.png");
}

TEST(Recipe, RejectsBadRecipesNamingTheProblem)
{
    Recipe r;
    std::string error;
    EXPECT_FALSE(parse_recipe("{ \"sample\": ", "", r, error));
    EXPECT_EQ(error.find("malformed JSON (parse error"), 0u) << error;
    EXPECT_FALSE(parse_recipe("[1, 2]", "", r, error));
    EXPECT_EQ(error, "a recipe is a JSON object ({ \"sample\": ..., ... })");
    EXPECT_FALSE(parse_recipe("{ \"size\": \"8x8\" }", "", r, error));
    EXPECT_EQ(error, "the recipe names no sample (\"sample\": \"file.png\")");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "octaves": 3 })", "", r, error));
    EXPECT_EQ(error.find("unknown key 'octaves' (known: texsyn_recipe, sample"), 0u) << error;
    EXPECT_NE(error.find("subbands, size, iterations,"), std::string::npos) << error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "texsyn_recipe": 2 })", "", r, error));
    EXPECT_EQ(error, "texsyn_recipe=2 is newer than this texsyn reads (version 1)");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "method": "quilting" })", "", r, error));
    EXPECT_EQ(error, "method=quilting is not one of pyramid|neighborhood|choosy");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "seed": -1 })", "", r, error));
    EXPECT_EQ(error, "seed=-1 is out of range (0..2147483647)");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "size": 3.5 })", "", r, error));
    EXPECT_EQ(error.find("size: expected a string"), 0u) << error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "subbands": "maybe" })", "", r, error));
    EXPECT_FALSE(parse_recipe(R"({ "sample": 5 })", "", r, error));
    EXPECT_EQ(error, "sample: expected a string, not 5");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "seed": true })", "", r, error));
    EXPECT_EQ(error, "seed: expected an integer or a string, not true");
    EXPECT_FALSE(
        parse_recipe(R"({ "sample": "a.png", "seed": 18446744073709551615 })", "", r, error));
    EXPECT_EQ(error, "seed=18446744073709551615 is not an integer");
}

TEST(Recipe, RestArgumentsOverrideFields)
{
    Recipe r;
    r.sample = "a.png";
    std::string error;
    ASSERT_TRUE(
        apply_recipe_arguments("seed=9&size=32x16&tocolorspace=sRGB%20-%20Texture", "", r, error))
        << error;
    EXPECT_EQ(r.pyramid.seed, 9u);
    EXPECT_EQ(r.pyramid.width, 32);
    EXPECT_EQ(r.tocolorspace, "sRGB - Texture");
    Recipe unchanged = r;
    EXPECT_FALSE(apply_recipe_arguments("seed=1&size", "", r, error));
    EXPECT_EQ(error, "malformed argument 'size' (expected name=value)");
    EXPECT_EQ(r.pyramid.seed, unchanged.pyramid.seed); // nothing applied on failure
    EXPECT_FALSE(apply_recipe_arguments("size=8x8&size=16x16", "", r, error));
    EXPECT_EQ(error, "size is given twice");
    ASSERT_TRUE(apply_recipe_arguments("sample=other.png", "/shows/a", r, error)) << error;
    EXPECT_EQ(r.sample, "/shows/a/other.png");
}

TEST(Recipe, FileNamesNameARecipeFileOrASample)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(recipe_from_filename("/no/such/rust.png.texsyn?size=8x8&seed=2", r, error))
        << error;
    EXPECT_EQ(r.sample, "/no/such/rust.png");
    EXPECT_EQ(r.pyramid.seed, 2u);
    EXPECT_FALSE(recipe_from_filename("rust.png?size=8x8", r, error));
    EXPECT_EQ(error, "rust.png: a recipe's name ends in .texsyn");

    fs::path dir = fs::temp_directory_path() / "texsyn_recipe_test";
    fs::create_directories(dir);
    std::ofstream(dir / "r.texsyn") << R"({ "sample": "s.png", "seed": 4 })";
    ASSERT_TRUE(recipe_from_filename((dir / "r.texsyn").string() + "?seed=5", r, error)) << error;
    EXPECT_EQ(r.sample, (dir / "s.png").string());
    EXPECT_EQ(r.pyramid.seed, 5u);
    std::ofstream(dir / "bad.texsyn") << R"({ "sample": "s.png", "orientations": 0 })";
    EXPECT_FALSE(recipe_from_filename((dir / "bad.texsyn").string(), r, error));
    EXPECT_EQ(error, (dir / "bad.texsyn").string() + ": orientations=0 is out of range (1..8)");
    fs::remove_all(dir);
}

TEST(Recipe, WrittenRecipesReadBackToTheSameRecipe)
{
    Recipe r;
    r.sample = "/shows/a/maps/rust.png";
    r.pyramid.width = 300;
    r.pyramid.height = 200;
    r.pyramid.seed = 77;
    r.pyramid.orientations = 5;
    r.iscolorspace = "sRGB - Texture";
    const std::string json = recipe_to_json(r, "/shows/a");
    EXPECT_NE(json.find("\"sample\": \"maps/rust.png\""), std::string::npos) << json;
    // Outside the recipe's folder: relative all the same, and normalised.
    const std::string moved = recipe_to_json(r, "/shows/b/x/../recipes");
    EXPECT_NE(moved.find("\"sample\": \"../../a/maps/rust.png\""), std::string::npos) << moved;
    Recipe back;
    std::string error;
    ASSERT_TRUE(parse_recipe(json, "/shows/a", back, error)) << error;
    EXPECT_EQ(back.sample, r.sample);
    EXPECT_EQ(back.iscolorspace, r.iscolorspace);
    EXPECT_EQ(back.pyramid.seed, r.pyramid.seed);
    EXPECT_EQ(
        PyramidOptions::table().format(back.pyramid), PyramidOptions::table().format(r.pyramid));
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
    ASSERT_EQ(examples.size(), 2u);
    EXPECT_EQ(examples[0].method, "pyramid");
    EXPECT_EQ(examples[0].pyramid.width, 2048);
    EXPECT_EQ(examples[1].method, "neighborhood");
    EXPECT_EQ(examples[1].neighborhood.n, (std::vector<int> { 9, 7, 5, 5 }));
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
    EXPECT_EQ(r.neighborhood.levels, 4);
    EXPECT_EQ(r.neighborhood.n, (std::vector<int> { 9, 7, 5, 5 }));
    EXPECT_EQ(r.neighborhood.width, 256);
    EXPECT_EQ(r.neighborhood.height, 128);
    EXPECT_EQ(r.neighborhood.seed, 5u);
    EXPECT_EQ(r.neighborhood.search, SearchMethod::Exhaustive);
    EXPECT_EQ(r.neighborhood.eps, 0.25f);
    EXPECT_EQ(r.neighborhood.coarse, 3);
    EXPECT_EQ(r.neighborhood.tile, 0);
    EXPECT_EQ(r.neighborhood.shape, NeighborhoodShape::Square);
    EXPECT_TRUE(r.validate(error)) << error;
    // A list as a string or as one number, as on the command line.
    ASSERT_TRUE(parse_recipe(
        R"({ "sample": "g.png", "method": "neighborhood", "levels": 4, "n": "9,7,5,5" })", "", r,
        error))
        << error;
    EXPECT_EQ(r.neighborhood.n, (std::vector<int> { 9, 7, 5, 5 }));
    ASSERT_TRUE(
        parse_recipe(R"({ "sample": "g.png", "method": "neighborhood", "n": 7 })", "", r, error))
        << error;
    EXPECT_EQ(r.neighborhood.n, (std::vector<int> { 7 }));
    // Lists of the pyramid method as arrays and fractional numbers too.
    ASSERT_TRUE(
        parse_recipe(R"({ "sample": "g.png", "gain": [1, 1.5], "balance": -0.5 })", "", r, error))
        << error;
    EXPECT_EQ(r.pyramid.gain, (std::vector<float> { 1.0f, 1.5f }));
    EXPECT_EQ(r.pyramid.balance, (std::vector<float> { -0.5f }));
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
    EXPECT_EQ(r.choosy.iterations, (std::vector<int> { 1, 8 }));
    EXPECT_EQ(r.choosy.levels, 3);
    EXPECT_EQ(r.choosy.width, 256);
    EXPECT_EQ(r.choosy.height, 128);
    EXPECT_EQ(r.choosy.seed, 5u);
    EXPECT_EQ(r.choosy.search, ChoosySearch::Exhaustive);
    EXPECT_EQ(r.choosy.penalty, 0.5f);
    EXPECT_EQ(r.choosy.isotropic, 0);
    EXPECT_EQ(r.choosy.dims, 12);
    EXPECT_EQ(r.choosy.eps, 0.25f);
    EXPECT_TRUE(r.validate(error)) << error;
    EXPECT_NE(recipe_to_json(r, "").find("\"iterations\": \"1,8\""), std::string::npos);
    // The pyramid's iterations stay an integer.
    EXPECT_FALSE(parse_recipe(R"({ "sample": "g.png", "iterations": [1, 8] })", "", r, error));
    EXPECT_TRUE(parse_recipe(
        R"({ "sample": "g.png", "method": "choosy", "iterations": "1,2,3", "levels": 2 })", "", r,
        error));
    EXPECT_FALSE(r.validate(error));
    EXPECT_EQ(error, "iterations=1,2,3 has 3 values for levels=2 (give 1..2)");
    ASSERT_TRUE(apply_recipe_arguments("iterations=2&method=choosy&isotropic=0", "", r, error))
        << error;
    EXPECT_EQ(r.choosy.iterations, (std::vector<int> { 2 }));
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
    // Bad values name the key.
    const std::pair<const char*, const char*> bad[] = {
        { R"("n": [9, "x"])",
            "n: expected a number, a string \"a,b,c\" or an array of numbers, not [9,\"x\"]" },
        { R"("n": [9, 7.5])",
            "n: expected a number, a string \"a,b,c\" or an array of numbers, not [9,7.5]" },
        { R"("n": [1])", "n=1 : 1 is out of range (3..63)" },
        { R"("levels": 2.5)", "levels: expected an integer or a string, not 2.5" },
        { R"("eps": true)", "eps: expected a number or a string, not true" },
        { R"("search": 1)", "search: expected a string, not 1" },
        { R"("search": "brute")", "search=brute is not one of exhaustive|tsvq|kdtree|coherent" },
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
    Recipe r;
    r.sample = "grass.png";
    std::string error;
    ASSERT_TRUE(apply_recipe_arguments(
        "size=64x48&levels=2&n=7,5&search=exhaustive&method=neighborhood&seed=4", "", r, error))
        << error;
    EXPECT_EQ(r.method, "neighborhood");
    EXPECT_EQ(r.neighborhood.width, 64);
    EXPECT_EQ(r.neighborhood.levels, 2);
    EXPECT_EQ(r.neighborhood.n, (std::vector<int> { 7, 5 }));
    EXPECT_EQ(r.neighborhood.seed, 4u);
    // On top of a neighbourhood recipe, its options need no method=.
    ASSERT_TRUE(apply_recipe_arguments("n=9&coarse=3", "", r, error)) << error;
    EXPECT_EQ(r.neighborhood.n, (std::vector<int> { 9 }));
    Recipe unchanged = r;
    EXPECT_FALSE(apply_recipe_arguments("seed=1&iterations=2", "", r, error));
    EXPECT_EQ(error,
        "key 'iterations' is an option of method pyramid, not of this recipe's method "
        "neighborhood (give method=pyramid)");
    EXPECT_EQ(r.neighborhood.seed, unchanged.neighborhood.seed); // nothing applied on failure
    EXPECT_FALSE(apply_recipe_arguments("method=pyramid&method=neighborhood", "", r, error));
    EXPECT_EQ(error, "method is given twice");
    // Changing the method keeps what both methods have (size, seed); the neighbourhood
    // options are left unused.
    ASSERT_TRUE(apply_recipe_arguments("iterations=2&method=pyramid", "", r, error)) << error;
    EXPECT_EQ(r.method, "pyramid");
    EXPECT_EQ(r.pyramid.width, 64);
    EXPECT_EQ(r.pyramid.height, 48);
    EXPECT_EQ(r.pyramid.seed, 4u);
    EXPECT_EQ(r.pyramid.iterations, 2);
    EXPECT_EQ(recipe_to_json(r, "").find("\"levels\""), std::string::npos);
}

TEST(Recipe, NeighborhoodRecipesRefuseSubbandsAndAnalysisFiles)
{
    Recipe r;
    std::string error;
    ASSERT_TRUE(recipe_from_filename(
        "/no/such/grass.png.texsyn?method=neighborhood&size=256x256", r, error))
        << error;
    EXPECT_EQ(r.method, "neighborhood");
    EXPECT_EQ(r.neighborhood.width, 256);
    EXPECT_FALSE(
        recipe_from_filename("/no/such/g.png.texsyn?method=neighborhood&subbands=1", r, error));
    EXPECT_EQ(error,
        "/no/such/g.png.texsyn: subbands=1 : method neighborhood has no subbands (only method "
        "pyramid does)");
    EXPECT_FALSE(recipe_from_filename("/no/such/g.tsa.texsyn?method=neighborhood", r, error));
    EXPECT_EQ(error,
        "/no/such/g.tsa.texsyn: sample=/no/such/g.tsa : an analysis file (.tsa) is for method "
        "pyramid only; method neighborhood needs a sample image");
    // The method's validate() runs on the whole recipe.
    EXPECT_FALSE(recipe_from_filename("/no/such/g.png.texsyn?method=neighborhood&n=8", r, error));
    EXPECT_EQ(error, "/no/such/g.png.texsyn: n=8 : 8 is not an odd width in 3..63");
    // run_recipe checks as well, before reading anything.
    r = Recipe();
    r.sample = std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png";
    r.method = "neighborhood";
    r.subbands = true;
    OIIO::ImageBuf out;
    EXPECT_FALSE(run_recipe(r, out, nullptr, error));
    EXPECT_EQ(error, "subbands=1 : method neighborhood has no subbands (only method pyramid does)");
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
    Recipe r;
    r.sample = "/shows/a/grass.png";
    r.method = "neighborhood";
    NeighborhoodOptions& o = r.neighborhood;
    o.width = 300;
    o.height = 200;
    o.seed = 77;
    o.levels = 3;
    o.n = { 9, 7, 5 };
    o.coarse = 3;
    o.search = SearchMethod::Exhaustive;
    o.eps = 0.25f;
    o.tile = 0;
    o.shape = NeighborhoodShape::Square;
    const std::string json = recipe_to_json(r, "/shows/a");
    EXPECT_NE(json.find("\"method\": \"neighborhood\""), std::string::npos) << json;
    EXPECT_NE(json.find("\"seed\": 77"), std::string::npos) << json;
    EXPECT_NE(json.find("\"n\": \"9,7,5\""), std::string::npos) << json;
    EXPECT_EQ(json.find("\"iterations\""), std::string::npos) << json; // the pyramid's only
    Recipe back;
    std::string error;
    ASSERT_TRUE(parse_recipe(json, "/shows/a", back, error)) << error;
    EXPECT_TRUE(back.validate(error)) << error;
    EXPECT_EQ(back.method, "neighborhood");
    EXPECT_EQ(back.sample, r.sample);
    EXPECT_EQ(back.neighborhood.seed, 77u);
    EXPECT_EQ(NeighborhoodOptions::table().format(back.neighborhood),
        NeighborhoodOptions::table().format(r.neighborhood));
}

// docs/recipe.schema.json cannot be generated from the option tables, so this checks it
// against them: every option of every method, its allowed range or choices, and the keys
// each method's branch allows. (tests/docs/check_recipe_schema.py validates recipes with it.)
TEST(Recipe, TheSchemaAgreesWithTheOptionTables)
{
    const nlohmann::json schema
        = nlohmann::json::parse(read_source_file("docs/recipe.schema.json"));
    const nlohmann::json& properties = schema.at("properties");
    const std::vector<std::string> recipe_keys = { "texsyn_recipe", "sample", "method", "seed",
        "iscolorspace", "tocolorspace", "colorconfig", "subbands" };
    std::vector<std::string> methods;
    detail::for_each_recipe_method([&](const char* method, auto member) {
        methods.push_back(method);
        // An option several methods have is defined once; a method's branch may narrow it.
        const nlohmann::json* branch = nullptr;
        for (const nlohmann::json& b : schema.at("allOf"))
            if (b.at("if").at("properties").at("method").at("const") == method)
                branch = &b.at("then");
        ASSERT_TRUE(branch) << "no allOf branch for method " << method;
        std::vector<std::string> keys = recipe_keys;
        for (const auto& f : detail::table_of(member).fields()) {
            keys.push_back(f.name);
            ASSERT_TRUE(properties.contains(f.name)) << method << " option " << f.name;
            const nlohmann::json& p
                = branch->contains("properties") && branch->at("properties").contains(f.name)
                ? branch->at("properties").at(f.name)
                : properties.at(f.name);
            if (f.type == OptionType::Choice) {
                std::vector<std::string> choices;
                std::stringstream allowed(f.allowed);
                for (std::string c; std::getline(allowed, c, '|');)
                    choices.push_back(c);
                EXPECT_EQ(p.at("enum").get<std::vector<std::string>>(), choices)
                    << method << " " << f.name;
            } else if (f.type == OptionType::Integer || f.type == OptionType::Real) {
                const std::string range = f.allowed.substr(0, f.allowed.find('|')); // "lo..hi"
                const size_t dots = range.find("..");
                EXPECT_EQ(p.at("minimum").dump(), range.substr(0, dots)) << method << " " << f.name;
                EXPECT_EQ(p.at("maximum").dump(), range.substr(dots + 2))
                    << method << " " << f.name;
            }
        }
        auto names = branch->at("propertyNames").at("enum");
        EXPECT_EQ(names.get<std::vector<std::string>>(), keys) << method;
    });
    EXPECT_EQ(properties.at("method").at("enum").get<std::vector<std::string>>(), methods);
}
