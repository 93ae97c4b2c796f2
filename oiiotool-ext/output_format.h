// SPDX-License-Identifier: Apache-2.0
// Which pixel types an output file can hold, and the default one (docs/cli.md "-d").
#pragma once

#include <string>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/typedesc.h>

namespace texsyn::cli {

/// The pixel type to write `filename` with: `requested` (-d; TypeUnknown = default) if the
/// format holds it; by default the input's type where the format holds it (16-bit PNG in,
/// 16-bit PNG out; float EXR in, float EXR out), else the format's first type: half for
/// OpenEXR, float for Radiance HDR, uint8 for PNG, JPEG, TIFF and formats texsyn does not
/// know. TIFF holds half here, but OIIO's TIFF writer stores it as float: a half input
/// (or -d half) gives a float TIFF file. Throws CliError naming -d and the types the format holds
/// if `requested` does not fit a format texsyn knows.
OIIO::TypeDesc output_pixel_type(
    const std::string& filename, OIIO::TypeDesc requested, OIIO::TypeDesc input_type);

/// The smallest and largest value of any channel of `image` (NaN ignored).
struct ValueRange {
    float low = 0.0f, high = 0.0f;
};
ValueRange value_range(const OIIO::ImageBuf& image, int nthreads);

/// `type` if it holds values in `range`; float where `type` is half and a value is beyond
/// half's range (+-65504: it would be written as infinity) unless -d asked for half, in
/// which case this throws CliError naming the output, its largest value and -d float.
OIIO::TypeDesc type_holding(
    ValueRange range, OIIO::TypeDesc type, OIIO::TypeDesc requested, const std::string& filename);

/// Whether pixels of `type` are written scene-linear by default (floating point) rather
/// than in the input's encoding (integers).
bool is_linear_type(OIIO::TypeDesc type);

/// Whether `filename`'s format stores colour associated with alpha (OpenEXR and .tx
/// textures do, as renderers expect; PNG, TIFF and the others are written un-associated).
bool stores_associated_alpha(const std::string& filename);

} // namespace texsyn::cli
