// SPDX-License-Identifier: Apache-2.0
// Synthesis recipes (DESIGN.md "Recipes"): a sample, a method, its options, a seed and
// colour spaces — everything needed to make one texture — as a JSON file (`*.texsyn`) or
// as REST arguments (`rust.png.texsyn?size=2048x2048&seed=7`). The OIIO format plugin
// opens recipes as images; `texsyn --recipe` writes them. docs/recipes.md documents the
// format and docs/recipe.schema.json is its JSON schema.
#pragma once

#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/synthesis.h>

namespace texsyn {

/// What `texsyn [--seed S] [--colorconfig C] SAMPLE [--iscolorspace I] --pyramid:OPTIONS
/// [--tocolorspace T] -d float -o out.exr` computes.
struct Recipe {
    std::string sample; ///< sample image path (resolved against the recipe's folder)
    std::string method = "pyramid";
    PyramidOptions pyramid;   ///< the method's options, seed included
    std::string iscolorspace; ///< "" = from the file (ColorConfig::guess_colorspace)
    std::string tocolorspace; ///< "" = scene_linear
    std::string colorconfig;  ///< "" = $OCIO, else the bundled config
    bool subbands = false;    ///< the subbands are further subimages of the plugin's image
};

/// The recipe format's version, written as "texsyn_recipe": 1.
constexpr int recipe_version = 1;

/// Reads a recipe from JSON `text`. Keys: texsyn_recipe (version, optional), sample
/// (required), method, seed, iscolorspace, tocolorspace, colorconfig, subbands, and the
/// method's options by their CLI names (numbers or strings: "size": "1024x1024" or
/// [1024, 1024]). Relative `sample` and `colorconfig` paths are resolved against
/// `base_dir`. Fails (false, `error` naming the key and what was expected) on malformed
/// JSON, unknown keys or methods, bad values, or a newer version.
bool parse_recipe(
    const std::string& text, const std::string& base_dir, Recipe& recipe, std::string& error);

/// Applies REST-style arguments "name=value&name=value" (the same keys as the JSON,
/// %-escapes decoded) on top of `recipe`; relative paths are resolved against `base_dir`.
/// Fails (false, `error`; `recipe` unchanged) on a piece without '=', a repeated or unknown
/// key, or a bad value.
bool apply_recipe_arguments(
    const std::string& arguments, const std::string& base_dir, Recipe& recipe, std::string& error);

/// The recipe named by an OIIO file name as the plugin receives it: "x.texsyn" (a JSON
/// file), "sample.png.texsyn" (no such file: the sample is "sample.png"), either followed
/// by "?REST arguments". Fails (false, `error`) if the name does not end in .texsyn, the
/// JSON file is bad, or the arguments are.
bool recipe_from_filename(const std::string& name, Recipe& recipe, std::string& error);

/// JSON text of `recipe` with every option written out; `sample` and `colorconfig` are
/// made relative to `base_dir` when they are below it.
std::string recipe_to_json(const Recipe& recipe, const std::string& base_dir);

/// Runs the recipe: reads the sample, converts it to scene-linear, synthesizes, and
/// converts the result to `tocolorspace` (colour associated with alpha, OIIO's in-memory
/// convention). `dst` is a float image with synth:* metadata (synth:sample,
/// synth:colorspace too); with `subbands` not null and recipe.subbands set, the subbands
/// are returned as well. Fails (false, `error`, prefixed by the sample's file name where
/// the sample is at fault).
bool run_recipe(const Recipe& recipe, OIIO::ImageBuf& dst, std::vector<NamedImage>* subbands,
    std::string& error);

} // namespace texsyn
