// SPDX-License-Identifier: Apache-2.0
// A call of a generated function (texsyn.pyramid(...)) sorted out: its inputs and keywords
// read with the GIL held, then its images and option files read without it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include <texsyn/inputs.h>
#include <texsyn/methods.h>

#include "py_colours.h"
#include "py_errors.h"
#include "py_images.h"
#include "py_objects.h"

namespace texsyn::python {

/// One input of a call, as given.
struct CallInput {
    std::string name; ///< in messages and synth:sample
    std::optional<ImageArg> image;
    std::shared_ptr<const TextureStatistics> analysis;
    std::shared_ptr<const PyMaterial> material; ///< null with a dict of maps until it is made
    std::string colorspace;                     ///< iscolorspace for it ("" = from the image)
};

/// Everything a generated function was called with, sorted out (GIL held).
struct Call {
    const Method* method = nullptr;
    std::string function; ///< "texsyn.pyramid"
    MethodOptions options;
    std::vector<CallInput> inputs;
    std::vector<std::pair<const OptionField*, ImageArg>> option_images; ///< given in memory
    std::shared_ptr<const ColorConfig> colors;
    uint64_t seed = 0;
    int threads = 0;
    size_t max_memory = 0; ///< RunSettings::max_memory
    pybind11::object progress = pybind11::none();
    std::string tocolorspace;
    bool subbands = false;          ///< give the pyramid's subbands too (rows that have them)
    std::vector<std::string> given; ///< the options the keywords set (their warnings are left out)
};

/// The name an image argument goes by: its file, an ImageBuf's file, else `role`.
std::string input_name(const ImageArg& arg, const std::string& role);

/// Sorts out the positional arguments of a call into call.inputs (before its keywords:
/// iscolorspace= counts them). Raises ValueError for the wrong number or kind.
void read_inputs(Call& call, pybind11::tuple args);

/// Reads the keywords of a call into call.options, its run keywords and colour spaces.
/// Raises ValueError for an unknown keyword (with the nearest) or a bad value.
void read_keywords(Call& call, pybind11::dict kwargs);

/// What one call's inputs became, for the library (kept alive through the run).
struct ReadInputs {
    std::vector<Sample> samples;
    std::vector<MethodInput> inputs;
    OptionImages files;
};

/// Reads the inputs of `call` and the images of its options: `file_options` name the files
/// (call.option_images are in memory). No GIL held; false with the message and its kind
/// (File for a file that cannot be read, Value for its pixels or colour space).
bool read_call_inputs(Call& call, const MethodOptions& file_options, ReadInputs& r, ErrorKind& kind,
    std::string& error);

} // namespace texsyn::python
