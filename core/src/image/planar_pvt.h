// SPDX-License-Identifier: Apache-2.0
// Shared by the sources that move pixels between ImageBufs and planes.
#pragma once

#include <OpenImageIO/imagebuf.h>

namespace texsyn {

/// `buf`'s pixels, if they are float, in memory, and packed (channel-interleaved, rows
/// one after another, as an ImageBuf allocated from a spec keeps them); else null.
const float* contiguous_float_pixels(const OIIO::ImageBuf& buf);

} // namespace texsyn
