// SPDX-License-Identifier: Apache-2.0
#include <texsyn/recipe.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

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
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "levels": 3 })", "", r, error));
    EXPECT_EQ(error.find("unknown key 'levels' (known: texsyn_recipe, sample"), 0u) << error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "texsyn_recipe": 2 })", "", r, error));
    EXPECT_EQ(error, "texsyn_recipe=2 is newer than this texsyn reads (version 1)");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "method": "quilting" })", "", r, error));
    EXPECT_EQ(error, "method=quilting is not one of pyramid");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "seed": -1 })", "", r, error));
    EXPECT_EQ(error, "seed=-1 is out of range (0..2147483647)");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "size": 3.5 })", "", r, error));
    EXPECT_EQ(error.find("size: expected a string"), 0u) << error;
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "subbands": "maybe" })", "", r, error));
    EXPECT_FALSE(parse_recipe(R"({ "sample": 5 })", "", r, error));
    EXPECT_EQ(error, "sample: expected a string, not 5");
    EXPECT_FALSE(parse_recipe(R"({ "sample": "a.png", "seed": true })", "", r, error));
    EXPECT_EQ(error, "seed: expected a number or a string, not true");
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

TEST(Recipe, TheExampleInTheDocsParses)
{
    std::ifstream in(std::string(TEXSYN_SOURCE_DIR) + "/docs/recipes.md");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string doc = ss.str();
    const size_t begin = doc.find("```json\n");
    ASSERT_NE(begin, std::string::npos);
    const size_t end = doc.find("```", begin + 8);
    std::string json = doc.substr(begin + 8, end - begin - 8);
    Recipe r;
    std::string error;
    ASSERT_TRUE(parse_recipe(json, "", r, error)) << error << "\n" << json;
    EXPECT_EQ(r.pyramid.width, 2048);
}
