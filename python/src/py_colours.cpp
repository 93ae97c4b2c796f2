// SPDX-License-Identifier: Apache-2.0
#include "py_colours.h"

#include <cstdlib>
#include <map>
#include <mutex>

#include <texsyn/volume.h>

#include "py_errors.h"
#include "py_run.h"

namespace py = pybind11;

namespace texsyn::python {

std::shared_ptr<const ColorConfig> colour_config(const std::string& name)
{
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const ColorConfig>> loaded;
    const char* env = std::getenv("OCIO");
    const std::string key = name + '\n' + (name.empty() && env ? env : "");
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = loaded.find(key); it != loaded.end())
        return it->second;
    std::string error;
    std::shared_ptr<const ColorConfig> config = ColorConfig::load(name, error);
    if (!config)
        raise_error(ErrorKind::Value,
            (name.empty() ? "colour config: " : "colorconfig=" + name + " : ") + error);
    loaded[key] = config;
    return config;
}

bool is_integer_type(OIIO::TypeDesc type)
{
    return type.basetype == OIIO::TypeDesc::UINT8 || type.basetype == OIIO::TypeDesc::UINT16
        || type.basetype == OIIO::TypeDesc::INT8 || type.basetype == OIIO::TypeDesc::INT16
        || type.basetype == OIIO::TypeDesc::UINT32 || type.basetype == OIIO::TypeDesc::INT32;
}

ColourOutput colour_output(std::shared_ptr<const ColorConfig> colors, const OutputForm& form,
    const std::string& input_space, const std::string& tocolorspace)
{
    ColourOutput out { std::move(colors), "", form };
    if (!tocolorspace.empty()) {
        out.space = out.colors->resolve(tocolorspace);
        if (out.space.empty())
            raise_error(ErrorKind::Value,
                "tocolorspace=" + tocolorspace + " : "
                    + out.colors->unknown_colorspace(tocolorspace));
    } else if (is_integer_type(form.type)) {
        out.space = !input_space.empty()
            ? input_space
            : out.colors->guess_colorspace(OIIO::ImageSpec(1, 1, 3, OIIO::TypeUInt8)).space;
    } else {
        out.space = out.colors->scene_linear();
    }
    return out;
}

py::object colour_to_python(OIIO::ImageBuf&& linear, const ColourOutput& out)
{
    OIIO::ImageBuf converted;
    std::string error;
    bool ok;
    {
        ReleaseGil release;
        ok = linear.spec().depth > 1
            ? convert_volume_colours(
                *out.colors, linear, out.colors->scene_linear(), out.space, converted, error)
            : out.colors->convert_image(linear, out.colors->scene_linear(), out.space,
                !is_integer_type(out.form.type), converted, error);
    }
    if (!ok)
        raise_error(ErrorKind::Runtime, error);
    out.colors->tag_colorspace(converted.specmod(), out.space);
    return to_python(std::move(converted), out.form);
}

} // namespace texsyn::python
