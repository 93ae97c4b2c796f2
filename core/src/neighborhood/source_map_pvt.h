// SPDX-License-Identifier: Apache-2.0
// Writing source-coordinate maps (neighborhood.h, choosy.h): shared by every method that
// copies sample pixels.
#pragma once

#include <cstdint>
#include <vector>

#include <OpenImageIO/imagebuf.h>

namespace texsyn::detail {

/// `map` becomes a width x height 2-channel float image ("x", "y"): pixel i holds the
/// coordinates of source[i], an index y * source_width + x into the sample, and
/// "synth:sample_size" = "<sample_width>x<sample_height>" (what apply_source_map checks).
void write_source_map(OIIO::ImageBuf& map, const std::vector<uint32_t>& source, int width,
    int height, int source_width, int sample_width, int sample_height);

} // namespace texsyn::detail
