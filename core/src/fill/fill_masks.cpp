// SPDX-License-Identifier: Apache-2.0
// The fill's masks: the mask's regions, a region's crop and its masked pyramid, box
// erosion and dilation, the push-pull start, and the level and margin choices.
#include "fill_pvt.h"

#include <algorithm>
#include <cmath>

#include <OpenImageIO/imagebufalgo.h>

#include <texsyn/feature_scale.h>
#include <texsyn/pyramid.h>

#include "methods/method_helpers_pvt.h"
#include "patch/patch_pvt.h"

namespace texsyn::detail {

namespace {

// Known (normalised weight) a reduced pixel must reach to count as known: all of its kernel.
constexpr float kAllOfKernel = 1.0f - 1e-5f;

Plane plane_of(const std::vector<uint8_t>& mask, int width, int height)
{
    Plane p(width, height);
    std::transform(mask.begin(), mask.end(), p.data(), [](uint8_t v) { return float(v); });
    return p;
}

// 1D running box test along rows (dx) or columns: out = op over [i - half, i + half].
template <class Op>
std::vector<uint8_t> box_pass(const std::vector<uint8_t>& in, int width, int height, int half,
    bool along_rows, uint8_t outside, Op op)
{
    std::vector<uint8_t> out(in.size());
    const int n = along_rows ? width : height, lines = along_rows ? height : width;
    for (int line = 0; line < lines; ++line) {
        auto at = [&](int i) {
            if (i < 0 || i >= n)
                return outside;
            return along_rows ? in[size_t(line) * size_t(width) + size_t(i)]
                              : in[size_t(i) * size_t(width) + size_t(line)];
        };
        // The count of ones in the window, slid along the line.
        int ones = 0;
        for (int i = -half; i <= half; ++i)
            ones += at(i);
        for (int i = 0; i < n; ++i) {
            const size_t q = along_rows ? size_t(line) * size_t(width) + size_t(i)
                                        : size_t(i) * size_t(width) + size_t(line);
            out[q] = op(ones, 2 * half + 1);
            ones += at(i + half + 1) - at(i - half);
        }
    }
    return out;
}

} // namespace

std::vector<uint8_t> above_zero(const Plane& mask)
{
    std::vector<uint8_t> out(mask.size());
    std::transform(
        mask.data(), mask.data() + mask.size(), out.begin(), [](float v) { return v > 0.0f; });
    return out;
}

std::vector<uint8_t> erode_box(const std::vector<uint8_t>& mask, int width, int height, int half)
{
    auto all = [](int ones, int n) { return uint8_t(ones == n); };
    return box_pass(
        box_pass(mask, width, height, half, true, 0, all), width, height, half, false, 0, all);
}

bool has_source_patch(const CropLevel& crop, int patch)
{
    const std::vector<uint8_t> centres
        = erode_box(crop.source, crop.width(), crop.height(), patch / 2);
    return std::find(centres.begin(), centres.end(), uint8_t(1)) != centres.end();
}

std::vector<uint8_t> dilate_box(const std::vector<uint8_t>& mask, int width, int height, int half)
{
    auto any = [](int ones, int) { return uint8_t(ones > 0); };
    return box_pass(
        box_pass(mask, width, height, half, true, 0, any), width, height, half, false, 0, any);
}

std::vector<PixelBox> hole_regions(const std::vector<uint8_t>& hole, int width, int height, int gap)
{
    std::vector<PixelBox> boxes;
    std::vector<uint8_t> seen(hole.size(), 0);
    std::vector<uint32_t> stack;
    for (size_t start = 0; start < hole.size(); ++start) {
        if (!hole[start] || seen[start])
            continue;
        PixelBox box { int(start % size_t(width)), int(start / size_t(width)), 0, 0 };
        box.x1 = box.x0 + 1;
        box.y1 = box.y0 + 1;
        seen[start] = 1;
        stack.assign(1, uint32_t(start));
        while (!stack.empty()) {
            const uint32_t q = stack.back();
            stack.pop_back();
            const int x = int(q % uint32_t(width)), y = int(q / uint32_t(width));
            box = { std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x + 1),
                std::max(box.y1, y + 1) };
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= width || ny >= height)
                        continue;
                    const size_t r = size_t(ny) * size_t(width) + size_t(nx);
                    if (hole[r] && !seen[r]) {
                        seen[r] = 1;
                        stack.push_back(uint32_t(r));
                    }
                }
        }
        boxes.push_back(box);
    }
    // Merge boxes whose grown copies overlap, until none do (the first of a pair keeps its
    // place in the list).
    for (bool merged = true; merged;) {
        merged = false;
        for (size_t i = 0; i < boxes.size() && !merged; ++i)
            for (size_t j = i + 1; j < boxes.size() && !merged; ++j)
                if (boxes[i].grown(gap).overlaps(boxes[j])) {
                    boxes[i] = { std::min(boxes[i].x0, boxes[j].x0),
                        std::min(boxes[i].y0, boxes[j].y0), std::max(boxes[i].x1, boxes[j].x1),
                        std::max(boxes[i].y1, boxes[j].y1) };
                    boxes.erase(boxes.begin() + std::ptrdiff_t(j));
                    merged = true;
                }
    }
    return boxes;
}

CropLevel crop_level(const std::vector<Plane>& image, const std::vector<uint8_t>& hole,
    const std::vector<uint8_t>* exclude, const PixelBox& box)
{
    const int iw = image[0].width(), w = box.width(), h = box.height();
    CropLevel level;
    level.planes.assign(image.size(), Plane(w, h));
    level.known.assign(size_t(w) * size_t(h), 0);
    level.source.assign(size_t(w) * size_t(h), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t s = size_t(box.y0 + y) * size_t(iw) + size_t(box.x0 + x);
            const size_t q = size_t(y) * size_t(w) + size_t(x);
            for (size_t c = 0; c < image.size(); ++c)
                level.planes[c](x, y) = image[c].data()[s];
            level.known[q] = !hole[s];
            level.source[q] = !hole[s] && !(exclude && (*exclude)[s]);
        }
    return level;
}

CropLevel reduce_crop(const CropLevel& fine, int nthreads)
{
    const int w = fine.width(), h = fine.height();
    const Plane known = plane_of(fine.known, w, h);
    const Plane weight = reduce_plane(known, Boundary::Reflect, nthreads);
    const Plane source = reduce_plane(plane_of(fine.source, w, h), Boundary::Reflect, nthreads);
    CropLevel coarse;
    const size_t n = weight.size();
    for (const Plane& p : fine.planes) {
        Plane masked = p;
        for (size_t i = 0; i < masked.size(); ++i)
            masked.data()[i] *= known.data()[i];
        Plane sum = reduce_plane(masked, Boundary::Reflect, nthreads);
        for (size_t i = 0; i < n; ++i)
            sum.data()[i] = weight.data()[i] > 0.0f ? sum.data()[i] / weight.data()[i] : 0.0f;
        coarse.planes.push_back(std::move(sum));
    }
    coarse.known.resize(n);
    coarse.source.resize(n);
    for (size_t i = 0; i < n; ++i) {
        coarse.known[i] = weight.data()[i] >= kAllOfKernel;
        coarse.source[i] = source.data()[i] >= kAllOfKernel;
    }
    return coarse;
}

void pushpull_fill(CropLevel& level, int nthreads)
{
    const int w = level.width(), h = level.height(), nc = int(level.planes.size());
    OIIO::ImageSpec spec(w, h, nc + 1, OIIO::TypeDesc::FLOAT);
    spec.alpha_channel = nc;
    OIIO::ImageBuf premultiplied(spec);
    std::vector<float> pixel(size_t(nc) + 1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float k = level.known[size_t(y) * size_t(w) + size_t(x)];
            for (int c = 0; c < nc; ++c)
                pixel[size_t(c)] = k * level.planes[size_t(c)](x, y);
            pixel[size_t(nc)] = k;
            premultiplied.setpixel(x, y, pixel.data());
        }
    OIIO::ImageBuf filled;
    if (!OIIO::ImageBufAlgo::fillholes_pushpull(filled, premultiplied, {}, nthreads))
        throw std::runtime_error("push-pull: " + filled.geterror());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (!level.known[size_t(y) * size_t(w) + size_t(x)]) {
                filled.getpixel(x, y, pixel.data());
                for (int c = 0; c < nc; ++c)
                    level.planes[size_t(c)](x, y) = pixel[size_t(c)];
            }
}

void add_guidance(std::vector<Plane>& planes, int ncolour, const std::vector<uint8_t>* known,
    float weight, int nthreads, const StopFlag* stop)
{
    CropLevel filled;
    filled.planes.assign(planes.begin(), planes.begin() + ncolour);
    if (known) {
        filled.known = *known;
        pushpull_fill(filled, nthreads);
        throw_if_stopped(stop);
    }
    PlanarImage measured;
    measured.channels.assign(filled.planes.begin(), filled.planes.begin() + ncolour);
    const int feature = int(std::lround(estimate_feature_scale(measured, nthreads).size));
    throw_if_stopped(stop);
    Plane g = guidance_channel(filled.planes, feature, nthreads, stop);
    for (size_t i = 0; i < g.size(); ++i)
        g.data()[i] *= weight;
    planes.push_back(std::move(g));
}

std::vector<int> chessboard_distance(
    const std::vector<uint8_t>& inside, int width, const PixelBox& box, bool edge_is_outside)
{
    // Two-pass chessboard distance transform over the box (Rosenfeld & Pfaltz).
    constexpr int far = 1 << 29;
    const int w = box.width(), h = box.height();
    std::vector<int> d(size_t(w) * size_t(h));
    auto at = [&](int x, int y) -> int {
        if (x < 0 || y < 0 || x >= w || y >= h)
            return edge_is_outside ? 0 : far;
        return d[size_t(y) * size_t(w) + size_t(x)];
    };
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int& v = d[size_t(y) * size_t(w) + size_t(x)];
            v = inside[size_t(box.y0 + y) * size_t(width) + size_t(box.x0 + x)] ? std::min(far,
                    1
                        + std::min(
                            { at(x - 1, y), at(x - 1, y - 1), at(x, y - 1), at(x + 1, y - 1) }))
                                                                                : 0;
        }
    for (int y = h - 1; y >= 0; --y)
        for (int x = w - 1; x >= 0; --x) {
            int& v = d[size_t(y) * size_t(w) + size_t(x)];
            if (v > 0)
                v = std::min({ v, 1 + at(x + 1, y), 1 + at(x + 1, y + 1), 1 + at(x, y + 1),
                    1 + at(x - 1, y + 1) });
        }
    return d;
}

int hole_thickness(const std::vector<uint8_t>& hole, int width, const PixelBox& box)
{
    const std::vector<int> d = chessboard_distance(hole, width, box, true);
    const int largest = d.empty() ? 0 : *std::max_element(d.begin(), d.end());
    return std::max(1, 2 * largest - 1);
}

int fill_levels(const FillOptions& opt, int thickness)
{
    if (opt.levels > 0)
        return opt.levels;
    // At least three: with fewer, thin holes and bands come out smudged.
    const double across = double(thickness) / (3.0 * double(opt.patch.front()));
    return std::clamp(1 + int(std::ceil(std::log2(std::max(across, 1.0)))), 3, 8);
}

int fill_margin(const FillOptions& opt, int levels, int thickness)
{
    if (opt.context > 0)
        return opt.context;
    return std::max((2 * opt.patch.front()) << (levels - 1), (thickness + 1) / 2);
}

} // namespace texsyn::detail
