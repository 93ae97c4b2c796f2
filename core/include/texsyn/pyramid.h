// SPDX-License-Identifier: Apache-2.0
// Image pyramids for Heeger & Bergen 1995 §3.1: Laplacian (Burt & Adelson) and steerable
// (Simoncelli & Freeman, Fourier-domain construction).
//
// Rules for this header:
//  - A pyramid is a plan for one image size: build(image) -> bands, collapse(bands) ->
//    image. Plans are immutable after construction. Thread safety: build() and collapse()
//    may be called concurrently on one plan.
//  - collapse(build(x)) == x to float rounding for both kinds and every size (tests check
//    it), so iterating build/modify/collapse does not drift (the paper's warning).
//  - Bands are listed coarse-to-fine-independent in a fixed order with pyrtools names:
//      steerable: "highpass", "s0.o0" .. "s0.o<K-1>", "s1.o0", …, "lowpass"
//      laplacian: "L0" (finest) … "L<S-1>", "lowpass"
//  - Band values keep the image's units at every level, whatever the image size, so the
//    bands of a 256x256 sample and of a 1024x1024 synthesis are directly comparable.
//  - `nthreads` follows OIIO (0 = default pool size); results do not depend on it.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <texsyn/fft.h>
#include <texsyn/image.h>
#include <texsyn/stop.h>
#include <texsyn/volume.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

enum class PyramidKind { Steerable, Laplacian };

/// "steerable" or "laplacian".
const char* pyramid_kind_name(PyramidKind kind);

/// A band decomposition plan for one image size.
class Pyramid {
public:
    virtual ~Pyramid() = default;
    int width() const { return m_width; }
    int height() const { return m_height; }
    /// Band names in the order build() produces them (see the header comment).
    const std::vector<std::string>& band_names() const { return m_names; }
    int nbands() const { return int(m_names.size()); }

    /// Decomposes `image` (width x height) into nbands() planes (resized as needed).
    virtual void build(const Plane& image, std::vector<Plane>& bands, int nthreads = 0) const = 0;
    /// Reconstructs the image from bands shaped as build() makes them.
    virtual void collapse(
        const std::vector<Plane>& bands, Plane& image, int nthreads = 0) const = 0;

    /// Called once per band with (band index, band); may modify the band. Must be safe to
    /// call concurrently for different bands.
    using BandFunction = std::function<void(int, Plane&)>;

    /// build(image, bands); modify(b, bands[b]) for every b; collapse(bands, image) — with
    /// bit-identical results — but with the bands processed in parallel (each band's
    /// transforms and `modify` run on one thread), which scales far better than
    /// parallelising each transform. `bands` receives the modified bands. Once `stop` is
    /// set (stop.h) the bands not yet started are skipped and it returns early, leaving
    /// `image` and `bands` unspecified: the caller checks the flag.
    virtual void transform_bands(Plane& image, std::vector<Plane>& bands,
        const BandFunction& modify, int nthreads = 0, const StopFlag* stop = nullptr) const;

protected:
    Pyramid(int width, int height)
        : m_width(width)
        , m_height(height)
    { }
    int m_width;
    int m_height;
    std::vector<std::string> m_names;
};

/// Largest number of scales for a sample of this size: the most that keeps the coarsest
/// (low-pass) band at least 8 pixels on its short side (0 if the sample is under 16).
int max_pyramid_scales(int sample_width, int sample_height);

/// Laplacian pyramid with `scales` band-pass levels plus the low-pass residual.
/// reduce = blur with the separable (1,4,6,4,1)/16 kernel and keep even samples (size
/// ceil(n/2)); expand = insert zeros, blur, x4. Bands are G_k - expand(G_{k+1}), exact for
/// any size and either boundary. `boundary`: Circular for synthesis, Reflect for analysis
/// (§3.4). Returns nullptr and sets `error` unless 1 <= scales and width, height >=
/// 2^scales, or if the plan cannot be allocated.
std::unique_ptr<Pyramid> make_laplacian_pyramid(
    int width, int height, int scales, Boundary boundary, std::string& error);

/// One level of a Gaussian pyramid: `image` blurred with the separable (1,4,6,4,1)/16
/// kernel and subsampled to ceil(width/2) x ceil(height/2) (the Laplacian pyramid's reduce
/// step). `boundary`: Circular for a tiling image, Reflect for a sample.
Plane reduce_plane(const Plane& image, Boundary boundary, int nthreads = 0);

/// The inverse size change of reduce_plane (Burt & Adelson's expand, Castellanos &
/// Williams' "project"): `coarse` (ceil(width/2) x ceil(height/2)) upsampled to width x
/// height with zeros, blurred with the same kernel and normalised by the kernel weight that
/// fell on the inserted samples.
Plane expand_plane(const Plane& coarse, int width, int height, Boundary boundary, int nthreads = 0);

/// Gaussian pyramid of every channel: result[l][c], level 0 the channels themselves and
/// level l + 1 reduce_plane of level l (`nlevels` >= 1 levels).
std::vector<std::vector<Plane>> gaussian_pyramid(
    const std::vector<Plane>& channels, int nlevels, Boundary boundary, int nthreads = 0);

/// Steerable pyramid, Fourier-domain and self-inverting (a tight frame): high-pass
/// residual, `scales` levels of `orientations` (1..8) oriented bands, low-pass residual.
/// Only the low-pass is subsampled: the bands of scale s are ceil(width/2^s) x
/// ceil(height/2^s), the low-pass ceil(width/2^scales) x ceil(height/2^scales). Any
/// width, height >= 2^scales works (odd and non-power-of-two sizes too): masks are
/// evaluated at each level's true frequencies, so cropping is exact. The transform is
/// circular; analyse a non-periodic sample through periodic_component() first.
/// Returns nullptr and sets `error` if the FFT backend is unavailable or the arguments
/// are out of range.
std::unique_ptr<Pyramid> make_steerable_pyramid(
    int width, int height, int scales, int orientations, FftBackend fft, std::string& error);

/// A band decomposition plan for one volume size (3-D), with the same rules as Pyramid.
class VolumePyramid {
public:
    virtual ~VolumePyramid() = default;
    int width() const { return m_width; }
    int height() const { return m_height; }
    int depth() const { return m_depth; }
    /// Band names in the order build() produces them: "L0" (finest) … "L<S-1>", "lowpass".
    const std::vector<std::string>& band_names() const { return m_names; }
    int nbands() const { return int(m_names.size()); }

    /// Decomposes `volume` (width x height x depth) into nbands() volumes (resized as
    /// needed).
    virtual void build(
        const Volume& volume, std::vector<Volume>& bands, int nthreads = 0) const = 0;
    /// Reconstructs the volume from bands shaped as build() makes them.
    virtual void collapse(
        const std::vector<Volume>& bands, Volume& volume, int nthreads = 0) const = 0;

protected:
    VolumePyramid(int width, int height, int depth)
        : m_width(width)
        , m_height(height)
        , m_depth(depth)
    { }
    int m_width;
    int m_height;
    int m_depth;
    std::vector<std::string> m_names;
};

/// 3-D Laplacian pyramid for solid textures (Heeger & Bergen 1995 §4: "since the Laplacian
/// pyramid is constructed using separable convolutions, it extends trivially to three
/// dimensions"): the 2-D pyramid's reduce and expand applied along x, y and z, circular in
/// all three (so a synthesized block tiles in every direction). Level s is
/// ceil(w/2^s) x ceil(h/2^s) x ceil(d/2^s); band values are in the volume's units like the
/// 2-D bands, so a sample's 2-D band histograms apply to the 3-D bands. Exact
/// reconstruction for any size; parallel over slabs, bit-identical at any nthreads.
/// Returns nullptr and sets `error` unless 1 <= scales and width, height, depth >=
/// 2^scales, or if the plan cannot be allocated.
std::unique_ptr<VolumePyramid> make_laplacian_pyramid_3d(
    int width, int height, int depth, int scales, std::string& error);

/// Moisan's periodic + smooth decomposition: returns the periodic
/// component p of `image` (same size and mean), whose spectrum has none of the cross-shaped
/// energy that the jump between opposite edges puts into a circular transform.
Plane periodic_component(const Plane& image, FftBackend fft, int nthreads = 0);

} // namespace texsyn
#pragma GCC visibility pop
