// SPDX-License-Identifier: Apache-2.0
// Reading samples into scene-linear float and writing results in the policy's colour space.
#include "cli_state.h"

#include <cstdio>

#include <fcntl.h>
#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/io.h>
#include <texsyn/subbands.h>

namespace texsyn::cli {

namespace {

bool is_float_format(const std::string& filename)
{
    std::string ext = OIIO::Strutil::lower(OIIO::Filesystem::extension(filename, false));
    return ext == "exr" || ext == "sxr" || ext == "mxr" || ext == "hdr" || ext == "rgbe"
        || ext == "pfm";
}

OIIO::TypeDesc output_type(const CliState& state, const std::string& filename)
{
    if (!state.data_format.empty())
        return OIIO::TypeDesc(state.data_format);
    return is_float_format(filename) ? OIIO::TypeHalf : OIIO::TypeUInt8;
}

void convert_buf(CliState& state, OIIO::ImageBuf& buf, const std::string& from,
    const std::string& to, const std::string& what)
{
    PlanarImage planes;
    std::string error;
    if (!planes_from_imagebuf(buf, planes, error))
        throw CliError(what + ": " + error);
    if (!state.colors().convert(planes, from, to, error, state.threads))
        throw CliError(what + ": " + error);
    OIIO::ImageSpec original = buf.spec();
    imagebuf_from_planes(planes, buf);
    for (const OIIO::ParamValue& p : original.extra_attribs)
        buf.specmod().attribute(p.name(), p.type(), p.data());
}

// Image libraries (libpng, libtiff) print their own diagnostics on stderr before OIIO
// reports the error; the tool states each error once, on one line, so silence them while
// a file is read.
class QuietStderr {
public:
    QuietStderr()
    {
        std::fflush(stderr);
        m_saved = ::dup(STDERR_FILENO);
        int devnull = ::open("/dev/null", O_WRONLY);
        if (m_saved >= 0 && devnull >= 0)
            ::dup2(devnull, STDERR_FILENO);
        if (devnull >= 0)
            ::close(devnull);
    }
    ~QuietStderr()
    {
        std::fflush(stderr);
        if (m_saved >= 0) {
            ::dup2(m_saved, STDERR_FILENO);
            ::close(m_saved);
        }
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

private:
    int m_saved = -1;
};

} // namespace

void push_input(CliState& state, const std::string& filename)
{
    StackImage img;
    std::string error;
    bool ok;
    {
        QuietStderr quiet;
        ok = read_image(filename, img.file_pixels, error);
    }
    if (!ok)
        throw CliError(error);
    img.source = filename;
    img.output_colorspace = state.pending_tocolorspace;
    state.stack.push_back(std::move(img));
    std::string space = state.pending_iscolorspace.empty()
        ? state.colors().guess_colorspace(state.stack.back().file_pixels.spec())
        : state.pending_iscolorspace;
    state.pending_iscolorspace.clear();
    reinterpret_input(state, space);
}

void reinterpret_input(CliState& state, const std::string& colorspace)
{
    StackImage& img = state.top("--iscolorspace");
    if (!img.file_pixels.initialized())
        throw CliError("--iscolorspace : the current image is not an input file "
                       "(put --iscolorspace right after the file name)");
    const ColorConfig& cc = state.colors();
    std::string space = cc.resolve(colorspace);
    if (space.empty())
        throw CliError("--iscolorspace : unknown colour space '" + colorspace + "'");
    PlanarImage planes;
    std::string error;
    if (!planes_from_imagebuf(img.file_pixels, planes, error))
        throw CliError(img.source + ": " + error);
    if (!cc.convert(planes, space, cc.scene_linear(), error, state.threads))
        throw CliError(img.source + ": " + error);
    imagebuf_from_planes(planes, img.buf);
    img.input_colorspace = space;
}

void write_output(CliState& state, const std::string& filename)
{
    StackImage& img = state.top("-o");
    const ColorConfig& cc = state.colors();
    OIIO::TypeDesc type = output_type(state, filename);
    if (type == OIIO::TypeUnknown)
        throw CliError("-d : unknown data format '" + state.data_format
            + "' (use uint8, uint16, half or float)");
    std::string space = img.output_colorspace;
    if (space.empty())
        space = type.is_floating_point() ? cc.scene_linear() : img.input_colorspace;
    if (cc.resolve(space).empty())
        throw CliError("--tocolorspace : unknown colour space '" + space + "'");
    space = cc.resolve(space);

    OIIO::ImageBuf out;
    out.copy(img.buf);
    convert_buf(state, out, cc.scene_linear(), space, filename);
    OIIO::ImageSpec& spec = out.specmod();
    spec.attribute("synth:sample", OIIO::Filesystem::filename(img.source));
    spec.attribute("synth:colorspace", space);
    spec.attribute("synth:commandline", state.command_line);
    spec.attribute("oiio:ColorSpace", space);
    // Reproducible files: OIIO would otherwise stamp the current time.
    spec.attribute("DateTime", "2000:01:01 00:00:00");

    std::string error;
    if (state.subbands) {
        if (img.subbands.empty())
            throw CliError(
                "-o " + filename + " : --subbands needs a synthesis on the stack (e.g. --pyramid)");
        if (!write_subband_exr(filename, out, img.subbands, error))
            throw CliError(error);
        return;
    }
    if (!write_image_atomic(out, filename, type, error))
        throw CliError(error);
}

} // namespace texsyn::cli
