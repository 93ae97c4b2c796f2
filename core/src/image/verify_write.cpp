// SPDX-License-Identifier: Apache-2.0
// Written files are checked before they are committed: image libraries do not all report
// a full disk (a PNG ends truncated, a TGA sparse, and OIIO's ImageBuf::write ignores what
// the writer's close() returns). So an image is encoded in memory and its bytes written
// here, every write() checked, then fsynced; one that cannot be (no memory writer, too
// large) is written by the library and then checked: the bytes reached the disk (fsync),
// the file has no holes, and an image decodes completely.
#include <texsyn/io.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <texsyn/memory.h>

#include "io_pvt.h"

namespace texsyn {

namespace {

std::string errno_text(const char* what)
{
    return std::string(what) + " (" + std::strerror(errno) + ")";
}

// write_bytes() for `size` bytes at `data`.
bool write_file(const std::string& path, const void* data, size_t size, std::string& reason)
{
    // Never through a link, and never into a FIFO or device (O_NONBLOCK: opening a FIFO
    // with no reader would block).
    const int fd = ::open(
        path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0666);
    if (fd < 0) {
        reason = errno_text("cannot create");
        return false;
    }
    struct stat st;
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        reason = "cannot create (not a regular file)";
        ::close(fd);
        return false;
    }
    const auto* bytes = static_cast<const char*>(data);
    size_t done = 0;
    while (done < size) {
        const ssize_t n = ::write(fd, bytes + done, size - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            reason = errno_text("write error");
            ::close(fd);
            return false;
        }
        done += size_t(n);
    }
    if (::fsync(fd) != 0) {
        reason = errno_text("the data did not reach the disk");
        ::close(fd);
        return false;
    }
    if (::close(fd) != 0) {
        reason = errno_text("write error");
        return false;
    }
    return true;
}

// Images whose pixels at the file's type take more than this are written by the library
// and read back, rather than held a second time, encoded, in memory.
constexpr size_t max_encoded_in_memory = size_t(256) << 20;

// The size of `image`'s pixels at the file's pixel type, if they are in memory and packed
// (so that an ImageBuf wrapping them writes the same file); else 0.
size_t packed_file_bytes(const OIIO::ImageBuf& image, OIIO::TypeDesc format)
{
    const OIIO::ImageSpec& spec = image.spec();
    if (!image.localpixels() || image.pixel_stride() != OIIO::stride_t(spec.pixel_bytes())
        || image.scanline_stride() != OIIO::stride_t(spec.scanline_bytes())
        || image.z_stride() != OIIO::stride_t(spec.scanline_bytes() * size_t(spec.height)))
        return 0;
    OIIO::ImageSpec file = spec;
    if (format != OIIO::TypeUnknown)
        file.set_format(format);
    return size_t(file.image_bytes());
}

} // namespace

bool encode_in_memory(const OIIO::ImageBuf& image, const std::string& path, OIIO::TypeDesc format,
    std::vector<unsigned char>& bytes, std::string& reason)
{
    const size_t raw = packed_file_bytes(image, format);
    std::string refusal;
    if (raw == 0 || raw > max_encoded_in_memory || !check_memory(raw, "the encoded image", refusal))
        return false;
    auto out = OIIO::ImageOutput::create(path);
    if (!out || !out->supports("ioproxy")) {
        (void)OIIO::geterror();
        return false;
    }
    out.reset();
    bytes.clear();
    bytes.reserve(raw + (size_t(1) << 16)); // what most files need: no regrowth
    OIIO::Filesystem::IOVecOutput memory(bytes);
    OIIO::ImageBuf view(image.spec(), const_cast<void*>(image.localpixels()));
    view.set_write_ioproxy(&memory);
    if (!view.write(path, format)) {
        reason = one_line(view.geterror());
        return false;
    }
    // A memory writer can fail silently where a file writer does not (OIIO 2.4's TIFF writer
    // leaves out its directory when the file has an Exif block): the bytes must at least
    // open as an image of the right size and channels.
    OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::create(path, false, nullptr, &reader);
    // create() uses the proxy only to choose the reader: open() reads the file named `path`
    // unless the proxy is set on the reader itself.
    if (in)
        in->set_ioproxy(&reader);
    OIIO::ImageSpec got;
    const OIIO::ImageSpec& spec = image.spec();
    const bool ok = in && in->open(path, got) && got.width == spec.width
        && got.height == spec.height && got.nchannels == spec.nchannels;
    if (in && !ok)
        (void)in->geterror();
    (void)OIIO::geterror();
    return ok;
}

bool write_image_checked(const OIIO::ImageBuf& image, const std::string& path,
    OIIO::TypeDesc format, std::string& reason)
{
    std::vector<unsigned char> bytes;
    if (encode_in_memory(image, path, format, bytes, reason))
        return write_file(path, bytes.data(), bytes.size(), reason);
    if (!reason.empty()) // the encoder refused the image
        return false;
    if (!image.write(path, format)) {
        reason = one_line(image.geterror());
        return false;
    }
    return sync_written_file(path, reason) && verify_image_file(path, image.spec(), reason);
}

std::string one_line(std::string s)
{
    for (char& c : s)
        if (c == '\n')
            c = ' ';
    while (!s.empty() && s.back() == ' ')
        s.pop_back();
    return s;
}

bool sync_written_file(const std::string& path, std::string& reason)
{
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        reason = errno_text("the written file cannot be opened");
        return false;
    }
    bool ok = true;
    struct stat st { };
    if (::fsync(fd) != 0) {
        reason = errno_text("the data did not reach the disk");
        ok = false;
    } else if (::fstat(fd, &st) != 0) {
        reason = errno_text("the written file cannot be examined");
        ok = false;
    } else if (st.st_size == 0) {
        reason = "nothing was written (disk full?)";
        ok = false;
    } else {
        const off_t hole = ::lseek(fd, 0, SEEK_HOLE);
        if (hole >= 0 && hole < st.st_size) {
            reason = "the file has unwritten gaps (disk full?)";
            ok = false;
        }
    }
    ::close(fd);
    return ok;
}

bool verify_image_file(
    const std::string& path, const OIIO::ImageSpec& expected, std::string& reason)
{
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        reason = "the written file is incomplete (disk full?): " + one_line(OIIO::geterror());
        return false;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width != expected.width || spec.height != expected.height) {
        reason = "the written file reads back with another size";
        return false;
    }
    // Decode every pixel (scanline files in bands of rows, to bound memory), so that a
    // truncated file is found whatever its format.
    std::vector<unsigned char> pixels;
    bool ok = true;
    if (spec.tile_width) {
        pixels.resize(spec.image_bytes(true));
        ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeUnknown, pixels.data());
    } else {
        const size_t row = std::max<size_t>(spec.scanline_bytes(true), 1);
        const int band = std::max(1, int((size_t(64) << 20) / row));
        for (int z = spec.z; ok && z < spec.z + spec.depth; ++z)
            for (int y = spec.y; ok && y < spec.y + spec.height; y += band) {
                const int yend = std::min(spec.y + spec.height, y + band);
                pixels.resize(row * size_t(yend - y));
                ok = in->read_scanlines(
                    0, 0, y, yend, z, 0, spec.nchannels, OIIO::TypeUnknown, pixels.data());
            }
    }
    // Some readers (libjpeg on a truncated file) decode what is there, report success and
    // only record the error.
    if (!ok || in->has_error()) {
        reason = "the written file is incomplete (disk full?): " + one_line(in->geterror());
        return false;
    }
    return true;
}

bool write_bytes(const std::string& path, const std::string& bytes, std::string& reason)
{
    return write_file(path, bytes.data(), bytes.size(), reason);
}

} // namespace texsyn
