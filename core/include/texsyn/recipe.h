// SPDX-License-Identifier: Apache-2.0
// Synthesis recipes (DESIGN.md "Recipes"): a method of the registry (methods.h), its
// samples, options, seed and colour spaces — everything needed to make one texture — as a
// JSON file (`*.texsyn`) or as REST arguments (`rust.png.texsyn?size=2048x2048&seed=7`).
// The OIIO format plugin opens recipes as images; `texsyn --recipe` writes them.
// docs/recipes.md documents the format and docs/recipe.schema.json (generated from the
// registry) is its JSON schema.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/methods.h>
#include <texsyn/subbands.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// What `texsyn [--seed S] [--colorconfig C] SAMPLE… [--iscolorspace I] --METHOD:OPTIONS
/// [--tocolorspace T] -d float -o out.exr` computes, METHOD being `method`.
struct Recipe {
    std::string method = "pyramid"; ///< a registry row that makes images or volumes
    /// The method's inputs in the order the tool pushes them: sample images or analysis
    /// files (paths resolved against the recipe's folder); none for a generator.
    std::vector<std::string> samples;
    /// The colour space of the samples: none (each from its file,
    /// ColorConfig::guess_colorspace), one for all, or one per sample ("" = from the file).
    std::vector<std::string> iscolorspace;
    MethodOptions options;    ///< the method's options (its defaults unless given)
    uint64_t seed = 0;        ///< the tool's --seed
    std::string tocolorspace; ///< "" = scene_linear
    std::string colorconfig;  ///< "" = $OCIO, else the bundled config
    /// The subbands are further subimages of the plugin's image (methods with subbands).
    bool subbands = false;
    /// The options given in the file or arguments, as text, in order: what a change of
    /// `method` by REST arguments carries over to the new method (those it has).
    std::vector<std::pair<std::string, std::string>> given;

    /// The row of `method`, or null.
    const Method* row() const { return find_method(method); }

    /// Checks the recipe as a whole: a method that makes images or volumes, its options
    /// (validate()), as many samples as it takes (analysis files only where it takes
    /// them), as many colour spaces as samples (or one), and subbands only for a method
    /// that has them. False with a message naming the key.
    bool validate(std::string& error) const;
};

/// The recipe format's version, written as "texsyn_recipe": 1.
constexpr int recipe_version = 1;

/// The longest recipe texsyn reads (1 MB; a recipe is a few hundred bytes): a longer file
/// is refused from its size, before it is read.
constexpr size_t kMaxRecipeBytes = size_t(1) << 20;

/// False (with "FILE: is 10.0 GB, more than a recipe can be (1.0 MB)") if the file
/// `filename` is larger than kMaxRecipeBytes; checked from its size, without reading it.
bool check_recipe_file_size(const std::string& filename, std::string& error);

/// Reads a recipe from JSON `text`. Keys: texsyn_recipe (version, optional), sample (a
/// string, or an array of strings for several; absent for a generator), method, seed,
/// iscolorspace (a string, or an array, one per sample), tocolorspace, colorconfig,
/// subbands, and the method's options by their CLI names (numbers or strings; sizes and
/// lists also as arrays: "size": "1024x1024" or [1024, 1024], "n": "9,7" or [9, 7]).
/// `method` is read first wherever it stands; an option of another method only is an
/// error naming that method. Relative paths (samples, colorconfig, the options' input
/// files) are resolved against `base_dir`. Fails (false, `error` naming the key and what
/// was expected) on malformed JSON, unknown keys or methods, keys of another method, bad
/// values, a newer version, or text longer than kMaxRecipeBytes. Does not call
/// Recipe::validate().
bool parse_recipe(
    const std::string& text, const std::string& base_dir, Recipe& recipe, std::string& error);

/// Applies REST-style arguments "name=value&name=value" (the same keys as the JSON,
/// %-escapes decoded; `sample` a comma-separated list) on top of `recipe`, by the same
/// rules as parse_recipe: `method` first wherever it stands. A `method` that changes the
/// recipe's starts from the new method's defaults and carries over the options the recipe
/// gave that the new method has and takes (size, …); the others are left unused. Relative
/// paths are resolved against `base_dir`. Fails (false, `error`; `recipe` unchanged) on a
/// piece without '=', a repeated or unknown key, a key of another method, or a bad value.
bool apply_recipe_arguments(
    const std::string& arguments, const std::string& base_dir, Recipe& recipe, std::string& error);

/// The recipe named by an OIIO file name as the plugin receives it: "x.texsyn" (a JSON
/// file), "sample.png.texsyn" (no such file: the sample is "sample.png"; for a method that
/// takes no sample, or one only if it exists, e.g. "noise.texsyn?method=cascade", none),
/// either followed by "?REST arguments". Fails (false, `error`) if the name does not end
/// in .texsyn, the JSON file is bad or larger than kMaxRecipeBytes (checked before reading
/// it), the arguments are, or the result fails Recipe::validate().
bool recipe_from_filename(const std::string& name, Recipe& recipe, std::string& error);

/// How deep recipes may nest (a recipe whose sample or input file is a recipe, ...) by
/// default; $TEXSYN_MAX_RECIPE_DEPTH (1 to 64) overrides it.
constexpr int kDefaultMaxRecipeDepth = 8;

/// How many syntheses one recipe may trigger by default, itself and every recipe it
/// nests, each use counted (a mix of 16 recipes each mixing 3 is 1 + 16 + 48 = 65);
/// $TEXSYN_MAX_RECIPE_SYNTHESES (1 to 1000000) overrides it.
constexpr int kDefaultMaxRecipeSyntheses = 64;

/// Bounds the work a recipe can ask for before any of it starts: walks the recipes it
/// nests (samples and input files named *.texsyn, read as recipe_from_filename() reads
/// them, nothing else: no image is read or hashed), depth first in file order, and fails
/// (false, `error` naming the nested recipe file where a limit was passed, the limit and
/// the variable that raises it) if
/// they nest deeper than the depth limit (a recipe that uses itself) or would run more
/// syntheses than the synthesis limit, if a nested recipe is bad, or if a limit variable
/// holds anything but a whole number in its range. The walk stops at the limit: its cost
/// is bounded by it. run_recipe(), recipe_spec() and the plugin call it for the outermost
/// recipe.
bool check_recipe_work(const Recipe& recipe, std::string& error);

/// Sets `json` to the JSON text of `recipe` with every option of its method written out (but
/// output files); paths (samples, colorconfig, input files) are made relative to `base_dir`.
/// False (with the reason in `error`) if a name is not valid UTF-8: Linux file names may be
/// bytes, and JSON text cannot hold them.
bool recipe_to_json(
    const Recipe& recipe, const std::string& base_dir, std::string& json, std::string& error);

/// Runs the recipe as the `texsyn` tool runs the same command line: reads the samples
/// (read_sample: scene-linear, analysis files as they are) and the options' input files,
/// runs the method (run_method), and converts the result to `tocolorspace` (colour
/// associated with alpha, OIIO's in-memory convention; a volume stays un-associated, as
/// its files keep it). `dst` is a float image — 3-D for a volume (spec.depth slices) —
/// with synth:* metadata (synth:sample, synth:colorspace too); with `subbands` not null
/// and recipe.subbands set, the subbands are returned as well. Fails (false, `error`,
/// prefixed by the sample's file name where the sample is at fault) if
/// Recipe::validate() does or the synthesis does. `control` gives the run's threads and
/// progress and stop flag (RunSettings::nthreads, ::progress, ::stop; its other members
/// are the recipe's).
bool run_recipe(const Recipe& recipe, OIIO::ImageBuf& dst, std::vector<NamedImage>* subbands,
    std::string& error, const RunSettings& control = {});

/// What run_recipe() will give, without running it: the spec of its result (size, depth,
/// channels, float, and the synth:* metadata, synth:options as the recipe gives them,
/// oiio:ColorSpace and wrapmodes "periodic,periodic" for a result that tiles), from the
/// samples' headers and analyses (no pixel decoded). Fails (false, `error`) where
/// run_recipe() would fail before synthesizing: a bad recipe, config or colour space, a
/// missing or unreadable sample or input file, a sample beyond the memory limit.
bool recipe_spec(const Recipe& recipe, OIIO::ImageSpec& spec, std::string& error);

/// run_recipe()'s result as the subimages of an image file, as the OIIO plugin serves
/// them: the synthesis ("synth"), or a volume's z slices ("z0000", …: volume_exr_part_name),
/// then with recipe.subbands the subbands (named as in subbands.md, colour associated
/// with alpha); each a float image with that "oiio:subimagename", the synthesis's synth:*
/// metadata and no other, all with one display window (the largest part's).
/// With $TEXSYN_CACHE naming a folder (docs/cache.md) the result comes from the on-disk
/// cache when it holds it intact, the same pixels bit for bit; else it is synthesized —
/// once for all the processes and threads that ask for it at the same time: the others
/// wait, then read it — and stored. The cache never makes this fail: where it cannot be
/// used (the folder cannot be made, an entry is damaged, a disk is full) a one-line
/// warning goes to stderr, once per process, and the result is synthesized.
/// $TEXSYN_CACHE_VERBOSE=1 writes a line per lookup to stderr ("texsyn cache: hit KEY
/// (pyramid rust.png)", "miss …, synthesizing", "stored KEY"). Fails (false, `error`) as
/// run_recipe() does.
bool recipe_images(const Recipe& recipe, std::vector<OIIO::ImageBuf>& images, std::string& error);

} // namespace texsyn
#pragma GCC visibility pop
