// SPDX-License-Identifier: Apache-2.0
#include "py_images.h"

#include <algorithm>
#include <memory>
#include <vector>

#include <texsyn/memory.h>

#include "py_errors.h"

namespace py = pybind11;

namespace texsyn::python {

namespace {

bool is_oiio_imagebuf(py::handle obj)
{
    const py::handle type = py::type::handle_of(obj);
    return py::hasattr(type, "__module__")
        && py::str(type.attr("__module__")).cast<std::string>() == "OpenImageIO"
        && py::str(type.attr("__name__")).cast<std::string>() == "ImageBuf";
}

bool is_path(py::handle obj)
{
    return py::isinstance<py::str>(obj) || py::hasattr(obj, "__fspath__");
}

// The channel names a file of `n` channels would have: Y, YA, RGB, RGBA, then channelN.
void name_channels(OIIO::ImageSpec& spec)
{
    const int n = spec.nchannels;
    spec.channelnames.clear();
    if (n <= 2) {
        spec.channelnames = { "Y", "A" };
        spec.channelnames.resize(size_t(n));
    } else {
        for (int c = 0; c < n; ++c)
            spec.channelnames.push_back(
                c < 4 ? std::string(1, "RGBA"[c]) : "channel" + std::to_string(c));
    }
    spec.alpha_channel = n == 2 ? 1 : n >= 4 ? 3 : -1;
}

// Refuses (ValueError, as the methods' own estimates) a copy of `bytes` of the caller's
// pixels that the memory limit does not allow: a zero-stride view (np.broadcast_to) of
// 40000 x 40000 pixels takes no memory until it is copied.
void check_copy(double bytes, const std::string& what)
{
    std::string error;
    if (!check_memory(size_t(std::min(bytes, 1e18)), what + ": a copy of its pixels", error))
        raise_error(ErrorKind::Value, error);
}

ImageArg array_arg(py::handle obj, const std::string& what)
{
    py::array given = py::reinterpret_borrow<py::array>(obj);
    const double elements = double(given.size());
    // An array in the other byte order ('>f4', '>u2' here) is read in this one: one copy.
    if (!given.dtype().attr("isnative").cast<bool>()) {
        check_copy(elements * double(given.itemsize()), what);
        given = given.attr("astype")(given.dtype().attr("newbyteorder")("=")).cast<py::array>();
    }
    const py::dtype dt = given.dtype();
    const char kind = dt.kind();
    OIIO::TypeDesc type;
    py::array a;
    if (kind == 'u' && dt.itemsize() == 1)
        type = OIIO::TypeUInt8;
    else if (kind == 'u' && dt.itemsize() == 2)
        type = OIIO::TypeUInt16;
    else if (kind == 'f' && dt.itemsize() == 2)
        type = OIIO::TypeHalf;
    else if (kind == 'f')
        type = OIIO::TypeFloat;
    else
        raise_error(ErrorKind::Value,
            what + ": numpy arrays of uint8, uint16 or floating point are taken, got "
                + py::str(py::handle(dt)).cast<std::string>());
    const bool float64 = kind == 'f' && dt.itemsize() > 4; // the library works in float32
    if (float64 || !given.attr("flags").attr("c_contiguous").cast<bool>())
        check_copy(elements * (float64 ? 4.0 : double(dt.itemsize())), what);
    if (float64)
        a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(given);
    else
        a = py::array::ensure(given, py::array::c_style);
    if (!a)
        throw py::error_already_set();
    if (a.ndim() != 2 && a.ndim() != 3)
        raise_error(ErrorKind::Value,
            what + ": expected an array of H x W or H x W x C, got " + std::to_string(a.ndim())
                + " dimensions");
    const py::ssize_t h = a.shape(0), w = a.shape(1), c = a.ndim() == 3 ? a.shape(2) : 1;
    if (h < 1 || w < 1 || c < 1 || h > (1 << 30) || w > (1 << 30) || c > 1024)
        raise_error(ErrorKind::Value,
            what + ": an array of " + std::to_string(h) + " x " + std::to_string(w) + " x "
                + std::to_string(c) + " is not an image");
    OIIO::ImageSpec spec(int(w), int(h), int(c), type);
    name_channels(spec);
    // Integer arrays hold encoded values as 8- and 16-bit files do, colour un-associated
    // from alpha (PNG's convention); float arrays associated (OpenEXR's).
    if (type == OIIO::TypeUInt8 || type == OIIO::TypeUInt16)
        spec.attribute("oiio:UnassociatedAlpha", 1);
    ImageArg arg;
    arg.kind = ImageKind::Array;
    arg.type = type;
    arg.pixels = OIIO::ImageBuf(spec, const_cast<void*>(a.data()));
    arg.keep = a;
    arg.flat = a.ndim() == 2;
    return arg;
}

ImageArg imagebuf_arg(py::handle obj, const std::string& what)
{
    const OIIO::ImageBuf& buf = obj.cast<const OIIO::ImageBuf&>();
    ImageArg arg;
    arg.kind = ImageKind::ImageBuf;
    arg.path = buf.name(); // its file, if it was read from one (synth:sample names it)
    if (!buf.initialized() || buf.spec().deep || buf.spec().image_pixels() == 0)
        raise_error(buf.has_error() && !arg.path.empty() ? ErrorKind::File : ErrorKind::Value,
            what + ": the ImageBuf holds no image"
                + (buf.has_error() ? " (" + buf.geterror(false) + ")" : std::string()));
    arg.type = buf.spec().format;
    const OIIO::ImageSpec& spec = buf.spec();
    const bool contiguous = buf.localpixels() && spec.x == 0 && spec.y == 0 && spec.z == 0
        && buf.pixel_stride() == OIIO::stride_t(spec.pixel_bytes());
    if (contiguous) { // shared with the caller's ImageBuf for the call
        arg.pixels = OIIO::ImageBuf(spec, const_cast<void*>(buf.localpixels()));
        arg.keep = py::reinterpret_borrow<py::object>(obj);
        return arg;
    }
    // Cached, windowed or strided pixels: one copy, starting at 0, 0.
    OIIO::ImageSpec local = spec;
    local.x = local.y = local.z = 0;
    check_copy(double(spec.image_bytes()), what);
    arg.pixels.reset(local);
    if (!buf.get_pixels(buf.roi(), spec.format, arg.pixels.localpixels()))
        raise_error(ErrorKind::File, what + ": " + buf.geterror());
    return arg;
}

} // namespace

bool is_image_arg(py::handle obj)
{
    return is_path(obj) || py::isinstance<py::array>(obj) || is_oiio_imagebuf(obj);
}

ImageArg image_arg(py::handle obj, const std::string& what)
{
    if (py::isinstance<py::array>(obj))
        return array_arg(obj, what);
    if (is_oiio_imagebuf(obj))
        return imagebuf_arg(obj, what);
    if (is_path(obj)) {
        ImageArg arg;
        arg.path = py::str(py::module_::import("os").attr("fspath")(obj)).cast<std::string>();
        return arg;
    }
    throw py::type_error(what + ": expected a numpy array, an OpenImageIO.ImageBuf or a file "
        + "name, got " + py::str(py::type::handle_of(obj).attr("__name__")).cast<std::string>());
}

OutputForm output_form(const ImageArg& arg)
{
    if (arg.kind == ImageKind::Path)
        return { ImageKind::Array, OIIO::TypeFloat };
    return { arg.kind, arg.type, arg.flat };
}

py::object to_python(OIIO::ImageBuf&& image, const OutputForm& form)
{
    if (form.kind == ImageKind::ImageBuf) {
        auto out = std::make_unique<OIIO::ImageBuf>();
        if (form.type == OIIO::TypeFloat)
            *out = std::move(image);
        else if (!out->copy(image, form.type))
            raise_error(ErrorKind::Runtime, out->geterror());
        return py::cast(out.release(), py::return_value_policy::take_ownership);
    }
    const OIIO::ImageSpec& spec = image.spec();
    std::vector<py::ssize_t> shape = { spec.height, spec.width, spec.nchannels };
    if (form.flat && spec.nchannels == 1)
        shape.pop_back();
    if (spec.depth > 1)
        shape.insert(shape.begin(), spec.depth);
    if (form.type == OIIO::TypeFloat && image.localpixels()
        && image.pixel_stride() == OIIO::stride_t(spec.pixel_bytes())) {
        // Handed over: the array owns the ImageBuf.
        auto* owner = new OIIO::ImageBuf(std::move(image));
        py::capsule keep(owner, [](void* p) { delete static_cast<OIIO::ImageBuf*>(p); });
        return py::array_t<float>(shape, static_cast<float*>(owner->localpixels()), keep);
    }
    py::dtype dt = form.type == OIIO::TypeUInt8 ? py::dtype::of<uint8_t>()
        : form.type == OIIO::TypeUInt16         ? py::dtype::of<uint16_t>()
        : form.type == OIIO::TypeHalf           ? py::dtype("float16")
                                                : py::dtype::of<float>();
    py::array out(dt, shape);
    const OIIO::TypeDesc type = form.type == OIIO::TypeUInt8 || form.type == OIIO::TypeUInt16
            || form.type == OIIO::TypeHalf
        ? form.type
        : OIIO::TypeFloat;
    if (!image.get_pixels(image.roi(), type, out.mutable_data()))
        raise_error(ErrorKind::Runtime, image.geterror());
    return std::move(out);
}

} // namespace texsyn::python
