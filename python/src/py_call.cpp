// SPDX-License-Identifier: Apache-2.0
#include "py_call.h"

#include <algorithm>

#include <OpenImageIO/strutil.h>
#include <pybind11/stl.h>

#include <texsyn/error_text.h>
#include <texsyn/material.h>

#include "py_method_table.h"
#include "py_run.h"

namespace py = pybind11;

namespace texsyn::python {

namespace {

// The keywords every generated function takes besides its method's options.
const std::vector<std::string>& common_keywords()
{
    static const std::vector<std::string> names = { "seed", "threads", "max_memory", "progress",
        "colorconfig", "iscolorspace", "tocolorspace" };
    return names;
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

} // namespace

std::string input_name(const ImageArg& arg, const std::string& role)
{
    if (arg.kind == ImageKind::Path)
        return arg.path;
    if (arg.kind == ImageKind::ImageBuf && !arg.path.empty())
        return arg.path;
    return role;
}

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
            if (!m.copies_pixels || given.size() != 1)
                raise_error(ErrorKind::Value,
                    call.function + ": a material set is synthesized by the copying methods ("
                        + command_list(&Method::copies_pixels, "", "") + "), one set at a time");
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
        else if (k == "max_memory")
            call.max_memory = memory_keyword(value);
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

} // namespace texsyn::python
