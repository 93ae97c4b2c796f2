// SPDX-License-Identifier: Apache-2.0
#include "py_objects.h"

#include <filesystem>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <texsyn/methods.h>

#include "py_errors.h"
#include "py_run.h"

namespace py = pybind11;

namespace texsyn::python {

py::dict PyMaterial::maps() const
{
    return maps_of(*material);
}

py::dict PyMaterial::maps_of(const Material& synthesized) const
{
    py::dict out;
    for (size_t i = 0; i < synthesized.maps.size(); ++i) {
        const MaterialMap& map = synthesized.maps[i];
        OIIO::ImageBuf image = map.image;
        if (map.kind == MapKind::Colour)
            out[map.name.c_str()] = colour_to_python(std::move(image), albedo);
        else
            out[map.name.c_str()] = to_python(std::move(image), forms[i]);
    }
    return out;
}

namespace {

template <class T>
py::array_t<T> table(const std::vector<std::array<T, 3>>& rows)
{
    py::array_t<T> a({ py::ssize_t(rows.size()), py::ssize_t(3) });
    std::copy(rows.begin(), rows.end(), reinterpret_cast<std::array<T, 3>*>(a.mutable_data()));
    return a;
}

} // namespace

void register_objects(py::module_& m)
{
    py::class_<PyAnalysis>(m, "Analysis",
        "A sample's statistics, as texsyn.analyze() gives them and `texsyn --analyze` writes\n"
        "them (.tsa): taken wherever a method takes a sample or its analysis.")
        .def_static(
            "load",
            [](const std::filesystem::path& path) {
                auto stats = std::make_shared<TextureStatistics>();
                std::string error;
                bool ok;
                {
                    ReleaseGil release;
                    ok = read_statistics(path.string(), *stats, error);
                }
                if (!ok)
                    raise_error(ErrorKind::File, error);
                return PyAnalysis { std::move(stats) };
            },
            py::arg("path"), "Reads an analysis file (.tsa).")
        .def(
            "save",
            [](const PyAnalysis& a, const std::filesystem::path& path) {
                std::string error;
                bool ok;
                {
                    ReleaseGil release;
                    ok = write_statistics(path.string(), *a.stats, error);
                }
                if (!ok)
                    raise_error(ErrorKind::File, error);
            },
            py::arg("path"), "Writes the analysis file `path` (.tsa), atomically.")
        .def_property_readonly(
            "size",
            [](const PyAnalysis& a) {
                return py::make_tuple(a.stats->sample_width, a.stats->sample_height);
            },
            "The analysed sample's (width, height).")
        .def_property_readonly(
            "channelnames", [](const PyAnalysis& a) { return a.stats->channel_names; })
        .def_property_readonly(
            "colorspace", [](const PyAnalysis& a) { return a.stats->colorspace; },
            "The colour space the sample was read in.")
        .def_property_readonly(
            "source", [](const PyAnalysis& a) { return a.stats->source; }, "The sample's name.")
        .def("__repr__", [](const PyAnalysis& a) {
            return "<texsyn.Analysis of " + (a.stats->source.empty() ? "a sample" : a.stats->source)
                + ", " + std::to_string(a.stats->sample_width) + "x"
                + std::to_string(a.stats->sample_height) + ">";
        });

    static const std::string material_doc
        = "A material set: an albedo and its other maps (normal, height, roughness, ...), as\n"
          "texsyn.material() makes it. A method that copies pixels, given a Material,\n"
          "synthesizes every map together and returns a dict of maps with its source map.\n"
          "The methods that take one: "
        + command_list(&Method::copies_pixels, "", "") + ".";
    py::class_<PyMaterial>(m, "Material", material_doc.c_str())
        .def_property_readonly("maps", &PyMaterial::maps,
            "The maps by name, the albedo first, each given back as it was given.")
        .def_property_readonly("names",
            [](const PyMaterial& p) {
                std::vector<std::string> names;
                for (const MaterialMap& map : p.material->maps)
                    names.push_back(map.name);
                return names;
            })
        .def("__repr__", [](const PyMaterial& p) {
            std::string names;
            for (const MaterialMap& map : p.material->maps)
                names += (names.empty() ? "" : ", ") + map.name;
            return "<texsyn.Material " + names + ">";
        });

    py::class_<PySurface>(m, "Surface",
        "A texture grown on a mesh (texsyn.choosy_surface): the finest level's triangles with\n"
        "a colour per face, and the UV bakes where the mesh has UVs.")
        .def_property_readonly(
            "vertices", [](const PySurface& s) { return table(s.texture->vertices); },
            "float32 array of N x 3 vertex positions.")
        .def_property_readonly(
            "faces", [](const PySurface& s) { return table(s.texture->faces); },
            "uint32 array of M x 3 vertex indices, counter-clockwise seen from outside.")
        .def_property_readonly(
            "colours",
            [](const PySurface& s) {
                const auto& c = s.texture->colours;
                const size_t n = c.empty() ? 0 : c[0].size();
                py::array_t<float> a({ py::ssize_t(n), py::ssize_t(c.size()) });
                auto v = a.mutable_unchecked<2>();
                for (size_t k = 0; k < c.size(); ++k)
                    for (size_t f = 0; f < n; ++f)
                        v(py::ssize_t(f), py::ssize_t(k)) = c[k][f];
                return a;
            },
            "float32 array of M x C face colours, scene-linear, in channelnames' order.")
        .def_property_readonly(
            "channelnames", [](const PySurface& s) { return s.texture->channelnames; })
        .def_property_readonly(
            "bakes",
            [](const PySurface& s) {
                py::dict out;
                for (const auto& [udim, image] : s.texture->bake)
                    out[py::int_(udim)] = colour_to_python(OIIO::ImageBuf(image), s.bake);
                return out;
            },
            "The UV bakes by UDIM number (1001, ...), given back like the sample; empty for "
            "a mesh without UVs or with bake=0x0.")
        .def(
            "write_ply",
            [](const PySurface& s, const std::filesystem::path& path) {
                std::vector<std::array<uint8_t, 3>> rgb;
                std::string error;
                bool ok;
                {
                    ReleaseGil release;
                    ok = surface_display_rgb(*s.texture, *s.bake.colors, rgb, error)
                        && write_surface_ply(path.string(), *s.texture, &rgb, error);
                }
                if (!ok)
                    raise_error(ErrorKind::File, error);
            },
            py::arg("path"),
            "Writes the mesh as a binary PLY with float face colours (scene-linear) and 8-bit\n"
            "display colours, atomically, as `texsyn ... -o mesh.ply` does.")
        .def("__repr__", [](const PySurface& s) {
            return "<texsyn.Surface " + std::to_string(s.texture->faces.size()) + " faces, "
                + std::to_string(s.texture->bake.size()) + " UV bakes>";
        });
}

} // namespace texsyn::python
