// SPDX-License-Identifier: Apache-2.0
// Shared by the file input/output sources.
#pragma once

#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

namespace texsyn {

/// `s` with line breaks turned into spaces and trailing spaces removed: the tool prints
/// one line per error, and library messages can span several.
std::string one_line(std::string s);

/// False, with the reason, if the strips or tiles the first directory of the TIFF file
/// `path` points at do not all lie inside the file (a file cut short), or, for a
/// JPEG-compressed TIFF, do not all decode. True for anything that is not a TIFF this
/// check can read: the image reader then decides.
bool tiff_data_fits_in_file(const std::string& path, std::string& reason);

/// `image` encoded in memory as the file `path` names (its extension the format), into
/// `bytes`, if the format's writer can (an I/O proxy) and the pixels at the file's type
/// take at most 256 MB, and the bytes then open as an image of the image's size and
/// channels. False otherwise, with `reason` set only if the encoder refused the image
/// (the file writer would too).
bool encode_in_memory(const OIIO::ImageBuf& image, const std::string& path, OIIO::TypeDesc format,
    std::vector<unsigned char>& bytes, std::string& reason);

/// The write and the checks of write_image_atomic (texsyn/io.h), to `path` itself. False
/// with a reason otherwise; `path` may then exist, incomplete.
bool write_image_checked(const OIIO::ImageBuf& image, const std::string& path,
    OIIO::TypeDesc format, std::string& reason);

} // namespace texsyn
