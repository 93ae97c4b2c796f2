// SPDX-License-Identifier: Apache-2.0
// Written files are checked before they are committed: image libraries do not all report
// a full disk (a PNG ends truncated, a TGA sparse), so success means the bytes reached the
// disk (fsync), the file has no holes, and an image decodes completely.
#include <texsyn/io.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "io_pvt.h"

namespace texsyn {

namespace {

std::string errno_text(const char* what)
{
    return std::string(what) + " (" + std::strerror(errno) + ")";
}

} // namespace

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
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        reason = errno_text("cannot create");
        return false;
    }
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
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

} // namespace texsyn
