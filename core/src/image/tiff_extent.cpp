// SPDX-License-Identifier: Apache-2.0
// Whether a TIFF file holds the pixel data its first directory points at. libtiff reports
// a strip or tile cut short or damaged for most compressions, but OIIO 2.4 reads
// JPEG-compressed TIFF through libtiff's RGBA interface, which fills the rows of a strip it
// cannot decode from the strips before and reports success. So the directory's offsets and
// byte counts are checked against the file's size, and every strip or tile of a JPEG TIFF
// is decoded once with libtiff.
#include "io_pvt.h"

#include <algorithm>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <vector>

#include <tiffio.h>

namespace texsyn {

namespace {

class TiffReader {
public:
    explicit TiffReader(const std::string& path)
        : m_in(path, std::ios::binary)
    {
        m_in.seekg(0, std::ios::end);
        m_size = uint64_t(std::max<std::streamoff>(0, m_in.tellg()));
    }

    uint64_t size() const { return m_size; }

    /// The unsigned integer of `bytes` bytes at `offset` in the file's byte order.
    bool read(uint64_t offset, int bytes, uint64_t& value)
    {
        unsigned char b[8] = {};
        if (offset > m_size || uint64_t(bytes) > m_size - offset)
            return false;
        m_in.seekg(std::streamoff(offset));
        if (!m_in.read(reinterpret_cast<char*>(b), bytes))
            return false;
        value = 0;
        for (int i = 0; i < bytes; ++i)
            value |= uint64_t(b[m_big_endian ? i : bytes - 1 - i]) << (8 * (bytes - 1 - i));
        return true;
    }

    void set_big_endian(bool big) { m_big_endian = big; }

private:
    std::ifstream m_in;
    uint64_t m_size = 0;
    bool m_big_endian = false;
};

/// The values of an IFD entry whose type is SHORT (3), LONG (4) or LONG8 (16).
bool entry_values(TiffReader& f, uint64_t entry, bool big_tiff, std::vector<uint64_t>& values)
{
    uint64_t type = 0, count = 0;
    const int count_bytes = big_tiff ? 8 : 4;
    if (!f.read(entry + 2, 2, type) || !f.read(entry + 4, count_bytes, count))
        return false;
    const int size = type == 3 ? 2 : type == 4 ? 4 : type == 16 ? 8 : 0;
    if (!size || count > f.size())
        return false;
    const uint64_t field = entry + 4 + uint64_t(count_bytes);
    uint64_t at = field;
    if (count * uint64_t(size) > uint64_t(count_bytes) && !f.read(field, count_bytes, at))
        return false;
    values.resize(size_t(count));
    for (uint64_t i = 0; i < count; ++i)
        if (!f.read(at + i * uint64_t(size), size, values[size_t(i)]))
            return false;
    return true;
}

/// libtiff's messages for one file, kept (the first) instead of printed.
int keep_first_message(TIFF*, void* user_data, const char*, const char* fmt, va_list ap)
{
    auto* message = static_cast<std::string*>(user_data);
    if (message && message->empty()) {
        char text[512];
        std::vsnprintf(text, sizeof(text), fmt, ap);
        *message = text;
    }
    return 1;
}

/// False, with the reason, if a strip or tile of the JPEG-compressed TIFF `path` does not
/// decode; true for any other file (its reader reports its own errors).
bool jpeg_tiff_strips_decode(const std::string& path, std::string& reason)
{
    // A warning while decoding means damage too: libjpeg warns of a strip that ends early
    // ("Premature end of JPEG file") and fills the rest with grey. Warnings while opening
    // (unknown tags) do not count.
    std::string message, warning;
    TIFFOpenOptions* options = TIFFOpenOptionsAlloc();
    TIFFOpenOptionsSetErrorHandlerExtR(options, keep_first_message, &message);
    TIFFOpenOptionsSetWarningHandlerExtR(options, keep_first_message, &warning);
    TIFF* tif = TIFFOpenExt(path.c_str(), "r", options);
    TIFFOpenOptionsFree(options);
    if (!tif)
        return true;
    warning.clear();
    uint16_t compression = COMPRESSION_NONE;
    TIFFGetFieldDefaulted(tif, TIFFTAG_COMPRESSION, &compression);
    bool ok = true;
    if (compression == COMPRESSION_JPEG || compression == COMPRESSION_OJPEG) {
        const bool tiled = TIFFIsTiled(tif);
        const tmsize_t size = tiled ? TIFFTileSize(tif) : TIFFStripSize(tif);
        const uint32_t count = tiled ? TIFFNumberOfTiles(tif) : TIFFNumberOfStrips(tif);
        std::vector<unsigned char> buffer(size_t(std::max<tmsize_t>(size, 1)));
        for (uint32_t i = 0; ok && i < count; ++i) {
            ok = size > 0
                && (tiled ? TIFFReadEncodedTile(tif, i, buffer.data(), size)
                          : TIFFReadEncodedStrip(tif, i, buffer.data(), size))
                    > 0
                && warning.empty();
            if (!ok) {
                const std::string& why = message.empty() ? warning : message;
                reason = "strip or tile " + std::to_string(i) + " of " + std::to_string(count)
                    + " does not decode" + (why.empty() ? "" : " (" + why + ")");
            }
        }
    }
    TIFFClose(tif);
    return ok;
}

} // namespace

bool tiff_data_fits_in_file(const std::string& path, std::string& reason)
{
    TiffReader f(path);
    uint64_t order = 0, magic = 0;
    if (!f.read(0, 2, order) || (order != 0x4949 && order != 0x4d4d))
        return true; // not a TIFF this check knows: left to the reader
    f.set_big_endian(order == 0x4d4d);
    if (!f.read(2, 2, magic) || (magic != 42 && magic != 43))
        return true;
    const bool big_tiff = magic == 43;
    const int offset_bytes = big_tiff ? 8 : 4;
    uint64_t ifd = 0, entries = 0;
    if (!f.read(big_tiff ? 8 : 4, offset_bytes, ifd) || !f.read(ifd, big_tiff ? 8 : 2, entries)) {
        reason = "its first directory is outside the file";
        return false;
    }
    std::vector<uint64_t> offsets, counts;
    const uint64_t first = ifd + (big_tiff ? 8 : 2), entry_bytes = big_tiff ? 20 : 12;
    for (uint64_t e = 0; e < entries && e < 4096; ++e) {
        const uint64_t entry = first + e * entry_bytes;
        uint64_t tag = 0;
        if (!f.read(entry, 2, tag)) {
            reason = "its first directory is cut short";
            return false;
        }
        // StripOffsets/TileOffsets and StripByteCounts/TileByteCounts.
        std::vector<uint64_t>* into = tag == 273 || tag == 324 ? &offsets
            : tag == 279 || tag == 325                         ? &counts
                                                               : nullptr;
        if (into && !entry_values(f, entry, big_tiff, *into)) {
            reason = "its strip or tile table is outside the file";
            return false;
        }
    }
    for (size_t i = 0; i < offsets.size() && i < counts.size(); ++i)
        if (offsets[i] > f.size() || counts[i] > f.size() - offsets[i]) {
            reason = "it is cut short: strip or tile " + std::to_string(i) + " of "
                + std::to_string(offsets.size()) + " ends at byte "
                + std::to_string(offsets[i] + counts[i]) + " of a file of "
                + std::to_string(f.size());
            return false;
        }
    return jpeg_tiff_strips_decode(path, reason);
}

} // namespace texsyn
