// SPDX-License-Identifier: Apache-2.0
// The fill's parts: the mask's regions, the working crop of one region with its masks, the
// masked pyramid, and the coarse-to-fine EM on one region.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <texsyn/fill.h>
#include <texsyn/image.h>

namespace texsyn::detail {

/// A rectangle of pixels, [x0, x1) x [y0, y1).
struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    /// The box grown by `d` pixels on every side.
    PixelBox grown(int d) const { return { x0 - d, y0 - d, x1 + d, y1 + d }; }
    bool overlaps(const PixelBox& o) const
    {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};

/// The bounding boxes of the 8-connected components of `hole` (width x height, 1 = to fill),
/// merged while two of them, grown by `gap`, overlap; in row order of their first pixel.
std::vector<PixelBox> hole_regions(
    const std::vector<uint8_t>& hole, int width, int height, int gap);

/// A mask plane's values as 0/1: 1 where above 0.
std::vector<uint8_t> above_zero(const Plane& mask);

/// One level of a region's working crop: its planes, which pixels are known (to keep) and
/// which may lie in a source patch (known, not excluded, inside the image).
struct CropLevel {
    std::vector<Plane> planes;
    std::vector<uint8_t> known;  ///< 1 = keep, 0 = fill
    std::vector<uint8_t> source; ///< 1 = may be part of a source patch
    int width() const { return planes.empty() ? 0 : planes[0].width(); }
    int height() const { return planes.empty() ? 0 : planes[0].height(); }
};

/// The crop `box` (inside the image) of the image: every channel, with the hole and
/// exclusion masks; source pixels are those known and not excluded.
CropLevel crop_level(const std::vector<Plane>& image, const std::vector<uint8_t>& hole,
    const std::vector<uint8_t>* exclude, const PixelBox& box);

/// The next coarser level: values reduced over known pixels only (each a normalised
/// average, so hole colours do not leak into known ones); a pixel is known (source) where
/// every fine pixel under its kernel is.
CropLevel reduce_crop(const CropLevel& fine, int nthreads);

/// 1 where the (2 half + 1)^2 box around the pixel is all 1 in `mask` (0 near the edges).
std::vector<uint8_t> erode_box(const std::vector<uint8_t>& mask, int width, int height, int half);

/// Whether some patch x patch square of the crop lies wholly on source pixels.
bool has_source_patch(const CropLevel& crop, int patch);

/// 1 where the (2 half + 1)^2 box around the pixel has a 1 in `mask`.
std::vector<uint8_t> dilate_box(const std::vector<uint8_t>& mask, int width, int height, int half);

/// `planes` (the first `ncolour` its colours) with the guidance channel appended: the
/// distance to the colours' edges (patch_pvt.h's guidance_channel), x `weight`, computed
/// with the hole (`known` == 0, if given) push-pull filled so that its edge is not an edge.
/// Throws "stopped" between its steps once `stop` is set (stop.h).
void add_guidance(std::vector<Plane>& planes, int ncolour, const std::vector<uint8_t>* known,
    float weight, int nthreads, const StopFlag* stop);

/// The pixels of the hole (known == 0) filled by push-pull interpolation from the known
/// ones (OIIO's fillholes_pushpull).
void pushpull_fill(CropLevel& level, int nthreads);

/// Per pixel of `box` (of a `width`-wide mask), its chessboard distance (1, 2, ...) to the
/// nearest pixel not `inside`; 0 outside. Pixels beyond the box count as outside when
/// `edge_is_outside`, else as inside (a box that is inside everywhere then gets 2^29).
std::vector<int> chessboard_distance(
    const std::vector<uint8_t>& inside, int width, const PixelBox& box, bool edge_is_outside);

/// The thickness of the hole inside `box` (of a `width`-wide mask): the side of the largest
/// square of hole pixels, 2 d - 1 for the largest chessboard distance d of a hole pixel to
/// a pixel outside the hole (or the box's edge).
int hole_thickness(const std::vector<uint8_t>& hole, int width, const PixelBox& box);

/// The levels a region whose hole is `thickness` pixels thick is filled with: opt.levels,
/// or the automatic choice (the hole at most three of the largest patches thick at the
/// coarsest level; at least three levels, which texture_fill lowers for a crop too small
/// to hold them).
int fill_levels(const FillOptions& opt, int thickness);

/// The margin around a region's hole box its crop takes: opt.context, or enough for
/// `levels` levels (two largest patches at the coarsest) and half the hole's thickness.
int fill_margin(const FillOptions& opt, int levels, int thickness);

/// What filling one region gives: per pixel of the crop's finest level, the pixel whose
/// value it copies, as an index into the source (the image's crop: y * crop width + x; or
/// the sample: y * sample width + x); meaningful where the crop is not known.
struct RegionFill {
    std::vector<uint32_t> copied;
};

/// Fills one region: `levels` crop levels (finest first, from crop_level and reduce_crop)
/// coarse to fine, from the crop's own source pixels or, if `sample` is not empty, from the
/// sample's pyramid (`sample[l]`, planes). `stream` separates the regions' random draws;
/// `done` and `total` count progress units (pixels searched). False with a message if a
/// level has no source patch.
bool fill_region(std::vector<CropLevel>& levels, const std::vector<std::vector<Plane>>& sample,
    const FillOptions& opt, uint64_t stream, double& done, double total, RegionFill& result,
    std::string& error);

/// One region's copies, as compose_region reads them: its crop (in image pixels), its
/// channel count, and two readers of pixel values (raw, as the image holds them).
struct RegionCopies {
    PixelBox crop;
    int channels = 0;
    /// The value of the kept image at image pixel (x, y), every channel, into `out`.
    std::function<void(int x, int y, float* out)> kept;
    /// The copied content at crop pixel q (y * crop width + x) moved by (dx, dy): the pixel
    /// at q's source plus (dx, dy), clamped to the source, every channel, into `out`.
    std::function<void(size_t q, int dx, int dy, float* out)> copied;
};

/// Writes (through `write(x, y, values)`) every pixel of the region's crop where `mask`
/// (the image's size) is above 0: the copied content, with FillOutline::Match offset by
/// smooth offsets that take away the steps between the kept pixels and the copies across the
/// hole's outline and between neighbouring copies across their seams, keeping each copy's own
/// gradients (gradient-domain compositing: Pérez et al. 2003, Agarwala et al. 2004) and, if
/// `rim` > 1 (a soft image),
/// faded in over `rim` pixels from the kept pixels' smooth (push-pull) continuation;
/// blended with the kept value by the mask: (1 - m) x kept + m x fill.
void compose_region(const RegionCopies& copies, const Plane& mask, FillOutline outline, int rim,
    int nthreads, const std::function<void(int, int, const float*)>& write);

/// Progress units fill_region counts for these crop levels (pixels searched).
double fill_work(const std::vector<CropLevel>& levels, const FillOptions& opt);

} // namespace texsyn::detail
