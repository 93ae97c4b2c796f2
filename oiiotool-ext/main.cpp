// SPDX-License-Identifier: Apache-2.0
// texsyn: an oiiotool-style command line over libtexsyn. Parsing and dispatch only.
#include "cli_state.h"
#include "output_format.h"

#include <cstdio>
#include <cstring>
#include <filesystem>

#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>

namespace texsyn::cli {

namespace {

// Options that take one argument.
bool takes_argument(const std::string& a)
{
    return a == "--seed" || a == "--threads" || a == "--colorconfig" || a == "--iscolorspace"
        || a == "--tocolorspace" || a == "-d" || a == "-o" || a == "--recipe";
}

bool is_flag(const std::string& a)
{
    return a == "-v" || a == "--subbands" || a == "--help" || a == "-h" || a == "--version"
        || a == "--list-methods";
}

// "--pyramid:size=8x8" -> ("--pyramid", "size=8x8").
std::pair<std::string, std::string> split_command(const std::string& a)
{
    size_t colon = a.find(':');
    if (colon == std::string::npos)
        return { a, "" };
    return { a.substr(0, colon), a.substr(colon + 1) };
}

bool is_command(const std::string& name)
{
    return name == "--pyramid" || name == "--analyze" || name == "--check" || name == "--solid"
        || name == "--mix" || name == "--transfer" || name == "--neighborhood" || name == "--choosy"
        || name == "--cascade";
}

// What the pre-pass knows of each item on the stack.
enum class Kind { Image, Analysis, Solid };

// Checks a command's options (throws CliError) and returns how many images it pops (a
// command pushes one image back, --check leaves the one it reports on; --cascade pops the
// current image if there is one). Files a command writes besides -o (map= of
// --neighborhood and --choosy) are added to `outputs`, files it reads besides the stack
// (dilation=, rotation= and palette= of --cascade) to `inputs`.
int check_command(const std::string& name, const std::string& modifiers,
    std::vector<std::string>& outputs, std::vector<std::string>& inputs)
{
    if (name == "--mix")
        return parse_mix_options(name, modifiers).nsamples();
    if (name == "--transfer") {
        parse_transfer_options(name, modifiers);
        return 2;
    }
    if (name == "--check") {
        if (!modifiers.empty())
            throw CliError(name + " : takes no options (got '" + modifiers + "')");
    } else if (name == "--analyze") {
        parse_analyze_options(name, modifiers);
    } else if (name == "--solid") {
        parse_modifiers(name, modifiers, SolidOptions::table());
    } else if (name == "--cascade") {
        const CascadeCommand cascade = parse_cascade_command(name, modifiers);
        for (const auto& [key, file] : { std::pair { "dilation", &cascade.dilation },
                 { "rotation", &cascade.rotation }, { "palette", &cascade.palette } }) {
            std::error_code ec;
            if (file->empty())
                continue;
            if (!std::filesystem::is_regular_file(*file, ec))
                throw CliError(name + " : " + key + "=" + *file + " : no such file");
            inputs.push_back(*file);
        }
    } else if (name == "--neighborhood" || name == "--choosy") {
        const std::string map = name == "--choosy"
            ? parse_map_command<ChoosyOptions>(name, modifiers).map
            : parse_map_command<NeighborhoodOptions>(name, modifiers).map;
        if (!map.empty())
            outputs.push_back(map);
    } else {
        parse_pyramid_options(name, modifiers);
    }
    return 1;
}

// The items a command pops must be 2-D images (--pyramid takes an analysis too; the run
// explains why an analysis does not suit the others).
void check_command_inputs(const std::string& command, const std::vector<Kind>& inputs)
{
    for (Kind kind : inputs) {
        if (kind == Kind::Solid)
            throw CliError(command + " : " + solid_input_message);
        if (kind == Kind::Analysis && command == "--solid")
            throw CliError(command
                + " : the current item is an analysis; --solid analyses the sample itself (give "
                  "the image)");
    }
}

// Solid textures are written as OpenVDB or as an EXR of z slices; .vdb holds nothing else.
void check_output_kind(const std::string& out, Kind kind)
{
    const bool vdb = OIIO::Strutil::iends_with(out, ".vdb");
    if (kind == Kind::Solid && !vdb && !OIIO::Strutil::iends_with(out, ".exr"))
        throw CliError("-o " + out
            + " : a solid texture is written as .vdb (OpenVDB) or .exr (one part per z "
              "slice), not '"
            + std::filesystem::path(out).extension().string() + "'");
    if (kind != Kind::Solid && vdb)
        throw CliError(
            "-o " + out + " : .vdb holds solid textures (from --solid); the current image is 2-D");
}

int64_t int_argument(const std::string& option, const std::string& value, int64_t lo, int64_t hi)
{
    int64_t v = 0;
    std::string error;
    if (!parse_int_option(option, value, lo, hi, v, error))
        throw CliError(error);
    return v;
}

OIIO::TypeDesc data_format_argument(const std::string& v)
{
    OIIO::TypeDesc t(v);
    if (t != OIIO::TypeUInt8 && t != OIIO::TypeUInt16 && t != OIIO::TypeHalf
        && t != OIIO::TypeFloat)
        throw CliError("-d : unknown data format '" + v + "' (use uint8, uint16, half or float)");
    return t;
}

// An output path (of -o or --recipe) must not name an input and must be writable.
void check_output_path(
    const std::string& option, const std::string& out, const std::vector<std::string>& inputs)
{
    for (const std::string& in : inputs)
        if (in == out || same_file(in, out))
            throw CliError(option + " " + out + " : refusing to overwrite the input " + in);
    std::filesystem::path dir = std::filesystem::path(out).parent_path();
    if (dir.empty())
        dir = ".";
    std::error_code ec;
    if (std::filesystem::is_directory(out, ec))
        throw CliError(option + " " + out + " : is a directory");
    if (!std::filesystem::is_directory(dir, ec))
        throw CliError(option + " " + out + " : directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK) != 0)
        throw CliError(option + " " + out + " : directory " + dir.string() + " is not writable");
}

// First pass: global options and a check of every argument, before any work is done,
// so that a bad command line never leaves partial output behind.
enum class Early { Run, Exit };
Early parse_globals(CliState& state, const std::vector<std::string>& args)
{
    std::vector<std::string> inputs, outputs, recipes, colorspaces, side_outputs;
    std::vector<Kind> stack; // as the run will build it, for the commands' input checks
    bool solid = false;
    // Pops the `n` items `command` takes (checked), returning them.
    auto pop = [&](const std::string& command, int n) {
        if (int(stack.size()) < n)
            throw CliError(CliState::too_few_images(command, n, int(stack.size())));
        std::vector<Kind> popped(stack.end() - n, stack.end());
        stack.resize(stack.size() - size_t(n));
        return popped;
    };
    // Everything that makes or changes an image must be followed by an -o that writes it
    // (or a --check that reports on it).
    size_t last_output = 0;
    bool check = false;
    for (size_t i = 0; i < args.size(); ++i)
        if (args[i] == "-o" || args[i] == "--recipe")
            last_output = ++i;
        else if (split_command(args[i]).first == "--check")
            last_output = i;
        else if (takes_argument(args[i]))
            ++i;
        else if (args[i] == "--apply-map")
            i += 2;
    auto check_written = [&](size_t i) {
        if (last_output > 0 && i > last_output) // no -o at all is reported after the loop
            throw CliError(args[i] + " : has no effect, nothing is written after it (add -o FILE)");
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (takes_argument(a)) {
            if (i + 1 >= args.size())
                throw CliError(a + " : missing argument");
            const std::string& v = args[++i];
            if (a == "--seed")
                state.seed = uint64_t(int_argument("--seed", v, 0, 2147483647));
            else if (a == "--threads")
                state.threads = int(int_argument("--threads", v, 0, 1024));
            else if (a == "--colorconfig")
                state.colorconfig_path = v;
            else if (a == "-d")
                state.data_format = data_format_argument(v);
            else if (a == "-o") {
                outputs.push_back(v);
                const Kind kind = pop(a, 1)[0]; // -o writes the top item and leaves it
                check_output_kind(v, kind);
                stack.push_back(kind);
            } else if (a == "--recipe") {
                recipes.push_back(v);
                const Kind kind = pop(a, 1)[0];
                if (kind == Kind::Solid)
                    throw CliError("--recipe " + v
                        + " : recipes describe 2-D syntheses; the current image is a solid "
                          "texture");
                stack.push_back(kind);
            } else if (a == "--iscolorspace" || a == "--tocolorspace") {
                check_written(i - 1);
                colorspaces.push_back(a + " " + v);
            }
        } else if (a == "--apply-map") {
            if (i + 2 >= args.size())
                throw CliError("--apply-map : needs two arguments, the source map and the image "
                               "(--apply-map coords.exr height.png)");
            check_written(i);
            inputs.push_back(args[i + 1]);
            inputs.push_back(args[i + 2]);
            i += 2;
            stack.push_back(Kind::Image);
        } else if (is_flag(a)) {
            if (a == "--help" || a == "-h") {
                print_help();
                return Early::Exit;
            }
            if (a == "--version") {
                print_version();
                return Early::Exit;
            }
            if (a == "--list-methods") {
                print_methods();
                return Early::Exit;
            }
            if (a == "-v")
                state.verbose = true;
            if (a == "--subbands")
                state.subbands = true;
        } else if (!a.empty() && a[0] == '-') {
            auto [name, modifiers] = split_command(a);
            if (!is_command(name))
                throw CliError("unknown command or option '" + a + "' (see texsyn --help)");
            check_written(i);
            int n = check_command(name, modifiers, side_outputs, inputs);
            if (name == "--cascade" && stack.empty())
                n = 0; // a generator
            const std::vector<Kind> popped = pop(name, n);
            check_command_inputs(name, popped);
            check = check || name == "--check";
            solid = solid || name == "--solid";
            stack.push_back(name == "--analyze" ? Kind::Analysis
                    : name == "--solid"         ? Kind::Solid
                    : name == "--check"         ? popped[0]
                                                : Kind::Image);
        } else {
            check_written(i);
            inputs.push_back(a);
            stack.push_back(is_analysis_filename(a) ? Kind::Analysis : Kind::Image);
        }
    }
    if (outputs.empty() && recipes.empty() && !check && !args.empty())
        throw CliError("nothing to do: no -o FILE (see texsyn --help)");
    if (solid && state.subbands)
        throw CliError("--subbands : does not apply to --solid (solid textures have no "
                       "inspection EXR)");
    for (const std::string& recipe : recipes) {
        check_output_path("--recipe", recipe, inputs);
        if (!OIIO::Strutil::iends_with(recipe, ".texsyn"))
            throw CliError("--recipe " + recipe + " : name the recipe *.texsyn");
    }
    for (const std::string& out : side_outputs) {
        check_output_path("map=", out, inputs);
        for (const std::string& other : outputs)
            if (other == out)
                throw CliError("map=" + out + " : is also written by -o");
    }
    for (const std::string& out : outputs) {
        check_output_path("-o", out, inputs);
        if (is_analysis_filename(out)) {
            if (state.subbands)
                throw CliError("-o " + out + " : --subbands writes images, not analysis files");
            continue;
        }
        auto writer = OIIO::ImageOutput::create(out);
        if (!writer && OIIO::Strutil::iends_with(out, ".vdb")) {
            (void)OIIO::geterror(); // written by texsyn itself, checked above
        } else if (!writer) {
            (void)OIIO::geterror();
            throw CliError("-o " + out + " : no image format writes '"
                + std::filesystem::path(out).extension().string() + "' files");
        }
        if (state.subbands && !OIIO::Strutil::iends_with(out, ".exr"))
            throw CliError(
                "-o " + out + " : --subbands writes a multi-part OpenEXR; name the output *.exr");
        if (state.data_format != OIIO::TypeUnknown)
            output_pixel_type(out, state.data_format, OIIO::TypeUnknown);
    }
    for (const std::string& option : colorspaces) {
        const std::string name = option.substr(option.find(' ') + 1);
        if (state.colors().resolve(name).empty())
            throw CliError(
                option.substr(0, option.find(' ')) + " : unknown colour space '" + name + "'");
    }
    return Early::Run;
}

void run(CliState& state, const std::vector<std::string>& args)
{
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (takes_argument(a)) {
            const std::string& v = args[++i];
            if (a == "-o")
                write_output(state, v);
            else if (a == "--recipe")
                write_recipe(state, v);
            else if (a == "--iscolorspace") {
                if (state.stack.empty())
                    state.pending_iscolorspace = v;
                else
                    reinterpret_input(state, v);
            } else if (a == "--tocolorspace") {
                if (state.stack.empty())
                    state.pending_tocolorspace = v;
                else
                    state.stack.back().output_colorspace = v;
            }
        } else if (a == "--apply-map") {
            run_apply_map(state, args[i + 1], args[i + 2]);
            i += 2;
        } else if (is_flag(a)) {
            continue;
        } else if (!a.empty() && a[0] == '-') {
            auto [name, modifiers] = split_command(a);
            if (name == "--pyramid")
                run_pyramid(state, name, modifiers);
            else if (name == "--analyze")
                run_analyze(state, name, modifiers);
            else if (name == "--check")
                run_check(state, name);
            else if (name == "--solid")
                run_solid(state, name, modifiers);
            else if (name == "--mix")
                run_mix(state, name, modifiers);
            else if (name == "--transfer")
                run_transfer(state, name, modifiers);
            else if (name == "--neighborhood")
                run_neighborhood(state, name, modifiers);
            else if (name == "--choosy")
                run_choosy(state, name, modifiers);
            else if (name == "--cascade")
                run_cascade(state, name, modifiers);
        } else {
            push_input(state, a);
        }
    }
}

} // namespace

} // namespace texsyn::cli

int main(int argc, char* argv[])
{
    using namespace texsyn::cli;
    std::vector<std::string> args(argv + 1, argv + argc);
    CliState state;
    state.command_line = OIIO::Strutil::join(std::vector<std::string>(argv, argv + argc), " ");
    try {
        if (args.empty()) {
            print_help();
            return 1;
        }
        if (parse_globals(state, args) == Early::Exit)
            return 0;
        state.progress = ::isatty(STDERR_FILENO);
        if (state.threads > 0)
            OIIO::attribute("threads", state.threads);
        run(state, args);
        state.commit_outputs();
    } catch (const CliError& e) {
        state.discard_outputs();
        std::fprintf(stderr, "texsyn ERROR: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        state.discard_outputs();
        std::fprintf(stderr, "texsyn ERROR: %s\n", e.what());
        return 1;
    }
    return 0;
}
