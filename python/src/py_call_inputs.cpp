// SPDX-License-Identifier: Apache-2.0
// A call's images and option files read as the tool reads them (py_call.h).
#include "py_call.h"

#include <texsyn/io.h>

#include "py_method_table.h"

namespace texsyn::python {

namespace {

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

} // namespace

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
        if (in.material) {
            r.inputs.push_back(
                { nullptr, nullptr, in.material->name, in.material->material.get() });
            continue;
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

} // namespace texsyn::python
