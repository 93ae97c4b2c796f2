// SPDX-License-Identifier: Apache-2.0
// Planar float images: the representation every algorithm in texsyn works on.
//
// Rules for this header:
//  - A Plane is one channel of 32-bit floats, row-major, width*height values, no padding.
//  - Pixel (x, y) is at data()[y * width + x]; y = 0 is the top row, as in OIIO.
//  - Conversion to and from OIIO::ImageBuf happens only here (float planes inside,
//    pixel formats at the edges).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// How a pixel outside [0,width)x[0,height) is addressed.
///  Circular: the image is a torus (x mod width) — synthesis, seamless tiling.
///  Reflect:  whole-sample mirror without repeating the edge (…2 1 0 1 2…) — analysis of
///            a non-periodic sample (Heeger & Bergen 1995 §3.4).
enum class Boundary { Circular, Reflect };

/// One float channel. Value semantics; cheap to move.
class Plane {
public:
    Plane() = default;
    /// A width x height plane filled with `value`. Sizes must be >= 0.
    Plane(int width, int height, float value = 0.0f);

    int width() const { return m_width; }
    int height() const { return m_height; }
    size_t size() const { return m_data.size(); }
    bool empty() const { return m_data.empty(); }

    float* data() { return m_data.data(); }
    const float* data() const { return m_data.data(); }
    float* row(int y) { return m_data.data() + size_t(y) * size_t(m_width); }
    const float* row(int y) const { return m_data.data() + size_t(y) * size_t(m_width); }

    float& operator()(int x, int y) { return m_data[size_t(y) * size_t(m_width) + size_t(x)]; }
    float operator()(int x, int y) const { return m_data[size_t(y) * size_t(m_width) + size_t(x)]; }

    /// Value at any integer (x, y), addressed with boundary rule `b`.
    float at(int x, int y, Boundary b) const;

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<float> m_data;
};

/// Maps any integer coordinate into [0, n) with boundary rule `b` (n >= 1).
int wrap_coordinate(int i, int n, Boundary b);

/// A multi-channel image as planes of equal size, with OIIO-style channel names.
/// Channel layout: colour channels first, then alpha (if any), then extra channels (Z,
/// masks, …) which are neither colour converted nor associated with alpha.
struct PlanarImage {
    std::vector<Plane> channels;
    std::vector<std::string> channel_names;
    int alpha_channel = -1; ///< index of the alpha channel (>= 1), or -1

    int width() const { return channels.empty() ? 0 : channels[0].width(); }
    int height() const { return channels.empty() ? 0 : channels[0].height(); }
    int nchannels() const { return int(channels.size()); }
    /// Number of colour channels: those before alpha, or all of them without alpha.
    int ncolor() const { return alpha_channel >= 0 ? alpha_channel : nchannels(); }
};

/// Reads the full data window of `src` (any pixel type; lazily read files are read here)
/// into float planes. Channel names and the alpha channel come from src.spec() (an alpha
/// channel at index 0 is treated as an ordinary channel). Colour is returned un-associated
/// from alpha, so that colour statistics do not depend on coverage: associated colour
/// (OIIO's convention) is divided by alpha where alpha > 0, unless the spec says
/// "oiio:UnassociatedAlpha" (read_image() asks for that, so 8-bit PNG colour under
/// zero alpha survives). Fails (false, message in `error`) if src has an error, is
/// empty, is not 2-D (depth > 1), or if any pixel is NaN or infinite (the message names
/// the first offending pixel and channel). Rows are copied on up to `nthreads` threads
/// (0 = every core).
bool planes_from_imagebuf(
    const OIIO::ImageBuf& src, PlanarImage& dst, std::string& error, int nthreads = 0);

/// False, with "pixel (X, Y) channel C is NaN; texsyn needs finite pixel values" (or
/// "infinite") for the first such pixel in scanline order, if any pixel of `src` is not
/// finite.
bool check_finite_pixels(const OIIO::ImageBuf& src, std::string& error);

/// Writes `src` into `dst` as a new float ImageBuf of the same size and channels, with
/// origin (0,0). With `associate` (OIIO's in-memory convention, and what OpenEXR stores)
/// colour channels are multiplied by alpha; otherwise they are left un-associated and the
/// spec says "oiio:UnassociatedAlpha" = 1, which PNG and TIFF writers store losslessly.
/// Never fails for a well-formed PlanarImage (all planes the same size, >= 1 channel).
/// Rows are copied on up to `nthreads` threads (0 = every core).
void imagebuf_from_planes(
    const PlanarImage& src, OIIO::ImageBuf& dst, bool associate = true, int nthreads = 0);

} // namespace texsyn
#pragma GCC visibility pop
