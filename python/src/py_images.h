// SPDX-License-Identifier: Apache-2.0
// Images crossing between Python and the library: numpy arrays, OpenImageIO ImageBufs
// (Debian's python3-openimageio: its pybind11 type, shared with this module) and paths.
#pragma once

#include <string>

#include <OpenImageIO/imagebuf.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

namespace texsyn::python {

/// What a Python image argument is; a result is given back as the same kind.
enum class ImageKind {
    Path,     ///< a file name (str or os.PathLike): read like the command line reads it
    Array,    ///< a numpy array, H x W or H x W x C, uint8, uint16 or floating point
    ImageBuf, ///< an OpenImageIO.ImageBuf
};

/// An image argument, read with the GIL held.
struct ImageArg {
    ImageKind kind = ImageKind::Path;
    std::string path;      ///< Path: the file; ImageBuf: the file it was read from, if any
    OIIO::ImageBuf pixels; ///< Array, ImageBuf: its pixels (an array's are wrapped, not copied)
    OIIO::TypeDesc type;   ///< Array, ImageBuf: the pixel type given back
    bool flat = false;     ///< Array: given H x W, without a channel axis
    pybind11::object keep; ///< the Python object whose memory `pixels` may wrap
};

/// Whether `obj` is an image argument: str, os.PathLike, numpy array or ImageBuf.
bool is_image_arg(pybind11::handle obj);

/// Reads image argument `obj`; `what` names it in messages (e.g. "sample", "mask=").
/// Raises ValueError for arrays of another shape or type, TypeError for other objects.
ImageArg image_arg(pybind11::handle obj, const std::string& what);

/// How a result is given back: as `kind` (Path gives an array) of pixel type `type`.
struct OutputForm {
    ImageKind kind = ImageKind::Array;
    OIIO::TypeDesc type = OIIO::TypeFloat;
    bool flat = false; ///< Array: a one-channel result without its channel axis (H x W)
};

/// The form of a result made from `arg`: its kind, pixel type and whether it was an H x W
/// array (a path's: float arrays).
OutputForm output_form(const ImageArg& arg);

/// `image` (float; a volume with spec.depth slices) given back in `form`: an array
/// (H x W x C, or D x H x W x C; without the channel axis for a flat form of one channel;
/// a float image is handed over without a copy) or an ImageBuf with its metadata. Integer forms
/// convert the values (clamped, rounded) as OIIO writes them to integer files. Needs the GIL.
pybind11::object to_python(OIIO::ImageBuf&& image, const OutputForm& form);

} // namespace texsyn::python
