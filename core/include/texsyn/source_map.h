// SPDX-License-Identifier: Apache-2.0
// Source maps: where each pixel of a synthesis that copies sample pixels (neighborhood.h,
// choosy.h) came from, and re-applying one to another map of the same material.
//
// A source map is a 2-channel float image ("x", "y") of the synthesis's size holding, per
// pixel, the integer sample coordinate it was copied from, with "synth:sample_size" =
// "WxH" (the sample's size) and the synthesis's synth:* tags.
#pragma once

#include <OpenImageIO/imagebuf.h>

namespace texsyn {

/// Re-applies a synthesis to an image aligned with its sample (height, normal, roughness…
/// maps of the same material): dst(x, y) = image(map(x, y)) for every channel, values
/// copied exactly. `map` is a source map as neighborhood_synthesize writes it; `image`
/// must have the size recorded in its "synth:sample_size" (or, without it, contain every
/// coordinate). Fails (false, message in dst) if the map does not have 2 channels or holds
/// non-integer, non-finite or out-of-range coordinates, or if the sizes disagree.
bool apply_source_map(OIIO::ImageBuf& dst, const OIIO::ImageBuf& map, const OIIO::ImageBuf& image);
OIIO::ImageBuf apply_source_map(const OIIO::ImageBuf& map, const OIIO::ImageBuf& image);

} // namespace texsyn
