// SPDX-License-Identifier: Apache-2.0
#include <texsyn/io.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <system_error>

#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace texsyn {

namespace fs = std::filesystem;

bool check_regular_file(const std::string& filename, const std::string& what, std::string& error)
{
    std::error_code ec;
    const fs::file_status status = fs::status(filename, ec);
    if (ec || !fs::exists(status)) {
        error = filename + ": no such file";
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

bool read_image(
    const std::string& filename, OIIO::ImageBuf& dst, std::string& error, OIIO::ImageSpec* native)
{
    if (!check_regular_file(filename, "an image", error))
        return false;
    // Read with an ImageInput of our own, not through OIIO's shared ImageCache: texsyn runs
    // inside OIIO tools (as their format plugin), whose cache must not be re-entered while
    // it is opening the recipe. Ask for un-associated colour where the file stores it that
    // way (PNG, most TIFF): OIIO would otherwise premultiply 8-bit values, losing colour
    // under low alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto fail = [&](std::string msg) {
        if (msg.empty())
            msg = OIIO::geterror();
        error = filename + ": cannot read image" + (msg.empty() ? "" : " (" + msg + ")");
        // OIIO messages can span lines; the tool prints one line per error.
        for (char& c : error)
            if (c == '\n')
                c = ' ';
        return false;
    };
    auto in = OIIO::ImageInput::open(filename, &config);
    if (!in)
        return fail(OIIO::geterror());
    OIIO::ImageSpec spec = in->spec();
    spec.format = OIIO::TypeFloat;
    spec.channelformats.clear();
    OIIO::ImageBuf buf(spec);
    if (!buf.localpixels()) // OIIO logs a failed allocation and leaves no pixels
        return fail("not enough memory for its " + std::to_string(spec.width) + "x"
            + std::to_string(spec.height) + " pixels");
    // All pixels now, so truncation is found here and not mid-synthesis.
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, buf.localpixels()))
        return fail(in->geterror());
    if (native)
        *native = in->spec();
    dst = std::move(buf);
    return true;
}

std::string temporary_path_for(const std::string& filename)
{
    static std::atomic<unsigned> counter { 0 };
    fs::path p(filename);
    // Within NAME_MAX (255) even for a long name: the stem is shortened, never the marker,
    // pid and extension that make the file recognisable.
    const std::string tag = ".texsyn-tmp" + std::to_string(::getpid()) + "-"
        + std::to_string(counter++) + p.extension().string();
    std::string stem = p.stem().string();
    if (1 + stem.size() + tag.size() > 255)
        stem.resize(255 - 1 - std::min<size_t>(tag.size(), 254));
    const std::string name = "." + stem + tag;
    return (p.parent_path() / name).string();
}

bool commit_file(const std::string& temporary, const std::string& filename, std::string& error)
{
    std::error_code ec;
    fs::rename(temporary, filename, ec);
    if (ec) {
        fs::remove(temporary, ec);
        error = filename + ": cannot write (" + ec.message() + ")";
        return false;
    }
    return true;
}

bool same_file(const std::string& a, const std::string& b)
{
    std::error_code ec;
    bool eq = fs::equivalent(a, b, ec);
    return !ec && eq;
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
        (void)OIIO::geterror();
        error = filename + ": cannot write (no image format for extension '"
            + fs::path(filename).extension().string() + "')";
        return false;
    }
    out.reset();
    std::string tmp = temporary_path_for(filename);
    if (!image.write(tmp, format)) {
        std::string msg = image.geterror();
        for (char& c : msg)
            if (c == '\n')
                c = ' ';
        fs::remove(tmp, ec);
        error = filename + ": cannot write (" + msg + ")";
        return false;
    }
    return commit_file(tmp, filename, error);
}

bool write_multipart_exr(const std::string& filename, const std::vector<OIIO::ImageSpec>& specs,
    const std::function<void(size_t, OIIO::ImageBuf&)>& part, std::string& error)
{
    const std::string tmp = temporary_path_for(filename);
    auto fail = [&](const std::string& msg) {
        std::error_code ec;
        fs::remove(tmp, ec);
        error = filename + ": cannot write (" + msg + ")";
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
    return commit_file(tmp, filename, error);
}

} // namespace texsyn
