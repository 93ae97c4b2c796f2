// SPDX-License-Identifier: Apache-2.0
// Shared by the sources that move pixels between ImageBufs and planes.
#pragma once

#include <OpenImageIO/imagebuf.h>

namespace texsyn {

/// `buf`'s pixels, if they are float, in memory, and packed (channel-interleaved, rows
/// one after another, as an ImageBuf allocated from a spec keeps them); else null.
const float* contiguous_float_pixels(const OIIO::ImageBuf& buf);

/// What imagebuf_from_planes(planes_from_imagebuf(src)) makes, without the planes: a new
/// float ImageBuf with origin (0,0), src's channel names and the same pixel values, for an
/// `src` whose float pixels are in memory (contiguous_float_pixels), all finite, without
/// alpha (alpha needs the division and multiplication the round trip does). False, with
/// `dst` untouched, for any other `src`: the round trip then decides (and reports).
bool copy_without_planes(const OIIO::ImageBuf& src, OIIO::ImageBuf& dst);

} // namespace texsyn
