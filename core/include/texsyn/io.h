// SPDX-License-Identifier: Apache-2.0
// File input and atomic output. Every message names the file.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

namespace texsyn {

/// Reads the first subimage of `filename` completely into a float ImageBuf (its metadata
/// included), with colour left un-associated from alpha where the file stores it so (the
/// spec then says "oiio:UnassociatedAlpha"). Reads with its own ImageInput, never through
/// OIIO's shared ImageCache, so it is safe inside an OIIO format plugin. If `native` is not
/// null it receives the file's own spec (pixel type included). Fails (false, "FILE:
/// reason") if the file is missing, not a regular file, unreadable, truncated or not an
/// image, or if its pixels cannot be allocated.
bool read_image(const std::string& filename, OIIO::ImageBuf& dst, std::string& error,
    OIIO::ImageSpec* native = nullptr);

/// False (with "FILE: no such file", "FILE: is a directory, not WHAT" or "FILE: is not a
/// regular file (a FIFO, device or socket), not WHAT") unless `filename` is a regular file
/// (after links). Checked before any library opens a file: reading a FIFO or /dev/zero
/// would block or never end.
bool check_regular_file(const std::string& filename, const std::string& what, std::string& error);

/// A path in the same directory as `filename`, with the same extension (so OIIO picks the
/// same format), that does not exist yet: write there, then commit_file().
std::string temporary_path_for(const std::string& filename);

/// Renames `temporary` over `filename` (atomic on one file system); removes `temporary`
/// and fails if the rename fails.
bool commit_file(const std::string& temporary, const std::string& filename, std::string& error);

/// Whether `a` and `b` name the same existing file (after resolving links and "..").
bool same_file(const std::string& a, const std::string& b);

/// Writes `image` to `filename` atomically (temporary file + rename): a failed write
/// leaves no file behind and never an incomplete one. `format` is the pixel type on disk
/// (TypeUnknown = the buffer's). Fails (false, "FILE: reason").
bool write_image_atomic(const OIIO::ImageBuf& image, const std::string& filename,
    OIIO::TypeDesc format, std::string& error);

/// Writes a multi-part OpenEXR atomically: one part per entry of `specs` (OpenEXR requires
/// them to share one display window; "oiio:subimagename" names a part), the pixels of part
/// i from `part(i, buf)`, which fills `buf` with a float image of that part's data size
/// and channels. Fails (false, "FILE: cannot write (reason)") leaving no file behind.
bool write_multipart_exr(const std::string& filename, const std::vector<OIIO::ImageSpec>& specs,
    const std::function<void(size_t, OIIO::ImageBuf&)>& part, std::string& error);

} // namespace texsyn
