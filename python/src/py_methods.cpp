// SPDX-License-Identifier: Apache-2.0
// A call of a generated function run: its inputs read, the method run without the GIL,
// and the result returned in the form of the input its colours come from.
#include "py_methods.h"

#include <algorithm>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <texsyn/material.h>
#include <texsyn/methods.h>
#include <texsyn/subbands.h>

#include "py_call.h"
#include "py_method_table.h"
#include "py_run.h"

namespace py = pybind11;

namespace texsyn::python {

namespace {

py::object run_call(Call& call);

// `image`'s planes as a float32 array H x W x C.
py::array_t<float> planar_array(const PlanarImage& image)
{
    const int w = image.width(), h = image.height(), nc = image.nchannels();
    py::array_t<float> a({ py::ssize_t(h), py::ssize_t(w), py::ssize_t(nc) });
    float* out = a.mutable_data();
    for (int c = 0; c < nc; ++c) {
        const float* in = image.channels[size_t(c)].data();
        for (size_t i = 0; i < size_t(w) * size_t(h); ++i)
            out[i * size_t(nc) + size_t(c)] = in[i];
    }
    return a;
}

// A dict of maps ({"albedo": ..., "normal": ...}) as the Material texsyn.material() makes.
std::shared_ptr<const PyMaterial> material_of_dict(const Call& call, py::dict maps)
{
    // The row that makes material sets from their maps.
    const Method* row = *std::find_if(methods().begin(), methods().end(),
        [](const Method* r) { return r->output == MethodOutput::Material; });
    Call m;
    m.method = row;
    m.function = call.function;
    m.options = row->defaults();
    m.colors = call.colors;
    m.threads = call.threads;
    if (!maps.contains("albedo"))
        raise_error(ErrorKind::Value,
            call.function + ": a dict of maps needs an \"albedo\" (give maps by name: albedo, "
                + row->defaults().table().names() + ")");
    for (auto [key, value] : maps) {
        const std::string name = py::str(key).cast<std::string>();
        if (name == "albedo") {
            CallInput in;
            in.image = image_arg(value, "albedo");
            in.name = input_name(*in.image, "albedo");
            in.colorspace = call.inputs.empty() ? "" : call.inputs[0].colorspace;
            m.inputs.push_back(std::move(in));
            continue;
        }
        const OptionField* f = m.options.table().find(name);
        if (!f || f->type != OptionType::InputFile)
            raise_error(ErrorKind::Value,
                call.function + ": no map called \"" + name + "\" (maps: albedo, "
                    + row->defaults().table().names() + ")");
        ImageArg arg = image_arg(value, name);
        std::string error;
        if (arg.kind == ImageKind::Path) {
            if (!m.options.set(f->name, arg.path, error))
                raise_error(ErrorKind::Value, error);
        } else {
            m.option_images.emplace_back(f, std::move(arg));
        }
    }
    return std::make_shared<PyMaterial>(run_call(m).cast<PyMaterial>());
}

// The form and colour space a result takes from the input its colours come from.
ColourOutput result_output(const Call& call, const ReadInputs& r)
{
    const Method& m = *call.method;
    OutputForm form;
    std::string space;
    if (!call.inputs.empty()) {
        const int from
            = m.colours_from ? m.colours_from(call.options) : int(call.inputs.size()) - 1;
        const CallInput& in = call.inputs[size_t(from)];
        if (in.image)
            form = output_form(*in.image);
        if (in.material)
            form = in.material->albedo.form;
        space = in.material ? in.material->albedo.space : r.samples[size_t(from)].colorspace;
        if (in.analysis)
            space = in.analysis->colorspace;
    }
    return colour_output(call.colors, form, space, call.tocolorspace);
}

py::object run_call(Call& call)
{
    const Method& m = *call.method;
    std::string error;
    // The options' files are read as the tool reads them; in-memory option images are
    // named by what they are before the options are validated (a rule such as fill's
    // "mask= is required" sees them).
    const MethodOptions file_options = call.options;
    for (auto& [field, arg] : call.option_images)
        if (!call.options.set(
                field->name, arg.kind == ImageKind::Array ? "array" : "ImageBuf", error))
            raise_error(ErrorKind::Value, error);
    if (!call.options.validate(error))
        raise_error(ErrorKind::Value, error);
    const std::shared_ptr<const PyMaterial> material
        = call.inputs.size() == 1 ? call.inputs[0].material : nullptr;

    RunControl control(call.progress);
    RunSettings settings;
    settings.seed = call.seed;
    settings.nthreads = call.threads;
    settings.max_memory = call.max_memory;
    settings.progress = control.progress();
    settings.stop = control.stop();
    settings.source_map = m.copies_pixels;
    settings.subbands = call.subbands;
    ReadInputs r;
    MethodResult result;
    ErrorKind kind = ErrorKind::Runtime;
    const bool ok = control.run([&] {
        bool ok = read_call_inputs(call, file_options, r, kind, error);
        // Options that cannot apply to these inputs are bad options, found before the run.
        if (ok && !material
            && (m.output == MethodOutput::Image || m.output == MethodOutput::Volume)) {
            std::vector<InputLayout> layouts;
            for (const MethodInput& in : r.inputs)
                layouts.push_back(input_layout(in));
            ResultLayout layout;
            kind = ErrorKind::Value;
            ok = result_layout(m, call.options, layouts, layout, error);
        }
        if (ok) {
            ok = run_method(m, call.options, r.inputs, r.files, settings, result, error);
            kind = control.failure_kind();
        }
        return ok;
    });
    control.raise_if_stopped();
    if (!ok)
        raise_error(kind, call.function + ": " + error);
    for (const RunWarning& w : result.warnings)
        if (std::find(call.given.begin(), call.given.end(), w.option) == call.given.end())
            py::module_::import("warnings")
                .attr("warn")(call.function + ": " + w.text,
                    py::module_::import("builtins").attr("UserWarning"), 2);

    const ColourOutput out = result_output(call, r);
    switch (m.output) {
    case MethodOutput::Analysis: {
        const Sample& s = r.samples[0];
        result.analysis->colorspace = s.colorspace;
        result.analysis->sample_format = s.file_format.c_str();
        return py::cast(PyAnalysis { std::move(result.analysis) });
    }
    case MethodOutput::Report:
        return py::str(result.report);
    case MethodOutput::Mesh:
        return py::cast(PySurface { std::move(result.surface), out });
    case MethodOutput::Material: {
        PyMaterial set;
        set.material = std::move(result.material);
        set.albedo = out;
        set.name = call.inputs[0].name;
        for (const MaterialMap& map : set.material->maps) {
            OutputForm form;
            if (map.name == "albedo")
                form = out.form;
            for (const auto& [field, arg] : call.option_images)
                if (field->name == map.name)
                    form = output_form(arg);
            set.forms.push_back(form);
        }
        return py::cast(std::move(set));
    }
    case MethodOutput::Image:
    case MethodOutput::Volume:
        break;
    }
    py::object image = material ? py::object(material->maps_of(*result.material))
                                : colour_to_python(std::move(result.image), out);
    // The images of the output-file options (a source map), after the result; None for one
    // a run has not (a fill from sample= copies from two images: it has no source map).
    py::list files;
    for (const OptionField& f : call.options.table().fields())
        if (f.type == OptionType::OutputFile) {
            const auto file = std::find_if(result.files.begin(), result.files.end(),
                [&](const auto& named) { return named.first == f.name; });
            if (file != result.files.end())
                files.append(
                    to_python(std::move(file->second), { out.form.kind, OIIO::TypeFloat }));
            else if (settings.source_map && f.name == "map")
                files.append(py::none());
        }
    if (call.subbands) { // float32 arrays of the decorrelated components, by part name
        py::dict bands;
        for (const NamedImage& band : result.subbands)
            bands[band.name.c_str()] = planar_array(band.image);
        files.append(bands);
    }
    if (files.empty())
        return image;
    py::list all;
    all.append(image);
    for (py::handle f : files)
        all.append(f);
    return py::tuple(all);
}

py::object run_method_py(const std::string& name, py::tuple args, py::dict kwargs)
{
    Call call;
    call.method = find_method(name);
    if (!call.method)
        raise_error(ErrorKind::Value, "no method called '" + name + "'");
    call.function = "texsyn." + keyword_of(name);
    call.options = call.method->defaults();
    read_inputs(call, args);
    read_keywords(call, kwargs);
    for (CallInput& in : call.inputs)
        if (!in.image && !in.analysis) {
            if (!in.material)
                in.material = material_of_dict(call, py::reinterpret_borrow<py::dict>(args[0]));
            in.name = in.material->name;
        }
    return run_call(call);
}

} // namespace

void register_methods(py::module_& m)
{
    m.def("_method_table", &method_table,
        "The registry's rows with their option tables (what the functions are made from).");
    m.def("_run_method", &run_method_py, py::arg("name"), py::arg("args"), py::arg("kwargs"));
}

} // namespace texsyn::python
