// SPDX-License-Identifier: Apache-2.0
// The state of one `texsyn` run: global options and the image stack (oiiotool's model).
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/cascade.h>
#include <texsyn/choosy.h>
#include <texsyn/color.h>
#include <texsyn/neighborhood.h>
#include <texsyn/recipe.h>
#include <texsyn/synthesis.h>

namespace texsyn::cli {

/// An error to report as "texsyn ERROR: <what>" with exit code 1.
struct CliError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// One item on the stack: an image (float, scene-linear pixels in `buf`), an analysis
/// (`statistics` set, `buf` empty) read from a .tsa file or made by --analyze, or a solid
/// texture (`volume` set, `buf` empty) made by --solid.
struct StackImage {
    OIIO::ImageBuf buf;
    std::shared_ptr<const TextureStatistics> statistics;
    std::shared_ptr<PlanarVolume> volume;
    OIIO::ImageBuf file_pixels; ///< an input's pixels as read (for --iscolorspace)
    OIIO::TypeDesc input_format = OIIO::TypeUInt8; ///< the sample file's pixel type
    /// The file it was read from, or the sample file(s) a synthesis came from.
    std::vector<std::string> sources;
    bool from_file = false;           ///< an input file, or made from one by --analyze
    std::string input_colorspace;     ///< the space the sample file was in
    std::string output_colorspace;    ///< set by --tocolorspace; "" = default policy
    std::vector<NamedImage> subbands; ///< filled when --subbands is on
    bool has_recipe = false;          ///< a synthesis of a sample file: `recipe` describes it
    Recipe recipe;
};

struct CliState {
    // Global options.
    uint64_t seed = 0;
    int threads = 0;
    bool verbose = false;
    bool subbands = false;
    bool progress = false; ///< -v or stderr is a terminal
    std::string colorconfig_path;
    std::string pending_iscolorspace; ///< --iscolorspace seen before any input
    std::string pending_tocolorspace; ///< --tocolorspace seen before any image
    OIIO::TypeDesc data_format;       ///< -d: output pixel type; unknown = the default
    std::string command_line;

    std::vector<StackImage> stack;
    /// Outputs written so far, as (temporary file, final name): renamed into place by
    /// commit_outputs() when the whole run succeeded, removed by discard_outputs() if not,
    /// so a failed run leaves no output behind.
    std::vector<std::pair<std::string, std::string>> pending_outputs;
    void commit_outputs();
    void discard_outputs();

    /// The colour config, loaded on first use (so --colorconfig anywhere before the first
    /// input counts).
    const ColorConfig& colors();

    /// The top image; throws CliError naming `command` if the stack is empty.
    StackImage& top(const std::string& command);
    /// Pops the top image; throws CliError naming `command` if the stack is empty or its
    /// top is an analysis rather than an image.
    StackImage pop(const std::string& command);
    /// Pops the top item, image or analysis (for commands that synthesize from either).
    StackImage pop_sample(const std::string& command);
    /// Pops the top n images, returned in the order they were pushed; throws CliError
    /// naming `command` if there are fewer or one is an analysis.
    std::vector<StackImage> pop(const std::string& command, int n);

    /// "CMD : no current image (…)" or "CMD : needs N images on the stack, there are H":
    /// the message for a command that finds too few images.
    static std::string too_few_images(const std::string& command, int needed, int have);

private:
    std::unique_ptr<ColorConfig> m_colors;
};

/// Reads `filename`, converts it to scene-linear float, and pushes it.
void push_input(CliState& state, const std::string& filename);

/// Declares the colour space of the input on top of the stack and re-linearises it.
void reinterpret_input(CliState& state, const std::string& colorspace);

/// Writes the top image for `filename` (colour space and pixel type per the policy in
/// docs/colour.md), with synth:* metadata, to a temporary file in pending_outputs; with
/// --subbands writes the multi-part inspection EXR.
void write_output(CliState& state, const std::string& filename);

/// The samples' file names (without folders), comma-separated: synth:sample.
std::string sample_names(const StackImage& img);

/// What a command that needs a 2-D image says when given a solid texture.
extern const char* const solid_input_message;

/// Parses a command's modifiers with its option table, each option at most once; throws
/// CliError naming the command on a bad or repeated one.
template <class T>
T parse_modifiers(
    const std::string& command, const std::string& modifiers, const OptionTable<T>& table)
{
    T opt;
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string error;
    if (!split_option_string(modifiers, pairs, error))
        throw CliError(command + " : " + error);
    for (size_t i = 0; i < pairs.size(); ++i) {
        for (size_t j = 0; j < i; ++j)
            if (pairs[j].first == pairs[i].first)
                throw CliError(command + " : " + pairs[i].first + " is given twice");
        if (!table.set(opt, pairs[i].first, pairs[i].second, error))
            throw CliError(command + " : " + error);
    }
    return opt;
}

/// A new stack image for the synthesis of `base` by a command: its colour spaces and pixel
/// type (the defaults of -o), and `sources` for synth:sample.
StackImage synthesis_result(const StackImage& base, std::vector<std::string> sources);

/// Runs `synthesize(result)` for `command` with its progress on a terminal and, with -v, a
/// timing line; throws CliError "<command> : <result's error><legend>" if it fails, else
/// pushes the result. `legend` (e.g. " (sample 0 = a.png, …)") is appended only to errors
/// that name a sample or the image.
void run_synthesis(CliState& state, const std::string& command, StackImage result,
    const std::string& legend, const std::function<bool(StackImage&)>& synthesize);

/// The recipe of a synthesis of the file `sample` (sample, colour spaces, colour config);
/// describe_by_recipe adds the method and its options.
Recipe recipe_of_sample(const CliState& state, const StackImage& sample);

/// Makes `result`, a synthesis of `sample` by `method` with `opt`, carry its recipe if
/// `sample` is a file (a recipe names a file); nthreads and progress are left out, they
/// never change the result.
template <class T>
void describe_by_recipe(const CliState& state, const StackImage& sample, StackImage& result,
    const char* method, T Recipe::*member, const T& opt)
{
    if (!sample.from_file)
        return;
    result.has_recipe = true;
    result.recipe = recipe_of_sample(state, sample);
    result.recipe.method = method;
    T& options = result.recipe.*member;
    options = opt;
    options.nthreads = 0;
    options.progress = nullptr;
}

/// A progress callback that shows "texsyn: COMMAND  NN%" on stderr.
std::function<void(float)> progress_reporter(const std::string& command);

/// The global options a synthesis takes from the command line: seed, threads, progress.
template <class T>
void apply_run_settings(const CliState& state, const std::string& command, T& opt)
{
    opt.seed = state.seed;
    opt.nthreads = state.threads;
    if (state.progress)
        opt.progress = progress_reporter(command);
}

/// --pyramid's options; throws CliError naming the command.
PyramidOptions parse_pyramid_options(const std::string& command, const std::string& modifiers);
/// --pyramid[:name=value…]: pops a sample, pushes the synthesis.
void run_pyramid(CliState& state, const std::string& command, const std::string& modifiers);

/// --analyze[:name=value…]: pops an image, pushes its analysis (written with -o x.tsa).
void run_analyze(CliState& state, const std::string& command, const std::string& modifiers);

/// Checks --analyze's modifiers (only the analysis settings are allowed); throws CliError.
PyramidOptions parse_analyze_options(const std::string& command, const std::string& modifiers);

/// --check: prints the homogeneity report of the top image (texsyn/homogeneity.h) to
/// stdout, warnings included; leaves the stack unchanged. Never fails on a poor sample.
void run_check(CliState& state, const std::string& command);

/// --solid[:name=value…]: pops a sample, pushes a solid texture (a volume).
void run_solid(CliState& state, const std::string& command, const std::string& modifiers);

/// Writes the solid texture on top of the stack for `filename`: OpenVDB for .vdb, a
/// multi-part EXR of z slices for .exr (scene-linear unless --tocolorspace says otherwise),
/// with synth:* metadata, to a temporary file in pending_outputs.
void write_volume_output(CliState& state, const std::string& filename);

/// --mix's options, validated (MixOptions::validate); throws CliError naming the command.
MixOptions parse_mix_options(const std::string& command, const std::string& modifiers);
/// --mix[:name=value…]: pops opt.nsamples() samples (sample 0 is the one pushed first),
/// pushes their mixture.
void run_mix(CliState& state, const std::string& command, const std::string& modifiers);

/// --transfer's options (the --pyramid options but size), validated; throws CliError.
PyramidOptions parse_transfer_options(const std::string& command, const std::string& modifiers);
/// --transfer[:name=value…]: pops the sample (top) and the image below it, pushes the
/// image's layout with the sample's statistics.
void run_transfer(CliState& state, const std::string& command, const std::string& modifiers);

/// The options of a method that copies sample pixels (--neighborhood, --choosy) and the
/// tool's own map=FILE: the source map to write (a file name, so not a method option).
template <class T>
struct MapCommand {
    T options;
    std::string map;
};

/// Takes `name`=FILE (at most once, not empty) out of a command's modifiers into `file`;
/// returns the other modifiers. Throws CliError naming the command.
std::string take_file_modifier(const std::string& command, const std::string& modifiers,
    const std::string& name, std::string& file);

/// Takes map=FILE.exr (at most once) out of a command's modifiers into `map`; returns the
/// other modifiers. Throws CliError naming the command.
std::string take_map_modifier(
    const std::string& command, const std::string& modifiers, std::string& map);

/// Parses and validates the modifiers of a command whose method has options T and writes a
/// source map with map=; throws CliError naming the command.
template <class T>
MapCommand<T> parse_map_command(const std::string& command, const std::string& modifiers)
{
    MapCommand<T> result;
    const std::string rest = take_map_modifier(command, modifiers, result.map);
    result.options = parse_modifiers(command, rest, T::table());
    std::string error;
    if (!result.options.validate(error))
        throw CliError(command + " : " + error);
    return result;
}

/// Writes `map`, the source map of a synthesis of `sample` by `command`, for `filename`
/// (to a temporary file in pending_outputs).
void write_source_map_output(CliState& state, const std::string& command, const StackImage& sample,
    OIIO::ImageBuf& map, const std::string& filename);

/// A synthesis function that can fill a source map (neighborhood_synthesize, …).
template <class T>
using MapSynthesis = bool (*)(OIIO::ImageBuf&, const OIIO::ImageBuf&, const T&, OIIO::ImageBuf*);

/// COMMAND[:name=value…] for `method` (options at Recipe member `member`), run by
/// `synthesize`: pops a sample, pushes the synthesis (with its recipe); with map=FILE also
/// writes the source map.
template <class T>
void run_map_command(CliState& state, const std::string& command, const std::string& modifiers,
    const char* method, T Recipe::*member, MapSynthesis<T> synthesize)
{
    MapCommand<T> parsed = parse_map_command<T>(command, modifiers);
    apply_run_settings(state, command, parsed.options);
    StackImage sample = state.pop(command);
    OIIO::ImageBuf map;
    run_synthesis(state, command, synthesis_result(sample, sample.sources), "", [&](StackImage& r) {
        if (!synthesize(r.buf, sample.buf, parsed.options, parsed.map.empty() ? nullptr : &map))
            return false;
        describe_by_recipe(state, sample, r, method, member, parsed.options);
        return true;
    });
    if (!parsed.map.empty())
        write_source_map_output(state, command, sample, map, parsed.map);
}

/// --neighborhood[:name=value…]: Wei & Levoy; pops a sample, pushes the synthesis; with
/// map=FILE also writes the source map.
void run_neighborhood(CliState& state, const std::string& command, const std::string& modifiers);

/// --choosy[:name=value…]: Castellanos & Williams choosy sampling; pops a sample, pushes
/// the synthesis; with map=FILE also writes the source map.
void run_choosy(CliState& state, const std::string& command, const std::string& modifiers);

/// --cascade's options and the tool's own file options (file names, so not method
/// options): dilation=FILE and rotation=FILE (control images, read Raw) and palette=FILE
/// (an image whose colours, read like any input, colour the result); `sized` says whether
/// size= was given.
struct CascadeCommand {
    CascadeOptions options;
    std::string dilation, rotation, palette;
    bool sized = false;
    /// The files it reads, in option order (empty names skipped).
    std::vector<std::string> files() const;
};

/// Parses and validates --cascade's modifiers; throws CliError naming the command.
CascadeCommand parse_cascade_command(const std::string& command, const std::string& modifiers);

/// --cascade[:name=value…]: iterated nonlinear maps and convolution in a multiscale
/// cascade. A generator: with no image on the stack it pushes a new one; else it pops the
/// image, uses it as the initial lattice (texture transfer, at the image's size unless
/// size= is given) and pushes the result. dilation=FILE and rotation=FILE read control
/// images (Raw); palette=FILE reads an image whose colours the result takes.
void run_cascade(CliState& state, const std::string& command, const std::string& modifiers);

/// --apply-map MAP IMAGE: reads IMAGE (an input like any other), rearranges its pixels by
/// the source map MAP, and pushes the result, which keeps IMAGE's colour space on output.
void run_apply_map(CliState& state, const std::string& map_file, const std::string& image_file);

/// --recipe FILE: writes the recipe of the top image (a synthesis of a sample file), with
/// paths relative to FILE's folder, to a temporary file in pending_outputs.
void write_recipe(CliState& state, const std::string& filename);

/// Prints --help, --list-methods and --version text to stdout.
void print_help();
void print_methods();
void print_version();

} // namespace texsyn::cli
