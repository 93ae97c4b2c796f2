// SPDX-License-Identifier: Apache-2.0
// §3.8: the flat grids of equilateral triangles the sample image is mapped onto, and the
// bilinear mapping itself.
#include "face_level_pvt.h"

#include <algorithm>
#include <cmath>

namespace texsyn::detail {

FacePyramid triangular_grid(int width, int height, int levels)
{
    // The coarse grid: rows of congruent triangles 2^(levels-1) pixels high, each row
    // offset by half a side from the one above, as wide as fits in the image.
    const double row = double(1 << (levels - 1));
    const double side = row * 2.0 / std::sqrt(3.0);
    const int rows = int(height / row);
    const int per_row = std::max(2, int(std::floor(width / side - 0.5)) + 1);
    FaceLevel base;
    for (int j = 0; j <= rows; ++j)
        for (int i = 0; i < per_row; ++i)
            base.vertices.emplace_back(float((i + 0.5 * (j % 2)) * side), float(j * row), 0.0f);
    auto at = [per_row](int j, int i) { return uint32_t(j * per_row + i); };
    // Faces counter-clockwise as a viewer of the image sees them (y down).
    auto add = [&base](uint32_t a, uint32_t b, uint32_t c) {
        const Imath::V3f& p = base.vertices[a];
        const Imath::V3f u = base.vertices[b] - p, v = base.vertices[c] - p;
        if (u.x * v.y - u.y * v.x > 0.0f)
            std::swap(b, c);
        base.faces.push_back({ a, b, c });
    };
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i + 1 < per_row; ++i) {
            if (j % 2 == 0) { // the lower row is shifted right
                add(at(j, i), at(j, i + 1), at(j + 1, i));
                add(at(j + 1, i), at(j + 1, i + 1), at(j, i + 1));
            } else { // the upper row is shifted right
                add(at(j, i), at(j, i + 1), at(j + 1, i + 1));
                add(at(j + 1, i), at(j + 1, i + 1), at(j, i));
            }
        }
    return build_face_pyramid(std::move(base), levels, EdgePoints::Midpoint);
}

namespace {

// Catmull-Rom weights of the four taps around a position `t` in [0, 1) past the second.
std::array<float, 4> catmull_rom(float t)
{
    const float t2 = t * t, t3 = t2 * t;
    return { 0.5f * (-t3 + 2.0f * t2 - t), 0.5f * (3.0f * t3 - 5.0f * t2 + 2.0f),
        0.5f * (-3.0f * t3 + 4.0f * t2 + t), 0.5f * (t3 - t2) };
}

} // namespace

std::vector<std::vector<float>> sample_at_centroids(
    const std::vector<Plane>& image, const FaceLevel& level)
{
    const int w = image[0].width(), h = image[0].height();
    std::vector<std::vector<float>> out(image.size(), std::vector<float>(level.size()));
    for (size_t f = 0; f < level.size(); ++f) {
        const double x = double(level.centroid[f].x) - 0.5, y = double(level.centroid[f].y) - 0.5;
        const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
        const std::array<float, 4> wx = catmull_rom(float(x - x0)), wy = catmull_rom(float(y - y0));
        for (size_t c = 0; c < image.size(); ++c) {
            const Plane& p = image[c];
            float sum = 0.0f, lo = 1e30f, hi = -1e30f;
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) {
                    const float v
                        = p(std::clamp(x0 - 1 + i, 0, w - 1), std::clamp(y0 - 1 + j, 0, h - 1));
                    sum += wx[size_t(i)] * wy[size_t(j)] * v;
                    if (i == 1 || i == 2)
                        if (j == 1 || j == 2) {
                            lo = std::min(lo, v);
                            hi = std::max(hi, v);
                        }
                }
            // No overshoot past the four nearest pixels: no values the sample does not have.
            out[c][f] = std::clamp(sum, lo, hi);
        }
    }
    return out;
}

} // namespace texsyn::detail
