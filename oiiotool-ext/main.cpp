// SPDX-License-Identifier: Apache-2.0
// texsyn: an oiiotool-style command line over libtexsyn. Parsing and dispatch only.
#include "cli_state.h"

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
        || a == "--tocolorspace" || a == "-d" || a == "-o";
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
    return name == "--pyramid";
}

int64_t int_argument(const std::string& option, const std::string& value, int64_t lo, int64_t hi)
{
    int64_t v = 0;
    std::string error;
    if (!parse_int_option(option, value, lo, hi, v, error))
        throw CliError(error);
    return v;
}

void check_output_path(const std::string& out, const std::vector<std::string>& inputs)
{
    for (const std::string& in : inputs)
        if (in == out || same_file(in, out))
            throw CliError("-o " + out + " : refusing to overwrite the input " + in);
    auto writer = OIIO::ImageOutput::create(out);
    if (!writer) {
        (void)OIIO::geterror();
        throw CliError("-o " + out + " : no image format writes '"
            + std::filesystem::path(out).extension().string() + "' files");
    }
    std::filesystem::path dir = std::filesystem::path(out).parent_path();
    if (dir.empty())
        dir = ".";
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec))
        throw CliError("-o " + out + " : directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK) != 0)
        throw CliError("-o " + out + " : directory " + dir.string() + " is not writable");
}

// First pass: global options and a check of every argument, before any work is done,
// so that a bad command line never leaves partial output behind.
enum class Early { Run, Exit };
Early parse_globals(CliState& state, const std::vector<std::string>& args)
{
    std::vector<std::string> inputs, outputs;
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
                state.data_format = v;
            else if (a == "-o")
                outputs.push_back(v);
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
            if (!is_command(split_command(a).first))
                throw CliError("unknown command or option '" + a + "' (see texsyn --help)");
        } else {
            inputs.push_back(a);
        }
    }
    if (!state.data_format.empty()) {
        OIIO::TypeDesc t(state.data_format);
        if (t != OIIO::TypeUInt8 && t != OIIO::TypeUInt16 && t != OIIO::TypeHalf
            && t != OIIO::TypeFloat)
            throw CliError("-d : unknown data format '" + state.data_format
                + "' (use uint8, uint16, half or float)");
    }
    for (const std::string& out : outputs) {
        check_output_path(out, inputs);
        if (state.subbands && !OIIO::Strutil::iends_with(out, ".exr"))
            throw CliError(
                "-o " + out + " : --subbands writes a multi-part OpenEXR; name the output *.exr");
    }
    if (outputs.empty() && !args.empty())
        throw CliError("nothing to do: no -o FILE (see texsyn --help)");
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
            else if (a == "--iscolorspace") {
                if (state.stack.empty())
                    state.pending_iscolorspace = v;
                else
                    reinterpret_input(state, v);
            } else if (a == "--tocolorspace") {
                if (state.colors().resolve(v).empty())
                    throw CliError("--tocolorspace : unknown colour space '" + v + "'");
                if (state.stack.empty())
                    state.pending_tocolorspace = v;
                else
                    state.stack.back().output_colorspace = v;
            }
        } else if (is_flag(a)) {
            continue;
        } else if (!a.empty() && a[0] == '-') {
            auto [name, modifiers] = split_command(a);
            if (name == "--pyramid")
                run_pyramid(state, name, modifiers);
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
        state.progress = state.verbose || ::isatty(STDERR_FILENO);
        if (state.threads > 0)
            OIIO::attribute("threads", state.threads);
        run(state, args);
    } catch (const CliError& e) {
        std::fprintf(stderr, "texsyn ERROR: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "texsyn ERROR: %s\n", e.what());
        return 1;
    }
    return 0;
}
