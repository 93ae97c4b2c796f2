// SPDX-License-Identifier: Apache-2.0
// Planar float volumes: the solid textures of Heeger & Bergen 1995 §4, and their files
// (DESIGN.md "Output files": OpenVDB, and a multi-part EXR of z slices for tools without
// VDB support).
//
// Rules for this header:
//  - A Volume is one channel of width*height*depth 32-bit floats, x fastest, then y, then
//    z: voxel (x, y, z) is at data()[(z * height + y) * width + x]. It is stored as one
//    width x (height*depth) Plane (the z slices stacked top to bottom), so pointwise plane
//    operations (histogram matching, colour transforms) apply to a whole volume as they
//    are. Sizes are limited to height * depth < 2^31.
//  - Slices are named by the axis they are perpendicular to: a Z slice (xy) at z is
//    width x height with x along its rows and y down; a Y slice (xz) at y is width x depth
//    with x along its rows and z down; an X slice (yz) at x is height x depth with y along
//    its rows and z down.
//  - Volumes hold scene-linear float colour, un-associated from alpha.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/paramlist.h>
#include <OpenImageIO/typedesc.h>

#include <texsyn/image.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

class ColorConfig; // texsyn/color.h

/// One float channel of a 3-D block. Value semantics; cheap to move.
class Volume {
public:
    Volume() = default;
    /// A width x height x depth volume filled with `value`. Sizes must be >= 0 with
    /// height * depth < 2^31.
    Volume(int width, int height, int depth, float value = 0.0f);
    /// Adopts `voxels`, a width x (height*depth) plane laid out as described above.
    Volume(Plane voxels, int height, int depth);

    int width() const { return m_voxels.width(); }
    int height() const { return m_height; }
    int depth() const { return m_depth; }
    size_t size() const { return m_voxels.size(); }
    float* data() { return m_voxels.data(); }
    const float* data() const { return m_voxels.data(); }
    /// The first voxel of z slice `z` (width * height contiguous floats).
    float* slab(int z) { return m_voxels.row(z * m_height); }
    const float* slab(int z) const { return m_voxels.row(z * m_height); }

    float& operator()(int x, int y, int z) { return m_voxels(x, z * m_height + y); }
    float operator()(int x, int y, int z) const { return m_voxels(x, z * m_height + y); }

    /// The voxels as a width x (height*depth) plane (see the header comment). The plane may
    /// be swapped with another of the same size, never resized.
    Plane& voxels() { return m_voxels; }
    const Plane& voxels() const { return m_voxels; }

private:
    Plane m_voxels;
    int m_height = 0;
    int m_depth = 0;
};

/// The axis a slice is perpendicular to (see the header comment).
enum class SliceAxis { X, Y, Z };

/// "x", "y" or "z".
const char* slice_axis_name(SliceAxis axis);

/// Number of slices of `v` perpendicular to `axis` (its size along that axis).
int slice_count(const Volume& v, SliceAxis axis);

/// Copies slice `index` (0 <= index < slice_count) perpendicular to `axis` into `out`,
/// which is resized to the slice's size (header comment).
void extract_slice(const Volume& v, SliceAxis axis, int index, Plane& out);

/// Adds `slice` (shaped as extract_slice makes it) into the voxels of slice `index` of `v`.
/// Different slices of one axis touch disjoint voxels, so they may be added concurrently.
void add_slice(const Plane& slice, SliceAxis axis, int index, Volume& v);

/// A multi-channel volume, laid out like PlanarImage: colour channels first, then alpha
/// (if any), then extra channels.
struct PlanarVolume {
    std::vector<Volume> channels;
    std::vector<std::string> channel_names;
    int alpha_channel = -1;          ///< index of the alpha channel (>= 1), or -1
    OIIO::ParamValueList attributes; ///< metadata written to every file (synth:* …)

    int width() const { return channels.empty() ? 0 : channels[0].width(); }
    int height() const { return channels.empty() ? 0 : channels[0].height(); }
    int depth() const { return channels.empty() ? 0 : channels[0].depth(); }
    int nchannels() const { return int(channels.size()); }
    /// Number of colour channels: those before alpha, or all of them without alpha.
    int ncolor() const { return alpha_channel >= 0 ? alpha_channel : nchannels(); }
};

/// Swaps the voxels of every channel of `v` with the planes of `img` (resized to as many
/// channels): each volume's width x (height*depth) plane goes to `img` and back with a
/// second call, so pointwise image operations (colour conversion, decorrelation) apply to
/// volumes without copying. Between the two calls `v`'s channels hold no voxels.
void swap_voxel_planes(PlanarVolume& v, PlanarImage& img);

/// `v` as a 3-D float ImageBuf: width x height x depth voxels (spec.depth), origin
/// (0,0,0), the volume's channels and names, colour un-associated from alpha (flagged
/// "oiio:UnassociatedAlpha", as the volume keeps it) and `v.attributes` as metadata.
void imagebuf_from_volume(const PlanarVolume& v, OIIO::ImageBuf& dst);

/// The inverse: a float volume from a 2-D or 3-D ImageBuf (any pixel type), colour
/// un-associated from alpha (divided by it unless flagged "oiio:UnassociatedAlpha"),
/// synth:* metadata and wrapmodes into `v.attributes`. Fails (false, `error`) if `src` has an
/// error, is empty, too large (height * depth >= 2^31) or has NaN/Inf voxels.
bool volume_from_imagebuf(const OIIO::ImageBuf& src, PlanarVolume& dst, std::string& error);

/// A 3-D ImageBuf (as imagebuf_from_volume() makes one) with its colour converted from
/// space `from` to `to` by `colors` (ColorConfig::convert: alpha and other channels
/// untouched), kept un-associated as volumes keep it. False with a message, `dst` unchanged.
bool convert_volume_colours(const ColorConfig& colors, const OIIO::ImageBuf& volume,
    const std::string& from, const std::string& to, OIIO::ImageBuf& dst, std::string& error);

/// Z slice `z` of a 3-D ImageBuf as a 2-D float image of the same width, height,
/// channels and metadata, colour associated with alpha (the slice EXR's parts; the OIIO
/// plugin's subimages).
OIIO::ImageBuf volume_slice(const OIIO::ImageBuf& volume, int z);

/// Writes `v` as an OpenVDB file (atomically: temporary file, then rename) that stock
/// tools read: one dense Vec3f grid "Cd" from the first three colour channels (a grey
/// volume fills all three from its one channel; a missing third is 0), a float grid
/// "density" (class fog volume) from alpha if there is one, and one float grid per further
/// channel, named after it. Every voxel of the w x h x d block is active, at index
/// coordinates (0,0,0)..(w-1,h-1,d-1) with a voxel size of 1. `v.attributes` become file
/// metadata (strings, ints and floats). Fails (false, "FILE: reason") if the file cannot
/// be written.
bool write_volume_vdb(const std::string& filename, const PlanarVolume& v, std::string& error);

/// Writes `v` as a multi-part OpenEXR (atomically) with one part per z slice, named
/// "z0000", "z0001", … (four digits, more if the depth needs them), each width x height
/// with the volume's channels in `format` (TypeHalf or TypeFloat), colour associated with
/// alpha as OpenEXR stores it. All parts share one display window and carry
/// `v.attributes`, so stock `oiiotool out.exr --subimage z0005 -o slice.png` extracts a
/// slice. Fails (false, "FILE: reason") if the file cannot be written.
bool write_volume_exr(
    const std::string& filename, const PlanarVolume& v, OIIO::TypeDesc format, std::string& error);

/// The part name of z slice `z` in a volume `depth` slices deep, e.g. "z0005".
std::string volume_exr_part_name(int z, int depth);

} // namespace texsyn
#pragma GCC visibility pop
