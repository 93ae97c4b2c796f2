// SPDX-License-Identifier: Apache-2.0
// --cascade: iterated nonlinear maps and convolution in a multiscale cascade; a generator,
// or a texture transfer from the current image.
#include "cli_state.h"
#include "quiet_stderr.h"

#include <texsyn/io.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace texsyn::cli {

namespace {

bool starts_number(const std::string& v)
{
    return !v.empty()
        && (std::isdigit(static_cast<unsigned char>(v[0])) || v[0] == '-' || v[0] == '.'
            || v[0] == '+');
}

// The shorthands, rewritten into options: `map=curve:x0,y0,…` (a piece without '='
// after map=…curve) becomes curve=x0,y0,…; `kernel=w0,w1,…` (numbers) becomes
// kernel=custom:weights=… with ksize the square root of their count unless given;
// `ramp=FILE` (a name with a letter extension, e.g. rust.png) becomes palette=FILE.
std::string expand_shorthands(const std::string& modifiers)
{
    std::vector<std::string> pieces;
    std::string piece;
    for (char c : modifiers + ":") {
        if (c != ':') {
            piece += c;
            continue;
        }
        if (!piece.empty())
            pieces.push_back(piece);
        piece.clear();
    }
    bool has_ksize = false;
    for (const std::string& p : pieces)
        has_ksize = has_ksize || p.rfind("ksize=", 0) == 0;
    std::string out, previous;
    for (const std::string& p : pieces) {
        std::string rewritten = p;
        const size_t eq = p.find('=');
        const std::string key = p.substr(0, eq),
                          value = eq == std::string::npos ? "" : p.substr(eq + 1);
        if (eq == std::string::npos && previous.rfind("map=", 0) == 0 && previous.size() >= 5
            && previous.compare(previous.size() - 5, 5, "curve") == 0) {
            rewritten = "curve=" + p;
        } else if (key == "kernel" && starts_number(value)) {
            const size_t n = size_t(std::count(value.begin(), value.end(), ',')) + 1;
            const int side = int(std::lround(std::sqrt(double(n))));
            rewritten = "kernel=custom:weights=" + value;
            if (!has_ksize && size_t(side * side) == n)
                rewritten += ":ksize=" + std::to_string(side);
        } else if (key == "ramp") {
            const std::string ext = std::filesystem::path(value).extension().string();
            if (ext.size() > 1 && std::all_of(ext.begin() + 1, ext.end(), [](char c) {
                    return std::isalpha(static_cast<unsigned char>(c));
                }))
                rewritten = "palette=" + value;
        }
        out += (out.empty() ? "" : ":") + rewritten;
        previous = p;
    }
    return out;
}

} // namespace

CascadeCommand parse_cascade_command(const std::string& command, const std::string& modifiers)
{
    CascadeCommand result;
    std::string rest
        = take_file_modifier(command, expand_shorthands(modifiers), "dilation", result.dilation);
    rest = take_file_modifier(command, rest, "rotation", result.rotation);
    rest = take_file_modifier(command, rest, "palette", result.palette);
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string error;
    if (split_option_string(rest, pairs, error))
        for (const auto& pair : pairs)
            result.sized = result.sized || pair.first == "size";
    result.options = parse_modifiers(command, rest, CascadeOptions::table());
    if (!result.options.validate(error))
        throw CliError(command + " : " + error);
    return result;
}

std::vector<std::string> CascadeCommand::files() const
{
    std::vector<std::string> names;
    for (const std::string* f : { &dilation, &rotation, &palette })
        if (!f->empty())
            names.push_back(*f);
    return names;
}

namespace {

// A control image read as its file's numbers (no colour conversion); empty if no name.
OIIO::ImageBuf read_control(const std::string& command, const char* what, const std::string& file)
{
    OIIO::ImageBuf image;
    if (file.empty())
        return image;
    std::string error;
    bool ok;
    {
        QuietStderr quiet;
        ok = read_image(file, image, error);
    }
    if (!ok)
        throw CliError(command + " : " + what + "=" + error);
    return image;
}

} // namespace

void run_cascade(CliState& state, const std::string& command, const std::string& modifiers)
{
    CascadeCommand parsed = parse_cascade_command(command, modifiers);
    CascadeOptions& opt = parsed.options;
    opt.seed = state.seed;
    opt.nthreads = state.threads;

    const OIIO::ImageBuf dilation = read_control(command, "dilation", parsed.dilation);
    const OIIO::ImageBuf rotation = read_control(command, "rotation", parsed.rotation);

    // A generator's result is written like a float input's: scene-linear in float files,
    // and in the space of untagged integer files (sRGB) in integer ones.
    StackImage initial;
    const bool transfer = !state.stack.empty();
    if (transfer) {
        initial = state.pop(command);
        if (!parsed.sized) {
            opt.width = initial.buf.spec().width;
            opt.height = initial.buf.spec().height;
        }
    } else {
        initial.input_colorspace
            = state.colors().guess_colorspace(OIIO::ImageSpec(1, 1, 3, OIIO::TypeUInt8));
        initial.input_format = OIIO::TypeUnknown;
        initial.output_colorspace = state.pending_tocolorspace;
    }
    // The palette is read like any input (so in scene-linear), after the initial image.
    StackImage palette;
    if (!parsed.palette.empty()) {
        push_input(state, parsed.palette);
        palette = state.pop(command);
    }
    run_synthesis(
        state, command, synthesis_result(initial, initial.sources), "", [&](StackImage& r) {
            return cascade_synthesize(r.buf, opt, transfer ? &initial.buf : nullptr,
                parsed.dilation.empty() ? nullptr : &dilation,
                parsed.rotation.empty() ? nullptr : &rotation,
                parsed.palette.empty() ? nullptr : &palette.buf);
        });
}

} // namespace texsyn::cli
