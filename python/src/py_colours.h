// SPDX-License-Identifier: Apache-2.0
// Colour management of Python calls: which config, and the space a result is given in.
#pragma once

#include <memory>
#include <string>

#include <OpenImageIO/imagebuf.h>
#include <pybind11/pybind11.h>

#include <texsyn/color.h>

#include "py_images.h"

namespace texsyn::python {

/// The config named by colorconfig= ("" = $OCIO, else the bundled one), loaded once per
/// name (and $OCIO value) for the process. Raises ValueError naming colorconfig= if it
/// cannot be loaded.
std::shared_ptr<const ColorConfig> colour_config(const std::string& name);

/// How a colour result is given back.
struct ColourOutput {
    std::shared_ptr<const ColorConfig> colors;
    std::string space; ///< canonical: the space its values are in
    OutputForm form;
};

/// The output of a result made from an input read in `input_space` ("" = none, a
/// generator's): in `tocolorspace` if given; else, for an integer form, in the input's
/// space (a generator's: untagged 8-bit files', sRGB), like the tool writes 8- and 16-bit
/// files; else scene_linear. Raises ValueError for an unknown tocolorspace.
ColourOutput colour_output(std::shared_ptr<const ColorConfig> colors, const OutputForm& form,
    const std::string& input_space, const std::string& tocolorspace);

/// `linear` (float, scene_linear; a volume if spec.depth > 1) converted to out.space and
/// tagged (ColorConfig::tag_colorspace), colour associated with alpha in float forms and
/// un-associated (flagged) in integer ones and volumes, given back as out.form.
pybind11::object colour_to_python(OIIO::ImageBuf&& linear, const ColourOutput& out);

/// Whether pixels of `type` hold encoded values (integers) rather than scene-linear ones.
bool is_integer_type(OIIO::TypeDesc type);

} // namespace texsyn::python
