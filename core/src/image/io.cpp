// SPDX-License-Identifier: Apache-2.0
#include <texsyn/io.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <system_error>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/strutil.h>

#include <texsyn/memory.h>
#include <texsyn/recipe.h>

#include "io_pvt.h"

namespace texsyn {

namespace fs = std::filesystem;

bool check_regular_file(const std::string& filename, const std::string& what, std::string& error)
{
    std::error_code ec;
    const fs::file_status status = fs::status(filename, ec);
    if (ec || !fs::exists(status)) {
        error = filename
            + (ec == std::errc::too_many_symbolic_link_levels ? ": is a loop of symbolic links"
                                                              : ": no such file");
        return false;
    }
    if (fs::is_directory(status)) {
        error = filename + ": is a directory, not " + what;
        return false;
    }
    if (!fs::is_regular_file(status)) {
        error = filename + ": is not a regular file (a FIFO, device or socket), not " + what;
        return false;
    }
    return true;
}

namespace {

// "FILE: cannot read image (reason)", on one line: OIIO messages can span lines and the
// tool prints one line per error.
std::string cannot_read(const std::string& filename, const std::string& reason)
{
    return one_line(filename + ": cannot read image" + (reason.empty() ? "" : " (" + reason + ")"));
}

/// Reads every pixel of `in`'s current subimage as float into `pixels` (the whole image,
/// channel-interleaved), in bands of rows, and stops at the first band that fails or that
/// leaves an error behind: some readers (libjpeg on a truncated file) report success and
/// only record the error, and some (TIFF) record one error per missing row, which for a
/// header claiming a billion rows would grow past OIIO's limit and abort the process.
bool read_all_pixels(OIIO::ImageInput& in, float* pixels)
{
    const OIIO::ImageSpec& spec = in.spec();
    if (spec.depth > 1)
        return in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, pixels) && !in.has_error();
    const int band = spec.tile_height > 0
        ? std::max(spec.tile_height, 64 / spec.tile_height * spec.tile_height)
        : 64;
    const size_t row = size_t(spec.width) * size_t(spec.nchannels);
    for (int y = spec.y; y < spec.y + spec.height; y += band) {
        const int y1 = std::min(y + band, spec.y + spec.height);
        float* dst = pixels + size_t(y - spec.y) * row;
        const bool ok = spec.tile_width > 0
            ? in.read_tiles(0, 0, spec.x, spec.x + spec.width, y, y1, spec.z, spec.z + 1, 0,
                spec.nchannels, OIIO::TypeFloat, dst)
            : in.read_scanlines(0, 0, y, y1, spec.z, 0, spec.nchannels, OIIO::TypeFloat, dst);
        if (!ok || in.has_error())
            return false;
    }
    return true;
}

} // namespace

namespace {

// The file opened for reading (see read_image), its header checked: the TIFF extent, and
// `copies` float copies of its pixels against the memory limit. Null with `error`.
std::unique_ptr<OIIO::ImageInput> open_checked(
    const std::string& filename, int copies, std::string& error)
{
    if (!check_regular_file(filename, "an image", error))
        return nullptr;
    // A recipe is a few hundred bytes: a large one is refused from its size, before OIIO,
    // whose readers (DICOM's) would read the whole file looking for a format that opens it.
    if (OIIO::Strutil::iends_with(filename, ".texsyn") && !check_recipe_file_size(filename, error))
        return nullptr;
    // Read with an ImageInput of our own, not through OIIO's shared ImageCache: texsyn runs
    // inside OIIO tools (as their format plugin), whose cache must not be re-entered while
    // it is opening the recipe. Ask for un-associated colour where the file stores it that
    // way (PNG, most TIFF): OIIO would otherwise premultiply 8-bit values, losing colour
    // under low alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(filename, &config);
    if (!in) {
        error = cannot_read(filename, OIIO::geterror());
        return nullptr;
    }
    if (std::string reason;
        std::string(in->format_name()) == "tiff" && !tiff_data_fits_in_file(filename, reason)) {
        error = cannot_read(filename, reason);
        return nullptr;
    }
    // Refuse from the header, before any pixel is allocated or decoded: a few bytes of
    // PNG can claim 100000x100000 pixels.
    const OIIO::ImageSpec& spec = in->spec();
    std::string refusal;
    if (!check_memory(
            size_t(std::min(
                1e18, double(spec.image_pixels()) * spec.nchannels * 4.0 * std::max(copies, 1))),
            "its " + std::to_string(spec.width) + "x" + std::to_string(spec.height)
                + (spec.depth > 1 ? "x" + std::to_string(spec.depth) : "") + " pixels",
            refusal)) {
        error = filename + ": " + refusal;
        return nullptr;
    }
    return in;
}

} // namespace

bool read_image_spec(
    const std::string& filename, OIIO::ImageSpec& spec, std::string& error, int copies)
{
    auto in = open_checked(filename, copies, error);
    if (!in)
        return false;
    spec = in->spec();
    return true;
}

bool read_image(const std::string& filename, OIIO::ImageBuf& dst, std::string& error,
    OIIO::ImageSpec* native, int copies)
{
    auto fail = [&](std::string msg) {
        error = cannot_read(filename, msg.empty() ? OIIO::geterror() : msg);
        return false;
    };
    auto in = open_checked(filename, copies, error);
    if (!in)
        return false;
    OIIO::ImageSpec spec = in->spec();
    spec.format = OIIO::TypeFloat;
    spec.channelformats.clear();
    OIIO::ImageBuf buf(spec, OIIO::InitializePixels::No); // every pixel is read below
    if (!buf.localpixels()) // OIIO logs a failed allocation and leaves no pixels
        return fail("not enough memory for its " + std::to_string(spec.width) + "x"
            + std::to_string(spec.height) + " pixels");
    // All pixels now, so truncation is found here and not mid-synthesis.
    if (!read_all_pixels(*in, static_cast<float*>(buf.localpixels())))
        return fail(in->geterror());
    if (native)
        *native = in->spec();
    dst = std::move(buf);
    return true;
}

bool same_file(const std::string& a, const std::string& b)
{
    std::error_code ec;
    bool eq = fs::equivalent(a, b, ec);
    return !ec && eq;
}

bool write_image_verified(
    const OIIO::ImageBuf& image, const std::string& path, OIIO::TypeDesc format, std::string& error)
{
    std::string reason;
    if (OIIO::Strutil::iends_with(path, ".tx")) {
        // A texture for renderers: tiled, MIP-mapped by OIIO's own texture maker, wrapping
        // as the image says (a synthesis that tiles: periodic). Written by OIIO, so read
        // back as every such file is.
        OIIO::ImageSpec config;
        config.set_format(format == OIIO::TypeUnknown ? image.spec().format : format);
        config.tile_width = config.tile_height = 64;
        config.tile_depth = 1;
        config.attribute("compression", "zip");
        config.attribute(
            "wrapmodes", image.spec().get_string_attribute("wrapmodes", "black,black"));
        if (!OIIO::ImageBufAlgo::make_texture(
                OIIO::ImageBufAlgo::MakeTxTexture, image, path, config))
            reason = one_line(OIIO::geterror());
        else if (sync_written_file(path, reason) && verify_image_file(path, image.spec(), reason))
            return true;
    } else if (write_image_checked(image, path, format, reason))
        return true;
    std::error_code ec;
    fs::remove(path, ec);
    error = path + ": cannot write (" + (reason.empty() ? "unknown error" : reason) + ")";
    return false;
}

bool write_image_atomic(const OIIO::ImageBuf& image, const std::string& filename,
    OIIO::TypeDesc format, std::string& error)
{
    std::error_code ec;
    fs::path parent = fs::path(filename).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec)) {
        error = filename + ": cannot write (directory " + parent.string() + " does not exist)";
        return false;
    }
    auto out = OIIO::ImageOutput::create(filename);
    if (!out) {
        const std::string why = one_line(OIIO::geterror());
        error = filename + ": cannot write ("
            + (why.empty() ? "no image format for extension '"
                        + fs::path(filename).extension().string() + "'"
                           : why)
            + ")";
        return false;
    }
    out.reset();
    if (!check_output_destination(filename, error))
        return false;
    const std::string tmp = temporary_path_for(filename);
    if (write_image_verified(image, tmp, format, error))
        return commit_file(tmp, filename, error);
    discard_temporary(tmp);
    error = filename + error.substr(tmp.size());
    return false;
}

bool write_multipart_exr(const std::string& filename, const std::vector<OIIO::ImageSpec>& specs,
    const std::function<void(size_t, OIIO::ImageBuf&)>& part, std::string& error)
{
    if (!check_output_destination(filename, error))
        return false;
    const std::string tmp = temporary_path_for(filename);
    auto fail = [&](const std::string& msg) {
        discard_temporary(tmp);
        error = filename + ": cannot write (" + one_line(msg) + ")";
        return false;
    };
    auto out = OIIO::ImageOutput::create("exr");
    if (!out || !out->supports("multiimage"))
        return fail("this OpenImageIO cannot write multi-part OpenEXR");
    if (!out->open(tmp, int(specs.size()), specs.data()))
        return fail(out->geterror());
    for (size_t i = 0; i < specs.size(); ++i) {
        if (i && !out->open(tmp, specs[i], OIIO::ImageOutput::AppendSubimage))
            return fail(out->geterror());
        OIIO::ImageBuf pixels;
        part(i, pixels);
        if (!out->write_image(OIIO::TypeFloat, pixels.localpixels()))
            return fail(out->geterror());
    }
    if (!out->close())
        return fail(out->geterror());
    std::string reason;
    if (!sync_written_file(tmp, reason))
        return fail(reason);
    // Every part decodes completely: a full disk truncates the last parts.
    auto in = OIIO::ImageInput::open(tmp);
    if (!in)
        return fail("the written file is incomplete (disk full?): " + one_line(OIIO::geterror()));
    std::vector<float> pixels;
    for (size_t i = 0; i < specs.size(); ++i) {
        if (!in->seek_subimage(int(i), 0))
            return fail("the written file is incomplete (disk full?): part " + std::to_string(i)
                + " is missing");
        pixels.resize(size_t(in->spec().image_pixels()) * size_t(in->spec().nchannels));
        if (!in->read_image(int(i), 0, 0, in->spec().nchannels, OIIO::TypeFloat, pixels.data()))
            return fail("the written file is incomplete (disk full?): " + one_line(in->geterror()));
    }
    return commit_file(tmp, filename, error);
}

} // namespace texsyn
