// SPDX-License-Identifier: Apache-2.0
// Inputs: samples read into scene-linear float (texsyn/inputs.h), and --iscolorspace.
#include "cli_error.h"
#include "commands.h"
#include "quiet_stderr.h"

#include <cstdio>

#include <texsyn/inputs.h>

namespace texsyn::cli {

namespace {

// -v: the colour space `filename` was read as, why, and any doubt about it.
void report_colorspace(const std::string& filename, const Sample& sample)
{
    std::fprintf(stderr, "texsyn: %s read as '%s': %s\n", filename.c_str(),
        sample.colorspace.c_str(), sample.colorspace_reason.c_str());
    if (!sample.colorspace_warning.empty())
        std::fprintf(stderr, "texsyn WARNING: %s: %s\n", filename.c_str(),
            sample.colorspace_warning.c_str());
}

} // namespace

const ColorConfig& CliState::colors()
{
    if (!m_colors) {
        std::string error;
        m_colors = ColorConfig::load(colorconfig_path, error);
        if (!m_colors)
            throw CliError(error);
    }
    return *m_colors;
}

void push_input(CliState& state, const std::string& filename)
{
    if (!state.pending_iscolorspace.empty() && is_analysis_filename(filename))
        throw CliError("--iscolorspace : " + filename
            + " is an analysis, its statistics are already scene-linear");
    Sample sample;
    std::string error;
    bool ok;
    {
        QuietStderr quiet(filename); // image libraries print their own diagnostics
        ok = read_sample(
            filename, state.colors(), state.pending_iscolorspace, sample, error, state.threads);
    }
    if (!ok)
        throw CliError(error);
    state.pending_iscolorspace.clear();
    StackItem item;
    item.kind = sample.analysis ? ItemKind::Analysis : ItemKind::Image;
    item.buf = std::move(sample.pixels);
    item.file_pixels = std::move(sample.file_pixels);
    item.analysis = std::move(sample.analysis);
    item.name = item.file = filename;
    item.input_format = sample.file_format;
    item.input_colorspace = sample.colorspace;
    item.output_colorspace = state.pending_tocolorspace;
    if (state.verbose)
        report_colorspace(filename, sample);
    state.stack.push(std::move(item));
}

void reinterpret_input(CliState& state, const std::string& colorspace)
{
    StackItem& item = state.stack.top("--iscolorspace");
    if (!item.file_pixels.initialized())
        throw CliError("--iscolorspace : the current image is not an input file "
                       "(put --iscolorspace right after the file name)");
    Sample sample;
    sample.filename = item.name;
    sample.file_pixels = std::move(item.file_pixels);
    std::string error;
    const bool ok = relinearize_sample(sample, state.colors(), colorspace, error, state.threads);
    item.file_pixels = std::move(sample.file_pixels);
    if (!ok)
        throw CliError(
            error.rfind("unknown colour space", 0) == 0 ? "--iscolorspace : " + error : error);
    item.buf = std::move(sample.pixels);
    item.input_colorspace = sample.colorspace;
    if (state.verbose)
        report_colorspace(item.name, sample);
}

} // namespace texsyn::cli
