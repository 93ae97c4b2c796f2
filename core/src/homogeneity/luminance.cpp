// SPDX-License-Identifier: Apache-2.0
#include "homogeneity_pvt.h"

namespace texsyn::homogeneity {

bool has_luminance(const PlanarImage& image)
{
    return image.ncolor() >= 1 && image.width() >= 1 && image.height() >= 1;
}

void luminance_row(const PlanarImage& image, int y, float* out)
{
    // Rec.709 luma weights for linear Rec.709 primaries (the bundled scene_linear).
    static const float w3[3] = { 0.2126f, 0.7152f, 0.0722f };
    static const float w2[2] = { 0.5f, 0.5f };
    static const float w1[1] = { 1.0f };
    const int n = image.ncolor();
    const int nc = n >= 3 ? 3 : n;
    const float* w = nc == 3 ? w3 : nc == 2 ? w2 : w1;
    for (int x = 0; x < image.width(); ++x) {
        float s = 0.0f;
        for (int c = 0; c < nc; ++c)
            s += w[c] * image.channels[size_t(c)].row(y)[x];
        out[x] = s;
    }
}

} // namespace texsyn::homogeneity
