// SPDX-License-Identifier: Apache-2.0
// File input and atomic output. Every message names the file.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// Reads the first subimage of `filename` completely into a float ImageBuf (its metadata
/// included), with colour left un-associated from alpha where the file stores it so (the
/// spec then says "oiio:UnassociatedAlpha"). Reads with its own ImageInput, never through
/// OIIO's shared ImageCache, so it is safe inside an OIIO format plugin. If `native` is not
/// null it receives the file's own spec (pixel type included). Fails (false, "FILE:
/// reason") if the file is missing, not a regular file, unreadable, truncated or not an
/// image, or if `copies` float copies of its pixels (what the caller will hold at once)
/// would exceed the memory limit (texsyn/memory.h; checked from the header, before any
/// pixel is decoded), or if they cannot be allocated.
bool read_image(const std::string& filename, OIIO::ImageBuf& dst, std::string& error,
    OIIO::ImageSpec* native = nullptr, int copies = 1);

/// The header of `filename` (its first subimage's spec, the file's pixel type) with the
/// checks read_image() makes before decoding: a regular file, an image OIIO opens, a TIFF
/// whose data fits the file, `copies` float copies of its pixels within the memory limit.
/// Decodes no pixel. False with read_image()'s messages otherwise.
bool read_image_spec(
    const std::string& filename, OIIO::ImageSpec& spec, std::string& error, int copies = 1);

/// False (with "FILE: no such file", "FILE: is a directory, not WHAT" or "FILE: is not a
/// regular file (a FIFO, device or socket), not WHAT") unless `filename` is a regular file
/// (after links). Checked before any library opens a file: reading a FIFO or /dev/zero
/// would block or never end.
bool check_regular_file(const std::string& filename, const std::string& what, std::string& error);

/// A new, empty regular file in the same directory as `filename`, with the same extension
/// (so OIIO picks the same format): write there, then commit_file() or discard_temporary().
/// Created with O_CREAT | O_EXCL | O_NOFOLLOW under an unpredictable name
/// ".STEM.texsyn-tmpPID-HOST-N-RANDOM.EXT" (within NAME_MAX), so that a link planted in a
/// shared folder is never followed, and registered until committed or discarded, so that
/// remove_live_temporaries() finds it. If the folder refuses new files the path is returned
/// uncreated (the writer then fails with its reason). The first call for a folder removes
/// the temporaries that dead processes of this host left there (SIGKILL cannot be handled).
std::string temporary_path_for(const std::string& filename);

/// False (with "FILE: exists and is not a regular file (a device, FIFO or socket); texsyn
/// does not replace it", or "(a directory)") if `filename` exists, not following a link,
/// and is neither a regular file nor a symbolic link (which an output replaces, never its
/// target). Checked before a run writes anything, and again by commit_file().
bool check_output_destination(const std::string& filename, std::string& error);

/// Renames `temporary` over `filename` (atomic on one file system) if `temporary` is still
/// the regular file of this user that temporary_path_for() made (not a link, one name) and
/// check_output_destination() passes; otherwise, or if the rename fails, removes
/// `temporary` and fails ("FILE: reason").
bool commit_file(const std::string& temporary, const std::string& filename, std::string& error);

/// Removes a temporary file that will not be committed (if it exists).
void discard_temporary(const std::string& temporary);

/// Removes every temporary file not yet committed or discarded. Async-signal-safe: for
/// signal handlers and exit handlers, just before the process ends.
void remove_live_temporaries() noexcept;

/// Flushes a written file to the disk (fsync) and checks it is not empty and has no
/// holes (a writer that ignores a full disk leaves both). False with a reason otherwise.
bool sync_written_file(const std::string& path, std::string& reason);

/// Whether the image file at `path` reads back with `expected`'s width and height and
/// every pixel decodes (a truncated file does not). False with a reason otherwise.
bool verify_image_file(
    const std::string& path, const OIIO::ImageSpec& expected, std::string& reason);

/// Writes `bytes` to `path` (created or truncated), checking every write, and fsyncs it.
/// False with a reason ("write error (No space left on device)") otherwise.
bool write_bytes(const std::string& path, const std::string& bytes, std::string& reason);

/// Whether `a` and `b` name the same existing file (after resolving links and "..").
bool same_file(const std::string& a, const std::string& b);

/// Writes `image` to `path` (no temporary: for a path that is itself one) and checks the
/// result as write_image_atomic does; on failure removes `path` and fails (false, "PATH:
/// cannot write (reason)"). A *.tx path gets a texture for renderers, made by OIIO's own
/// texture maker (ImageBufAlgo::make_texture): tiled 64x64, MIP-mapped, zip-compressed,
/// with the image's "wrapmodes" (black if it has none) and metadata.
bool write_image_verified(const OIIO::ImageBuf& image, const std::string& path,
    OIIO::TypeDesc format, std::string& error);

/// Writes `image` to `filename` atomically (temporary file + rename): a failed write
/// leaves no file behind and never an incomplete one. Before the rename the file is either
/// encoded in memory and written with checked write() calls and fsync (formats OIIO can
/// write to memory, up to 256 MB of pixels at `format`, within memory_available()), or
/// written by OIIO, synced and read back completely (sync_written_file, verify_image_file).
/// The bytes are the same either way. `format` is the pixel type on disk (TypeUnknown =
/// the buffer's). Fails (false, "FILE: reason").
bool write_image_atomic(const OIIO::ImageBuf& image, const std::string& filename,
    OIIO::TypeDesc format, std::string& error);

/// Writes a multi-part OpenEXR atomically: one part per entry of `specs` (OpenEXR requires
/// them to share one display window; "oiio:subimagename" names a part), the pixels of part
/// i from `part(i, buf)`, which fills `buf` with a float image of that part's data size
/// and channels. Fails (false, "FILE: cannot write (reason)") leaving no file behind.
bool write_multipart_exr(const std::string& filename, const std::vector<OIIO::ImageSpec>& specs,
    const std::function<void(size_t, OIIO::ImageBuf&)>& part, std::string& error);

} // namespace texsyn
#pragma GCC visibility pop
