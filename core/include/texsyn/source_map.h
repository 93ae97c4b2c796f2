// SPDX-License-Identifier: Apache-2.0
// Source maps: where each pixel of a synthesis that copies sample pixels (neighborhood.h,
// choosy.h, patch.h) came from, and re-applying one to another map of the same material.
//
// A source map is a float image of the synthesis's size with the channels "x", "y" — per
// pixel, the integer sample coordinate it was copied from — and, from a synthesis that
// turns or mirrors the sample (isotropic=1), "t": the transform the pixel was copied under,
// 0..7 (swap x and y if t & 4, then mirror x if t & 1 and y if t & 2: the offset (dx, dy)
// in the result is the offset M_t (dx, dy) in the sample). "synth:sample_size" = "WxH" is the
// sample's size, and it carries the synthesis's synth:* tags.
#pragma once

#include <OpenImageIO/imagebuf.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// How a normal map's vectors are stored: the first three channels hold a tangent-space
/// normal encoded as 0.5 + 0.5 n (8-bit and float normal maps alike); the conventions differ
/// in which way n.y points.
enum class NormalMap {
    None,    ///< not a normal map: values are copied as they are
    OpenGL,  ///< n.y points up the image (Blender, Maya, MaterialX, glTF)
    DirectX, ///< n.y points down the image (Unreal, 3ds Max)
};

/// Options of apply_source_map().
struct ApplyMapOptions {
    /// A normal map is rotated and mirrored with the pixels it is copied under (the map's
    /// "t"), so that its vectors keep pointing the way the copied surface faces.
    NormalMap normal = NormalMap::None;
};

/// Re-applies a synthesis to an image aligned with its sample (height, normal, roughness…
/// maps of the same material): dst(x, y) = image(map(x, y)) for every channel, values
/// copied exactly (normal maps: turned with the copy, see ApplyMapOptions). A fill's map
/// (fill.h: a last channel "m", the mask) blends: dst = (1 - m) image(x, y) + m
/// image(map(x, y)), a blended normal made unit again.
///
/// The image may be the sample's size, or a whole multiple k or fraction 1/k of it in both
/// directions (a 2K height map for a 1K sample): coordinates are scaled, and the result is
/// k times (or 1/k of, rounded up) the map's size; at k times, each pixel's k x k block is
/// copied whole, turned like the pixel. `map` is a source map as the copying methods write
/// it; `image` must have a size so related to the "synth:sample_size" (or, without it,
/// contain every coordinate). Fails (false, message in dst) if the map does not have the
/// channels x, y (and t), holds non-integer, non-finite or out-of-range coordinates or
/// transforms, if the sizes do not relate, or if a normal map has fewer than 3 channels.
bool apply_source_map(OIIO::ImageBuf& dst, const OIIO::ImageBuf& map, const OIIO::ImageBuf& image,
    const ApplyMapOptions& opt = {});
OIIO::ImageBuf apply_source_map(
    const OIIO::ImageBuf& map, const OIIO::ImageBuf& image, const ApplyMapOptions& opt = {});

} // namespace texsyn
#pragma GCC visibility pop
