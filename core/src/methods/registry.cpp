// SPDX-License-Identifier: Apache-2.0
// The registry's rows, listed once, and the checks every run goes through.
#include <texsyn/methods.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <new>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebufalgo.h>

#include <texsyn/homogeneity.h>
#include <texsyn/stats.h>

#include "image/memory_pvt.h"
#include "material/material_run_pvt.h"
#include "result_layout_pvt.h"

namespace texsyn {

namespace detail {
// The rows, each defined in its method's folder (<method>/<method>_method.cpp).
const Method& pyramid_method();
const Method& solid_method();
const Method& mix_method();
const Method& transfer_method();
const Method& neighborhood_method();
const Method& choosy_method();
const Method& surface_method();
const Method& patch_method();
const Method& fill_method();
const Method& tileable_method();
const Method& material_method();
const Method& cascade_method();
const Method& analyze_method();
const Method& check_method();
} // namespace detail

namespace {

// Above this many pixels a sample is checked on a reduced copy: the lighting and the
// regions' means are low-frequency measures.
constexpr int64_t kCheckedPixels = 1024 * 1024;

// For a run with flatten=0: a warning if its first image input is lit unevenly enough for
// the method to re-tile the lighting (check_homogeneity's uneven_for_copying).
void warn_of_uneven_lighting(
    const MethodOptions& options, const std::vector<MethodInput>& inputs, MethodResult& result)
{
    if (!options.table().find("flatten") || options.value("flatten") != "0")
        return;
    const MethodInput* sample = nullptr;
    for (const MethodInput& in : inputs)
        if (in.image && !sample)
            sample = &in;
    if (!sample)
        return;
    const OIIO::ImageSpec& spec = sample->image->spec();
    OIIO::ImageBuf reduced;
    const OIIO::ImageBuf* measured = sample->image;
    if (int64_t(spec.width) * spec.height > kCheckedPixels) {
        const double k = std::sqrt(double(kCheckedPixels) / (double(spec.width) * spec.height));
        const int w = std::max(1, int(spec.width * k)), h = std::max(1, int(spec.height * k));
        reduced = OIIO::ImageBufAlgo::resize(*sample->image, "", 0.0f, OIIO::ROI(0, w, 0, h));
        measured = &reduced;
    }
    PlanarImage planes;
    std::string error;
    if (!planes_from_imagebuf(*measured, planes, error))
        return;
    const HomogeneityReport r = check_homogeneity(planes);
    if (!r.uneven_for_copying)
        return;
    char amplitude[16];
    std::snprintf(amplitude, sizeof(amplitude), "%.0f%%", 100.0 * r.illumination_amplitude);
    result.warnings.push_back({ "flatten",
        OIIO::Filesystem::filename(sample->name) + " is unevenly lit (" + amplitude + ", "
            + r.illumination_description
            + "): the result carries it as light and dark patches (or tiles whose edges differ); "
              "flatten=1 divides the "
              "lighting out (texsyn SAMPLE --check measures it)" });
}

} // namespace

const std::vector<const Method*>& methods()
{
    static const std::vector<const Method*> rows = {
        &detail::pyramid_method(),
        &detail::solid_method(),
        &detail::mix_method(),
        &detail::transfer_method(),
        &detail::neighborhood_method(),
        &detail::choosy_method(),
        &detail::surface_method(),
        &detail::patch_method(),
        &detail::fill_method(),
        &detail::tileable_method(),
        &detail::material_method(),
        &detail::cascade_method(),
        &detail::analyze_method(),
        &detail::check_method(),
    };
    return rows;
}

const Method* find_method(std::string_view name)
{
    for (const Method* m : methods())
        if (m->name == name)
            return m;
    return nullptr;
}

std::string command_list(const std::function<bool(const Method&)>& which, const std::string& suffix,
    const std::string& prefix)
{
    std::vector<std::string> names;
    for (const Method* m : methods())
        if (which(*m))
            names.push_back(prefix + m->name + suffix);
    std::string list;
    for (size_t i = 0; i < names.size(); ++i)
        list += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
    return list;
}

std::string method_names(bool all)
{
    std::string names;
    for (const Method* m : methods())
        if (all || m->makes_recipes())
            names += (names.empty() ? "" : "|") + m->name;
    return names;
}

int Method::input_count(const MethodOptions& options, int available) const
{
    switch (inputs) {
    case MethodInputs::None:
        return 0;
    case MethodInputs::OptionalImage:
        return available > 0 ? 1 : 0;
    case MethodInputs::Image:
    case MethodInputs::Sample:
        return 1;
    case MethodInputs::ImageAndSample:
        return 2;
    case MethodInputs::Samples:
        return count(options);
    }
    return 0;
}

bool Method::accepts_analysis(int index) const
{
    return inputs == MethodInputs::Sample || inputs == MethodInputs::Samples
        || (inputs == MethodInputs::ImageAndSample && index == 1);
}

namespace {

// synth:sample names the samples (file names without folders); a transfer's image is
// synth:image. An analysis records its sample's name.
void name_inputs(const Method& method, const std::vector<MethodInput>& inputs, MethodResult& result)
{
    std::string samples;
    for (size_t i = 0; i < inputs.size(); ++i) {
        const std::string name = OIIO::Filesystem::filename(inputs[i].name);
        if (method.inputs == MethodInputs::ImageAndSample && i == 0)
            result.image.specmod().attribute("synth:image", name);
        else
            samples += (samples.empty() ? "" : ",") + name;
    }
    if (result.analysis)
        result.analysis->source = samples;
    else if (!samples.empty() && result.image.initialized())
        result.image.specmod().attribute("synth:sample", samples);
}

} // namespace

bool run_method(const Method& method, const MethodOptions& options,
    const std::vector<MethodInput>& inputs, const OptionImages& files, const RunSettings& settings,
    MethodResult& result, std::string& error)
{
    if (!options.validate(error))
        return false;
    const int n = int(inputs.size());
    const int wanted = method.input_count(options, n);
    if (n != wanted) {
        error = method.name + " takes " + std::to_string(wanted) + " input"
            + (wanted == 1 ? "" : "s") + ", got " + std::to_string(n);
        return false;
    }
    for (int i = 0; i < n; ++i) {
        const MethodInput& in = inputs[size_t(i)];
        if (in.material && (!method.copies_pixels || n != 1)) {
            error = in.name + " is a material set; " + command_list(&Method::copies_pixels, "", "")
                + " synthesize one, one set at a time";
            return false;
        }
        if (int(!in.image) + int(!in.analysis) + int(!in.material) != 2) {
            error = "input " + std::to_string(i) + " (" + in.name
                + ") must be one of an image, an analysis or a material set";
            return false;
        }
        if (in.analysis && !method.accepts_analysis(i)) {
            error = in.name + " is an analysis, not an image (" + method.name
                + " needs the image it was made from)";
            return false;
        }
    }
    for (const OptionField& f : options.table().fields())
        if (f.type == OptionType::InputFile && f.file != FileUse::ReadMesh
            && !options.value(f.name).empty() && !files.count(f.name)) {
            error = option_error(f.name, options.value(f.name), "the file was not read");
            return false;
        }
    try {
        const detail::RunMemoryBudget budget(settings.max_memory);
        if (n == 1 && inputs[0].material)
            return detail::run_on_material(
                method, options, inputs[0], files, settings, result, error);
        if (!method.run(options, inputs, files, settings, result, error))
            return false;
        warn_of_uneven_lighting(options, inputs, result);
        name_inputs(method, inputs, result);
        return detail::check_result_layout(method, options, inputs, result, error);
    } catch (const std::bad_alloc&) {
        error = method.name + ": out of memory";
    } catch (const std::exception& e) {
        error = method.name + ": " + e.what();
    }
    return false;
}

} // namespace texsyn
