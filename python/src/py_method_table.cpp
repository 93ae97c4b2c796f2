// SPDX-License-Identifier: Apache-2.0
#include "py_method_table.h"

#include <algorithm>

#include <OpenImageIO/strutil.h>

#include <texsyn/material.h>
#include <texsyn/methods.h>

namespace py = pybind11;

namespace texsyn::python {

namespace {

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

} // namespace

std::string keyword_of(const std::string& option)
{
    std::string k = option;
    std::replace(k.begin(), k.end(), '-', '_');
    return k;
}

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
        row["materials"] = m->copies_pixels;
        row["subbands"] = m->subbands;
        py::list options;
        for (const OptionField& f : defaults.table().fields())
            options.append(describe_option(f, defaults.value(f.name)));
        row["options"] = options;
        rows.append(row);
    }
    return rows;
}

} // namespace texsyn::python
