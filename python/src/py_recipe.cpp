// SPDX-License-Identifier: Apache-2.0
#include "py_recipe.h"

#include <filesystem>

#include <OpenImageIO/filesystem.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <texsyn/recipe.h>

#include "py_errors.h"
#include "py_images.h"
#include "py_run.h"

namespace py = pybind11;

namespace texsyn::python {

namespace {

std::string current_dir()
{
    return py::str(py::module_::import("os").attr("getcwd")()).cast<std::string>();
}

// A recipe name (a path, perhaps with "?arguments") with its path made absolute against the
// current folder, so that the recipe's relative paths stay right after a chdir.
std::string absolute_recipe_name(const std::string& text)
{
    const size_t q = text.find('?');
    const std::string arguments = q == std::string::npos ? "" : text.substr(q);
    return std::filesystem::absolute(text.substr(0, q)).lexically_normal().string() + arguments;
}

Recipe load_recipe(const std::filesystem::path& name)
{
    const std::string absolute = absolute_recipe_name(name.string());
    Recipe recipe;
    std::string error;
    bool ok;
    {
        ReleaseGil release;
        ok = recipe_from_filename(absolute, recipe, error);
    }
    if (!ok)
        raise_error(ErrorKind::Value, error);
    // "x.texsyn" that is no file names the sample "x": say so now, not at run().
    // (A sample that is itself a recipe name is left to run().)
    for (const std::string& sample : recipe.samples)
        if (sample.find(".texsyn") == std::string::npos && !OIIO::Filesystem::exists(sample))
            raise_error(ErrorKind::File,
                name.string() + ": no such recipe file or sample (" + sample + ")");
    return recipe;
}

Recipe recipe_from_json(const std::string& text, py::object base_dir)
{
    Recipe recipe;
    std::string error;
    const std::string base
        = base_dir.is_none() ? current_dir() : py::str(base_dir).cast<std::string>();
    if (!parse_recipe(text, base, recipe, error) || !recipe.validate(error))
        raise_error(ErrorKind::Value, error);
    return recipe;
}

py::object run(const Recipe& recipe, py::object threads, py::object progress)
{
    RunControl control(progress);
    RunSettings settings;
    settings.nthreads = threads_keyword(threads);
    settings.progress = control.progress();
    settings.stop = control.stop();
    OIIO::ImageBuf image;
    std::string error;
    const bool ok
        = control.run([&] { return run_recipe(recipe, image, nullptr, error, settings); });
    control.raise_if_stopped();
    if (!ok) // before any progress: a recipe that cannot run as written (a sample missing too)
        raise_error(control.failure_kind(), error);
    return to_python(std::move(image), OutputForm {});
}

} // namespace

void register_recipe(py::module_& m)
{
    py::class_<Recipe>(m, "Recipe",
        "A synthesis recipe (docs/recipes.md): a method, its samples, options, seed and colour\n"
        "spaces. The same recipe gives the same pixels here, in `texsyn` and through the OIIO\n"
        "plugin (oiiotool, maketx, OpenImageIO.ImageBuf).")
        .def_static("load", &load_recipe, py::arg("name"),
            "Reads a recipe: a .texsyn JSON file, or a name as the OIIO plugin takes it\n"
            "(\"rust.png.texsyn?size=512x512&seed=7\"); relative paths in it are resolved now,\n"
            "against the recipe's folder. Raises OSError if the recipe or a sample it names is\n"
            "missing, ValueError for a bad recipe.")
        .def_static("from_json", &recipe_from_json, py::arg("text"),
            py::arg("base_dir") = py::none(),
            "A recipe from JSON text; relative paths are resolved against base_dir (default:\n"
            "the current folder).")
        .def(
            "to_json",
            [](const Recipe& r, py::object base_dir) {
                const std::string base
                    = base_dir.is_none() ? current_dir() : py::str(base_dir).cast<std::string>();
                std::string json, error;
                if (!recipe_to_json(r, base, json, error))
                    raise_error(ErrorKind::Value, error);
                return json;
            },
            py::arg("base_dir") = py::none(),
            "The recipe as JSON with every option written out; paths relative to base_dir\n"
            "(default: the current folder).")
        .def("run", &run, py::kw_only(), py::arg("threads") = py::int_(0),
            py::arg("progress") = py::none(),
            "Synthesizes the recipe: a float32 array (H x W x C; a volume D x H x W x C) in its\n"
            "tocolorspace (scene-linear by default), colour associated with alpha - the pixels\n"
            "`texsyn ... -d float -o out.exr` writes. Same seed, same pixels at any threads=.")
        .def_property_readonly("method", [](const Recipe& r) { return r.method; })
        .def_property_readonly("samples", [](const Recipe& r) { return r.samples; })
        .def_property_readonly("seed", [](const Recipe& r) { return r.seed; })
        .def_property_readonly("tocolorspace", [](const Recipe& r) { return r.tocolorspace; })
        .def_property_readonly(
            "options",
            [](const Recipe& r) {
                const MethodOptions options = r.options ? r.options : r.row()->defaults();
                py::dict d;
                for (const OptionField& f : options.table().fields())
                    d[f.name.c_str()] = options.value(f.name);
                return d;
            },
            "The method's options as text, by name.")
        .def("__repr__", [](const Recipe& r) {
            std::string samples;
            for (const std::string& s : r.samples)
                samples += (samples.empty() ? " of " : ", ") + s;
            return "<texsyn.Recipe " + r.method + samples + ", seed " + std::to_string(r.seed)
                + ">";
        });
}

} // namespace texsyn::python
