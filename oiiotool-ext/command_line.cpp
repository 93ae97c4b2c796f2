// SPDX-License-Identifier: Apache-2.0
#include "command_line.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/error_text.h>
#include <texsyn/inputs.h>
#include <texsyn/io.h>
#include <texsyn/material.h>
#include <texsyn/memory.h>

#include "cli_error.h"
#include "commands.h"
#include "item_kinds.h"
#include "output_format.h"

namespace texsyn::cli {

namespace {

const std::vector<std::string> k_with_argument = { "--seed", "--threads", "--colorconfig",
    "--iscolorspace", "--tocolorspace", "-d", "-o", "--recipe", "--max-memory" };
const std::vector<std::string> k_flags
    = { "-v", "--subbands", "--help", "-h", "--version", "--list-methods", "--colorspaces" };

bool listed(const std::vector<std::string>& list, const std::string& a)
{
    return std::find(list.begin(), list.end(), a) != list.end();
}

// The message for `arg`, which is no option or command: with the nearest one's name if it
// looks like a slip of the keyboard.
std::string unknown_command(const std::string& arg, const std::string& name)
{
    std::vector<std::string> known = k_with_argument;
    known.insert(known.end(), k_flags.begin(), k_flags.end());
    known.push_back("--apply-map");
    for (const Method* m : methods())
        known.push_back("--" + m->name);
    const std::string guess = closest_name(name, known);
    if (guess.empty())
        return "unknown command or option '" + arg + "' (see texsyn --help)";
    return "unknown command '" + name + "' (did you mean " + guess + "?)";
}

} // namespace

bool takes_argument(const std::string& a)
{
    return listed(k_with_argument, a);
}

bool is_flag(const std::string& a)
{
    return listed(k_flags, a);
}

std::pair<std::string, std::string> split_command(const std::string& a)
{
    size_t colon = a.find(':');
    if (colon == std::string::npos)
        return { a, "" };
    return { a.substr(0, colon), a.substr(colon + 1) };
}

bool is_apply_map(const std::string& arg)
{
    return split_command(arg).first == "--apply-map";
}

NormalMap apply_map_normal(const std::string& arg)
{
    const std::string modifier = split_command(arg).second;
    if (modifier.empty() || modifier == "normal=none")
        return NormalMap::None;
    if (modifier == "normal=opengl")
        return NormalMap::OpenGL;
    if (modifier == "normal=directx")
        return NormalMap::DirectX;
    throw CliError(arg + " : expected --apply-map:normal=opengl, normal=directx or normal=none");
}

namespace {

// What the check knows of each item the run will put on the stack.
struct PlannedItem {
    ItemKind kind = ItemKind::Image;
    std::string name;              ///< its file's name, or its result_name()
    bool made = false;             ///< a command's result
    std::vector<std::string> maps; ///< a material set's maps, by name
};

// The maps --material's options make: the albedo, then every map whose file is given (in
// the option table's order, which is the material's).
std::vector<std::string> material_maps(const MethodOptions& options)
{
    std::vector<std::string> maps = { "albedo" };
    for (const OptionField& f : options.table().fields())
        if (f.type == OptionType::InputFile && !options.value(f.name).empty())
            maps.push_back(f.name);
    return maps;
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

// Whether two output paths name the same file, however spelled (./a.exr, d/../a.exr).
bool same_path(const std::string& a, const std::string& b)
{
    std::error_code ea, eb;
    const std::filesystem::path pa
        = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ea), ea);
    const std::filesystem::path pb
        = std::filesystem::weakly_canonical(std::filesystem::absolute(b, eb), eb);
    return a == b || (!ea && !eb && pa == pb);
}

// An output path (of -o, --recipe or a file option) must not name an input and must be
// writable.
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
    std::string error;
    if (!check_output_destination(out, error)) // "OUT: exists and is not a regular file…"
        throw CliError(option + " " + out + " : " + error.substr(out.size() + 2));
    if (!std::filesystem::is_directory(dir, ec))
        throw CliError(option + " " + out + " : directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK) != 0)
        throw CliError(option + " " + out + " : directory " + dir.string() + " is not writable");
}

// The options of command `name` (row `m`) from its modifiers: shorthands expanded, parsed
// and validated; the files they read are added to `inputs` (they must exist), the files
// they write to `side_outputs` as (option, file).
MethodOptions command_options(const std::string& name, const Method& m,
    const std::string& modifiers, std::vector<std::string>& inputs,
    std::vector<std::pair<std::string, std::string>>& side_outputs)
{
    MethodOptions options = m.defaults();
    std::string error;
    if (!options.apply(m.shorthands ? m.shorthands(modifiers) : modifiers, error)
        || !options.validate(error))
        throw CliError(name + " : " + error);
    for (const OptionField& f : options.table().fields()) {
        const std::string file = options.value(f.name);
        if (file.empty())
            continue;
        if (f.type == OptionType::InputFile) {
            if (std::string why; !check_option_file(f, file, why))
                throw CliError(name + " : " + why);
            inputs.push_back(file);
        } else if (f.type == OptionType::OutputFile) {
            side_outputs.emplace_back(f.name, file);
        }
    }
    return options;
}

} // namespace

Early check_command_line(CliState& state, const std::vector<std::string>& args)
{
    std::vector<std::string> inputs, outputs, recipes, colorspaces;
    std::vector<std::pair<std::string, std::string>> side_outputs;
    std::vector<PlannedItem> stack; // as the run will build it
    std::string volume_command;     // a command that makes a solid texture
    bool report = false;
    // Pops the `n` items `command` takes (checked), returning them.
    auto pop = [&](const std::string& command, int n) {
        if (int(stack.size()) < n)
            throw CliError(too_few_items(command, n, int(stack.size())));
        std::vector<PlannedItem> popped(stack.end() - n, stack.end());
        stack.resize(stack.size() - size_t(n));
        return popped;
    };
    // Everything that makes or changes an image must be followed by an -o that writes it
    // (or a report on it).
    size_t last_output = 0;
    for (size_t i = 0; i < args.size(); ++i) {
        const Method* m = args[i].rfind("--", 0) == 0
            ? find_method(split_command(args[i]).first.substr(2))
            : nullptr;
        if (args[i] == "-o" || args[i] == "--recipe")
            last_output = ++i;
        else if (m && m->output == MethodOutput::Report)
            last_output = i;
        else if (takes_argument(args[i]))
            ++i;
        else if (is_apply_map(args[i]))
            i += 2;
    }
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
                state.seed = uint64_t(int_argument("--seed", v, 0, max_seed));
            else if (a == "--threads")
                state.threads = int(int_argument("--threads", v, 0, max_threads));
            else if (a == "--max-memory") {
                std::string error;
                if (!parse_memory_size(v, state.max_memory, error))
                    throw CliError("--max-memory " + v + " : " + error);
            } else if (a == "--colorconfig")
                state.colorconfig_path = v;
            else if (a == "-d")
                state.data_format = data_format_argument(v);
            else if (a == "-o") {
                const PlannedItem item = pop(a, 1)[0]; // -o writes the top item and leaves it
                for (const std::string& file : output_files(v, item.kind, item.maps))
                    outputs.push_back(file);
                stack.push_back(item);
            } else if (a == "--recipe") {
                recipes.push_back(v);
                const PlannedItem item = pop(a, 1)[0];
                if (!kind_rules(item.kind).recipes)
                    throw CliError("--recipe " + v + " : the current item is "
                        + item_kind_text(item.kind) + "; recipes describe images");
                stack.push_back(item);
            } else if (a == "--iscolorspace" || a == "--tocolorspace") {
                check_written(i - 1);
                colorspaces.push_back(a + " " + v);
            }
        } else if (is_apply_map(a)) {
            apply_map_normal(a);
            if (i + 2 >= args.size())
                throw CliError("--apply-map : needs two arguments, the source map and the image "
                               "(--apply-map coords.exr height.png)");
            check_written(i);
            inputs.push_back(args[i + 1]);
            inputs.push_back(args[i + 2]);
            i += 2;
            stack.push_back({ ItemKind::Image, args[i], false, {} });
        } else if (is_flag(a)) {
            if (a == "--help" || a == "-h") {
                if (i + 1 < args.size()) // --help METHOD
                    print_method_help(method_for_help(args[i + 1]));
                else
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
            if (a == "--colorspaces") {
                // Of the config the run would use: a --colorconfig after it counts too.
                for (size_t j = i + 1; j + 1 < args.size(); ++j)
                    if (args[j] == "--colorconfig")
                        state.colorconfig_path = args[j + 1];
                std::printf("%s", state.colors().describe().c_str());
                return Early::Exit;
            }
            if (a == "-v")
                state.verbose = true;
            if (a == "--subbands")
                state.subbands = true;
        } else if (!a.empty() && a[0] == '-') {
            const auto [name, modifiers] = split_command(a);
            const Method* m = name.rfind("--", 0) == 0 ? find_method(name.substr(2)) : nullptr;
            if (!m)
                throw CliError(unknown_command(a, name));
            if (modifiers == "help") {
                print_method_help(*m);
                return Early::Exit;
            }
            check_written(i);
            MethodOptions options = command_options(name, *m, modifiers, inputs, side_outputs);
            const std::vector<PlannedItem> popped
                = pop(name, m->input_count(options, int(stack.size())));
            for (size_t k = 0; k < popped.size(); ++k)
                kind_rules(popped[k].kind)
                    .check_input(
                        name, *m, int(k), int(popped.size()), popped[k].name, popped[k].made);
            state.options[i] = std::move(options);
            if (m->output == MethodOutput::Volume)
                volume_command = name;
            report = report || m->output == MethodOutput::Report;
            if (m->output == MethodOutput::Report) {
                stack.insert(stack.end(), popped.begin(), popped.end());
                continue;
            }
            std::vector<std::string> names;
            for (const PlannedItem& item : popped)
                names.push_back(item.name);
            const bool material_in = popped.size() == 1 && popped[0].kind == ItemKind::Material;
            stack.push_back({ material_in ? ItemKind::Material : item_kind(m->output),
                result_name(*m, names), true,
                material_in                               ? popped[0].maps
                    : m->output == MethodOutput::Material ? material_maps(state.options[i])
                                                          : std::vector<std::string>() });
        } else {
            check_written(i);
            inputs.push_back(a);
            stack.push_back({ is_analysis_filename(a) ? ItemKind::Analysis : ItemKind::Image,
                OIIO::Filesystem::filename(a), false, {} });
        }
    }
    if (outputs.empty() && recipes.empty() && !report && !args.empty())
        throw CliError("nothing to do: no -o FILE (see texsyn --help)");
    if (!volume_command.empty() && state.subbands)
        throw CliError("--subbands : does not apply to " + volume_command
            + " (solid textures have no inspection EXR)");
    for (const std::string& recipe : recipes) {
        check_output_path("--recipe", recipe, inputs);
        if (!OIIO::Strutil::iends_with(recipe, ".texsyn"))
            throw CliError("--recipe " + recipe + " : name the recipe *.texsyn");
    }
    for (const auto& [option, out] : side_outputs)
        check_output_path(option + "=", out, inputs);
    // No two outputs may name one file, however spelled (./a.png, a symlink to it): the
    // last would silently replace the others.
    std::vector<std::string> written;
    for (const std::string& out : outputs)
        written.push_back("-o " + out);
    for (const std::string& recipe : recipes)
        written.push_back("--recipe " + recipe);
    for (const auto& [option, out] : side_outputs)
        written.push_back(option + "=" + out);
    auto path_of = [](const std::string& w) { return w.substr(w.find_first_of(" =") + 1); };
    for (size_t i = 0; i < written.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (same_path(path_of(written[i]), path_of(written[j])))
                throw CliError(written[i] + " : is also written by " + written[j]);
    for (const std::string& out : outputs) {
        check_output_path("-o", out, inputs);
        if (is_analysis_filename(out)) {
            if (state.subbands)
                throw CliError("-o " + out + " : --subbands writes images, not analysis files");
            continue;
        }
        if (OIIO::Strutil::iends_with(out, ".ply")) // written by texsyn itself
            continue;
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
            throw CliError(option.substr(0, option.find(' ')) + " : "
                + state.colors().unknown_colorspace(name));
    }
    return Early::Run;
}

} // namespace texsyn::cli
