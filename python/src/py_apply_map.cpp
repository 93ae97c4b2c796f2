// SPDX-License-Identifier: Apache-2.0
#include "py_apply_map.h"

#include <string>
#include <vector>

#include <pybind11/stl.h>

#include <texsyn/io.h>
#include <texsyn/source_map.h>

#include "py_errors.h"
#include "py_images.h"
#include "py_run.h"

namespace py = pybind11;

namespace texsyn::python {

namespace {

py::object apply_map_py(
    py::handle map, py::handle image, const std::string& normal, py::object sample_size)
{
    ApplyMapOptions opt;
    if (normal == "opengl")
        opt.normal = NormalMap::OpenGL;
    else if (normal == "directx")
        opt.normal = NormalMap::DirectX;
    else if (normal != "none")
        raise_error(ErrorKind::Value, "normal=" + normal + " : expected none, opengl or directx");
    ImageArg m = image_arg(map, "map");
    ImageArg i = image_arg(image, "image");
    // An array map is what a copying method returned: its channels are x, y (and t).
    if (m.kind == ImageKind::Array && (m.pixels.nchannels() == 2 || m.pixels.nchannels() == 3)) {
        const std::vector<std::string> xyt { "x", "y", "t" };
        m.pixels.specmod().channelnames.assign(xyt.begin(), xyt.begin() + m.pixels.nchannels());
    }
    const OutputForm form = output_form(i);
    OIIO::ImageBuf dst;
    std::string error;
    bool ok = true;
    {
        ReleaseGil release;
        // Values are copied as they are: files read as their numbers.
        for (ImageArg* a : { &m, &i })
            if (a->kind == ImageKind::Path && ok)
                ok = read_image(a->path, a->pixels, error);
    }
    if (!ok)
        raise_error(ErrorKind::File, "texsyn.apply_map: " + error);
    if (!sample_size.is_none()) {
        std::vector<int> wh;
        try {
            wh = sample_size.cast<std::vector<int>>();
        } catch (const py::cast_error&) { // not a pair of integers: refused below
        }
        if (wh.size() != 2 || wh[0] < 1 || wh[1] < 1)
            raise_error(ErrorKind::Value, "sample_size= : expected (width, height)");
        OIIO::ImageBuf tagged;
        tagged.copy(m.pixels);
        tagged.specmod().attribute(
            "synth:sample_size", std::to_string(wh[0]) + "x" + std::to_string(wh[1]));
        m.pixels = std::move(tagged);
    }
    {
        ReleaseGil release;
        ok = apply_source_map(dst, m.pixels, i.pixels, opt);
    }
    if (!ok)
        raise_error(ErrorKind::Value, "texsyn.apply_map: " + dst.geterror());
    return to_python(std::move(dst), form);
}

} // namespace

void register_apply_map(py::module_& m)
{
    m.def("apply_map", &apply_map_py, py::arg("map"), py::arg("image"), py::kw_only(),
        py::arg("normal") = "none", py::arg("sample_size") = py::none(),
        R"(Re-applies a synthesis to an image aligned with its sample: result(x, y) =
image(map(x, y)), every channel copied exactly, as `texsyn --apply-map` does.

map: the source map a copying method returned (channels x, y and, after isotropic=1, t),
    as an array, an ImageBuf or a file.
image: a map of the same material (height, roughness, normal...): the sample's size, or a
    whole multiple or fraction of it (coordinates are scaled).
normal: "none" (values copied), or "opengl"/"directx": the image is a tangent-space normal
    map whose vectors turn with each copy's turn or mirror.
sample_size: (width, height) of the sample the map was made from, for an array map and an
    image of another size than the sample (ImageBuf and file maps carry it).

Returns the image's kind (array or ImageBuf) and pixel type, values copied unconverted.)");
}

} // namespace texsyn::python
