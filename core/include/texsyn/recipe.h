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

#include <texsyn/choosy.h>
#include <texsyn/neighborhood.h>
#include <texsyn/synthesis.h>

namespace texsyn {

/// What `texsyn [--seed S] [--colorconfig C] SAMPLE [--iscolorspace I] --METHOD:OPTIONS
/// [--tocolorspace T] -d float -o out.exr` computes, METHOD being `method`.
struct Recipe {
    std::string sample;               ///< sample image path (resolved against the recipe's folder)
    std::string method = "pyramid";   ///< "pyramid", "neighborhood" or "choosy": which options run
    PyramidOptions pyramid;           ///< the pyramid method's options, seed included
    NeighborhoodOptions neighborhood; ///< the neighborhood method's options, seed included
    ChoosyOptions choosy;             ///< the choosy method's options, seed included
    std::string iscolorspace;         ///< "" = from the file (ColorConfig::guess_colorspace)
    std::string tocolorspace;         ///< "" = scene_linear
    std::string colorconfig;          ///< "" = $OCIO, else the bundled config
    /// The subbands are further subimages of the plugin's image (method pyramid only).
    bool subbands = false;

    /// Checks the recipe as a whole: a known method, its options (their validate()), and
    /// that subbands and an analysis file (*.tsa) as the sample come only with method
    /// pyramid. False with a message naming the key.
    bool validate(std::string& error) const;
};

/// The recipe format's version, written as "texsyn_recipe": 1.
constexpr int recipe_version = 1;

/// Reads a recipe from JSON `text`. Keys: texsyn_recipe (version, optional), sample
/// (required), method, seed, iscolorspace, tocolorspace, colorconfig, subbands, and the
/// method's options by their CLI names (numbers or strings; sizes and lists also as
/// arrays: "size": "1024x1024" or [1024, 1024], "n": "9,7" or [9, 7]). `method` is read
/// first wherever it stands; an option of several methods (size) is set for each of them;
/// an option of another method only is an error. The seed is every method's. Relative
/// `sample` and `colorconfig` paths are resolved against `base_dir`. Fails (false, `error`
/// naming the key and what was expected) on malformed JSON, unknown keys or methods, keys
/// of another method, bad values, or a newer version. Does not call Recipe::validate().
bool parse_recipe(
    const std::string& text, const std::string& base_dir, Recipe& recipe, std::string& error);

/// Applies REST-style arguments "name=value&name=value" (the same keys as the JSON,
/// %-escapes decoded) on top of `recipe`, by the same rules as parse_recipe: `method`
/// first wherever it stands, so "size=64x64&method=neighborhood" sets the neighborhood
/// size. A `method` that changes the recipe's keeps what the recipe had set for both
/// methods (size, seed, colour spaces); options of the previous method only are left
/// unused. Relative paths are resolved against `base_dir`. Fails (false, `error`; `recipe`
/// unchanged) on a piece without '=', a repeated or unknown key, a key of another method,
/// or a bad value.
bool apply_recipe_arguments(
    const std::string& arguments, const std::string& base_dir, Recipe& recipe, std::string& error);

/// The recipe named by an OIIO file name as the plugin receives it: "x.texsyn" (a JSON
/// file), "sample.png.texsyn" (no such file: the sample is "sample.png"), either followed
/// by "?REST arguments". Fails (false, `error`) if the name does not end in .texsyn, the
/// JSON file is bad, the arguments are, or the result fails Recipe::validate().
bool recipe_from_filename(const std::string& name, Recipe& recipe, std::string& error);

/// JSON text of `recipe` with every option of its method written out; `sample` and
/// `colorconfig` are made relative to `base_dir`.
std::string recipe_to_json(const Recipe& recipe, const std::string& base_dir);

/// Runs the recipe: reads the sample, converts it to scene-linear, synthesizes by
/// `method` (pyramid_synthesize, or synthesize_from_statistics for an analysis file;
/// neighborhood_synthesize; choosy_synthesize), and
/// converts the result to `tocolorspace` (colour associated with alpha, OIIO's in-memory
/// convention). `dst` is a float image with synth:* metadata (synth:sample,
/// synth:colorspace too); with `subbands` not null and recipe.subbands set, the subbands
/// are returned as well. Fails (false, `error`, prefixed by the sample's file name where
/// the sample is at fault) if Recipe::validate() does or the synthesis does.
bool run_recipe(const Recipe& recipe, OIIO::ImageBuf& dst, std::vector<NamedImage>* subbands,
    std::string& error);

} // namespace texsyn
