// SPDX-License-Identifier: Apache-2.0
#include "py_methods.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/strutil.h>
#include <pybind11/stl.h>

#include <texsyn/error_text.h>
#include <texsyn/inputs.h>
#include <texsyn/io.h>
#include <texsyn/material.h>
#include <texsyn/methods.h>
#include <texsyn/source_map.h>
#include <texsyn/subbands.h>

#include "py_colours.h"
#include "py_errors.h"
#include "py_images.h"
#include "py_objects.h"
#include "py_run.h"

namespace py = pybind11;

namespace texsyn::python {

namespace {

// The keywords every generated function takes besides its method's options.
const std::vector<std::string>& common_keywords()
{
    static const std::vector<std::string> names
        = { "seed", "threads", "progress", "colorconfig", "iscolorspace", "tocolorspace" };
    return names;
}

// An option's Python keyword: its name with '-' as '_'.
std::string keyword_of(const std::string& option)
{
    std::string k = option;
    std::replace(k.begin(), k.end(), '-', '_');
    return k;
}

const char* inputs_name(MethodInputs inputs)
{
    switch (inputs) {
    case MethodInputs::None:
        return "none";
    case MethodInputs::OptionalImage:
        return "optional_image";
    case MethodInputs::Image:
        return "image";
    case MethodInputs::Sample:
        return "sample";
    case MethodInputs::ImageAndSample:
        return "image_and_sample";
    case MethodInputs::Samples:
        return "samples";
    }
    return "";
}

const char* output_name(MethodOutput output)
{
    switch (output) {
    case MethodOutput::Image:
        return "image";
    case MethodOutput::Volume:
        return "volume";
    case MethodOutput::Analysis:
        return "analysis";
    case MethodOutput::Report:
        return "report";
    case MethodOutput::Mesh:
        return "mesh";
    case MethodOutput::Material:
        return "material";
    }
    return "";
}

const char* type_name(OptionType type)
{
    switch (type) {
    case OptionType::Integer:
        return "integer";
    case OptionType::Real:
        return "real";
    case OptionType::Size:
        return "size";
    case OptionType::Integers:
        return "integers";
    case OptionType::Numbers:
        return "numbers";
    case OptionType::Choice:
        return "choice";
    case OptionType::Choices:
        return "choices";
    case OptionType::InputFile:
        return "input_file";
    case OptionType::OutputFile:
        return "output_file";
    }
    return "";
}

// An option's value text as a Python value: int, float, str, a tuple for sizes and lists,
// None for "none" or an unnamed file.
py::object python_value(const OptionField& f, const std::string& text)
{
    if (text.empty() || (!f.none.empty() && text == f.none))
        return py::none();
    auto parts = [&](const char* sep) { return OIIO::Strutil::splits(text, sep); };
    try {
        switch (f.type) {
        case OptionType::Integer:
            return py::int_(std::stoll(text));
        case OptionType::Real:
            return py::float_(std::stod(text));
        case OptionType::Size: {
            py::list l;
            for (const std::string& p : parts("x"))
                l.append(py::int_(std::stoll(p)));
            return py::tuple(l);
        }
        case OptionType::Integers:
        case OptionType::Numbers:
        case OptionType::Choices: {
            py::list l;
            for (const std::string& p : parts(","))
                l.append(f.type == OptionType::Integers ? py::object(py::int_(std::stoll(p)))
                        : f.type == OptionType::Numbers ? py::object(py::float_(std::stod(p)))
                                                        : py::object(py::str(p)));
            return py::tuple(l);
        }
        default:
            return py::str(text);
        }
    } catch (const std::exception&) { // a word where numbers go ("auto"): as it is
        return py::str(text);
    }
}

// One value of a Python option as text.
std::string scalar_text(const std::string& keyword, py::handle v)
{
    if (py::isinstance<py::bool_>(v))
        return v.cast<bool>() ? "1" : "0";
    if (py::isinstance<py::str>(v))
        return v.cast<std::string>();
    if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v) || py::hasattr(v, "__index__")
        || py::hasattr(v, "__float__"))
        return py::str(v).cast<std::string>();
    raise_error(ErrorKind::Value,
        keyword + "= : expected a number or a string, got "
            + py::str(py::type::handle_of(v).attr("__name__")).cast<std::string>());
}

// A Python option value as the option's text: sizes and lists from sequences, None as
// the option's "none".
std::string option_text(const OptionField& f, const std::string& keyword, py::handle v)
{
    if (v.is_none()) {
        if (f.none.empty())
            raise_error(ErrorKind::Value, keyword + "=None : " + keyword + " has no unset value");
        return f.none;
    }
    if (py::isinstance<py::str>(v) || !py::isinstance<py::sequence>(v))
        return scalar_text(keyword, v);
    std::string text;
    const char* sep = f.type == OptionType::Size ? "x" : ",";
    for (py::object item : py::reinterpret_borrow<py::sequence>(v)) // owned, as in read_inputs
        text += (text.empty() ? "" : sep) + scalar_text(keyword, item);
    return text;
}

py::dict describe_option(const OptionField& f, const std::string& default_text)
{
    py::dict d;
    d["name"] = keyword_of(f.name);
    d["option"] = f.name;
    d["type"] = type_name(f.type);
    d["help"] = f.help;
    d["allowed"] = f.allowed;
    d["default"] = python_value(f, default_text);
    d["default_text"] = default_text;
    d["file"] = f.file == FileUse::ReadImage ? "image"
        : f.file == FileUse::ReadData        ? "data"
        : f.file == FileUse::ReadMesh        ? "mesh"
        : f.file == FileUse::Write           ? "write"
                                             : "";
    return d;
}

// The registry as data for texsyn/__init__.py.
py::list method_table()
{
    py::list rows;
    for (const Method* m : methods()) {
        const MethodOptions defaults = m->defaults();
        py::dict row;
        row["name"] = keyword_of(m->name);
        row["command"] = m->name;
        row["inputs"] = inputs_name(m->inputs);
        row["output"] = output_name(m->output);
        row["summary"] = m->summary;
        row["help"] = m->help;
        row["example"] = m->example;
        row["doc"] = m->doc;
        row["materials"] = synthesizes_materials(*m);
        row["subbands"] = m->subbands;
        py::list options;
        for (const OptionField& f : defaults.table().fields())
            options.append(describe_option(f, defaults.value(f.name)));
        row["options"] = options;
        rows.append(row);
    }
    return rows;
}

// One input of a call, as given.
struct CallInput {
    std::string name; ///< in messages and synth:sample
    std::optional<ImageArg> image;
    std::shared_ptr<const TextureStatistics> analysis;
    std::shared_ptr<const PyMaterial> material;
    std::string colorspace; ///< iscolorspace for it ("" = from the image)
};

// The name an image argument goes by: its file, an ImageBuf's file, else what it is.
std::string input_name(const ImageArg& arg, const std::string& role)
{
    if (arg.kind == ImageKind::Path)
        return arg.path;
    if (arg.kind == ImageKind::ImageBuf && !arg.path.empty())
        return arg.path;
    return role;
}

// Everything a generated function was called with, sorted out (GIL held).
struct Call {
    const Method* method = nullptr;
    std::string function; ///< "texsyn.pyramid"
    MethodOptions options;
    std::vector<CallInput> inputs;
    std::vector<std::pair<const OptionField*, ImageArg>> option_images; ///< given in memory
    std::shared_ptr<const ColorConfig> colors;
    uint64_t seed = 0;
    int threads = 0;
    py::object progress = py::none();
    std::string tocolorspace;
    bool subbands = false;          ///< give the pyramid's subbands too (rows that have them)
    std::vector<std::string> given; ///< the options the keywords set (their warnings are left out)
};

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
    const Method* row = find_method("material");
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

// Reads the keywords of a call to `method`.
void read_keywords(Call& call, py::dict kwargs)
{
    std::string colorconfig;
    py::object iscolorspace = py::none();
    std::vector<std::string> known = common_keywords();
    if (call.method->subbands)
        known.push_back("subbands");
    for (const OptionField& f : call.options.table().fields())
        if (f.type != OptionType::OutputFile)
            known.push_back(keyword_of(f.name));
    for (auto [key, value] : kwargs) {
        const std::string k = py::str(key).cast<std::string>();
        if (k == "seed")
            call.seed = seed_keyword(value);
        else if (k == "threads")
            call.threads = threads_keyword(value);
        else if (k == "progress")
            call.progress = py::reinterpret_borrow<py::object>(value);
        else if (k == "colorconfig")
            colorconfig = value.is_none() ? "" : py::str(value).cast<std::string>();
        else if (k == "iscolorspace")
            iscolorspace = py::reinterpret_borrow<py::object>(value);
        else if (k == "subbands" && call.method->subbands)
            call.subbands = PyObject_IsTrue(value.ptr()) == 1;
        else if (k == "tocolorspace")
            call.tocolorspace = value.is_none() ? "" : py::str(value).cast<std::string>();
        else {
            const OptionField* f = nullptr;
            for (const OptionField& field : call.options.table().fields())
                if (keyword_of(field.name) == k)
                    f = &field;
            if (!f || f->type == OptionType::OutputFile) {
                const std::string near = f ? std::string() : closest_name(k, known);
                raise_error(ErrorKind::Value,
                    call.function + ": unknown keyword '" + k + "'"
                        + (near.empty() ? "" : ", did you mean '" + near + "'?")
                        + (f ? " (" + f->name + "= is returned, not written)" : "")
                        + " (keywords: " + OIIO::Strutil::join(known, ", ") + ")");
            }
            std::string error;
            if (f->type == OptionType::InputFile && !value.is_none() && is_image_arg(value)
                && !py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__")) {
                if (f->file == FileUse::ReadMesh)
                    raise_error(ErrorKind::Value, k + "= : a mesh is given by its file name");
                call.option_images.emplace_back(f, image_arg(value, k + "="));
                continue;
            }
            const std::string text = f->type == OptionType::InputFile && !value.is_none()
                ? py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>()
                : option_text(*f, k, value);
            if (!call.options.set(f->name, text, error))
                raise_error(ErrorKind::Value, error);
            call.given.push_back(f->name);
        }
    }
    call.colors = colour_config(colorconfig);
    // iscolorspace: one for every input, or one per input.
    std::vector<std::string> spaces;
    if (py::isinstance<py::str>(iscolorspace))
        spaces.assign(std::max<size_t>(1, call.inputs.size()), iscolorspace.cast<std::string>());
    else if (py::isinstance<py::sequence>(iscolorspace))
        for (py::handle s : iscolorspace)
            spaces.push_back(s.is_none() ? "" : py::str(s).cast<std::string>());
    else if (!iscolorspace.is_none())
        raise_error(ErrorKind::Value,
            "iscolorspace= : expected a colour space name, or a list of one per input");
    if (!spaces.empty() && spaces.size() != call.inputs.size())
        raise_error(ErrorKind::Value,
            "iscolorspace= : " + std::to_string(spaces.size()) + " colour spaces for "
                + std::to_string(call.inputs.size()) + " inputs (give one, or one per input)");
    for (size_t i = 0; i < spaces.size(); ++i)
        if (!spaces[i].empty() && call.colors->resolve(spaces[i]).empty())
            raise_error(ErrorKind::Value,
                "iscolorspace=" + spaces[i] + " : " + call.colors->unknown_colorspace(spaces[i]));
        else
            call.inputs[i].colorspace = spaces[i];
}

// Sorts out the positional arguments of a call (before its keywords: iscolorspace= counts
// them).
void read_inputs(Call& call, py::tuple args)
{
    const Method& m = *call.method;
    // Owned: a sequence's items may be made as they are read (an array's rows), and a
    // borrowed handle would outlive them.
    std::vector<py::object> given;
    std::vector<std::string> roles;
    if (m.inputs == MethodInputs::Samples) {
        if (args.size() != 1 || py::isinstance<py::str>(args[0])
            || !py::isinstance<py::sequence>(args[0]))
            raise_error(ErrorKind::Value, call.function + ": expected one list of samples");
        for (py::object s : py::reinterpret_borrow<py::sequence>(args[0])) {
            roles.push_back("samples[" + std::to_string(given.size()) + "]");
            given.push_back(s);
        }
    } else {
        for (py::handle a : args)
            given.push_back(py::reinterpret_borrow<py::object>(a));
        const char* role = m.inputs == MethodInputs::Sample ? "sample" : "image";
        for (size_t i = 0; i < given.size(); ++i)
            roles.push_back(m.inputs == MethodInputs::ImageAndSample && i == 1 ? "sample" : role);
    }
    const size_t max = m.inputs == MethodInputs::None ? 0
        : m.inputs == MethodInputs::Samples           ? given.size()
        : m.inputs == MethodInputs::ImageAndSample    ? 2
                                                      : 1;
    const size_t min = m.inputs == MethodInputs::OptionalImage ? 0 : max;
    if (given.size() < min || given.size() > max)
        raise_error(ErrorKind::Value,
            call.function + " takes " + (min == max ? "" : "at most ") + std::to_string(max)
                + " input" + (max == 1 ? "" : "s") + ", got " + std::to_string(given.size()));
    for (size_t i = 0; i < given.size(); ++i) {
        CallInput in;
        const py::object& g = given[i];
        if (py::isinstance<PyAnalysis>(g)) {
            in.analysis = g.cast<const PyAnalysis&>().stats;
            in.name = in.analysis->source.empty() ? roles[i] : in.analysis->source;
        } else if (py::isinstance<PyMaterial>(g) || py::isinstance<py::dict>(g)) {
            if (!synthesizes_materials(m) || given.size() != 1)
                raise_error(ErrorKind::Value,
                    call.function + ": a material set is synthesized by the copying methods ("
                        + command_list(synthesizes_materials, "", "") + "), one set at a time");
            in.material = py::isinstance<PyMaterial>(g)
                ? std::make_shared<PyMaterial>(g.cast<PyMaterial>())
                : nullptr; // a dict: made once the keywords are read
        } else {
            in.image = image_arg(g, roles[i]);
            in.name = input_name(*in.image, roles[i]);
        }
        call.inputs.push_back(std::move(in));
    }
}

// What one call's inputs became, for the library (kept alive through the run).
struct ReadInputs {
    std::vector<Sample> samples;
    std::vector<MethodInput> inputs;
    OptionImages files;
};

// read_sample() of `path` with its failures told apart: the file's (missing, unreadable,
// truncated: File) from its pixels' (NaN or Inf, a colour space: Value).
bool read_path_sample(const std::string& path, const ColorConfig& colors,
    const std::string& colorspace, Sample& s, ErrorKind& kind, std::string& error, int nthreads)
{
    kind = ErrorKind::File;
    if (is_analysis_filename(path))
        return read_sample(path, colors, colorspace, s, error, nthreads);
    OIIO::ImageSpec native;
    OIIO::ImageBuf pixels;
    if (!read_image(path, pixels, error, &native, sample_read_copies))
        return false;
    kind = ErrorKind::Value;
    return sample_from_file_pixels(
        std::move(pixels), native, path, colors, colorspace, s, error, nthreads);
}

// Reads the inputs of `call` and the images of its options: `file_options` name the files
// (call.option_images are in memory). No GIL held; false with the message and its kind.
bool read_call_inputs(Call& call, const MethodOptions& file_options, ReadInputs& r, ErrorKind& kind,
    std::string& error)
{
    r.samples.resize(call.inputs.size());
    for (size_t i = 0; i < call.inputs.size(); ++i) {
        CallInput& in = call.inputs[i];
        Sample& s = r.samples[i];
        if (in.image && in.image->kind == ImageKind::Path) {
            if (!read_path_sample(
                    in.image->path, *call.colors, in.colorspace, s, kind, error, call.threads))
                return false;
        } else if (in.image) {
            kind = ErrorKind::Value;
            if (!sample_from_image(
                    in.image->pixels, in.name, *call.colors, in.colorspace, s, error, call.threads))
                return false;
        }
        const TextureStatistics* analysis = in.analysis ? in.analysis.get() : s.analysis.get();
        r.inputs.push_back({ analysis ? nullptr : &s.pixels, analysis, in.name });
    }
    // Option images: files read as the tool reads them, arrays and ImageBufs likewise.
    kind = ErrorKind::File;
    if (!read_option_files(file_options, *call.colors, r.files, error, call.threads))
        return false;
    kind = ErrorKind::Value;
    for (auto& [field, arg] : call.option_images) {
        const std::string what = keyword_of(field->name) + "=";
        if (field->file == FileUse::ReadImage) {
            Sample s;
            if (!sample_from_image(arg.pixels, what, *call.colors, "", s, error, call.threads))
                return false;
            r.files[field->name] = std::move(s.pixels);
        } else if (!r.files[field->name].copy(arg.pixels, OIIO::TypeFloat)) {
            error = what + " : " + r.files[field->name].geterror();
            return false;
        }
    }
    return true;
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
    settings.progress = control.progress();
    settings.stop = control.stop();
    settings.source_map = synthesizes_materials(m);
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
            ok = material ? run_material_method(m, call.options, *material->material,
                     material->name, r.files, settings, result, error)
                          : run_method(m, call.options, r.inputs, r.files, settings, result, error);
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

void register_methods(py::module_& m)
{
    m.def("_method_table", &method_table,
        "The registry's rows with their option tables (what the functions are made from).");
    m.def("_run_method", &run_method_py, py::arg("name"), py::arg("args"), py::arg("kwargs"));
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
