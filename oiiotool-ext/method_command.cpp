// SPDX-License-Identifier: Apache-2.0
// Every registry command the same way: pop its inputs, run it, push its result.
#include "cli_error.h"
#include "commands.h"
#include "item_kinds.h"
#include "quiet_stderr.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <OpenImageIO/filesystem.h>

#include <texsyn/inputs.h>
#include <texsyn/io.h>
#include <texsyn/material.h>

namespace texsyn::cli {

namespace {

// An item's name in another item's name and in synth:sample: a file without its folders.
std::string short_name(const StackItem& item)
{
    return item.file.empty() ? item.name : OIIO::Filesystem::filename(item.file);
}

// " (sample 0 = a.png, sample 1 = b.png)": which input is which, for a message about one.
std::string legend(const Method& m, const std::vector<StackItem>& inputs)
{
    if (inputs.size() < 2)
        return "";
    std::string s;
    for (size_t i = 0; i < inputs.size(); ++i) {
        const std::string role = m.inputs == MethodInputs::ImageAndSample
            ? (i == 0 ? "image" : "sample")
            : "sample " + std::to_string(i);
        s += (i ? ", " : " (") + role + " = " + short_name(inputs[i]);
    }
    return s + ")";
}

// The recipe of `m`'s result on `inputs`, if every input is a file; else null and `why`.
std::shared_ptr<const Recipe> recipe_of(CliState& state, const Method& m,
    const MethodOptions& options, const std::vector<StackItem>& inputs, std::string& why)
{
    if (!m.makes_recipes()) {
        why = "--" + m.name + " makes " + item_kind_text(item_kind(m.output))
            + ", and recipes describe images";
        return nullptr;
    }
    auto recipe = std::make_shared<Recipe>();
    recipe->method = m.name;
    recipe->options = options;
    recipe->seed = state.seed;
    recipe->subbands = state.subbands && m.subbands;
    // Only a config the user named is pinned (the bundled one by name): otherwise the
    // recipe follows $OCIO, or the bundled config, wherever it is opened.
    if (!state.colorconfig_path.empty())
        recipe->colorconfig
            = state.colors().is_bundled() ? ColorConfig::bundled_name : state.colorconfig_path;
    std::vector<std::string> spaces;
    for (const StackItem& item : inputs) {
        if (item.file.empty()) {
            why = "its input, the " + item.name
                + ", is not a file (recipes name their samples' files: write it first and "
                  "read that)";
            return nullptr;
        }
        recipe->samples.push_back(item.file);
        spaces.push_back(item.kind == ItemKind::Analysis ? "" : item.input_colorspace);
    }
    bool same = true, any = false;
    for (const std::string& s : spaces) {
        same = same && s == spaces[0];
        any = any || !s.empty();
    }
    if (any)
        recipe->iscolorspace = same ? std::vector<std::string> { spaces[0] } : spaces;
    return recipe;
}

void print_progress(const std::string& text)
{
    if (text.empty())
        return;
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Writes `image`, the file of output-file option `option` (e.g. a source map), to `file`
// as float, with the names of `inputs` and the command line.
void write_option_file(CliState& state, const std::string& command, const std::string& option,
    const std::string& file, OIIO::ImageBuf& image, const std::string& samples)
{
    image.specmod().attribute("synth:sample", samples);
    image.specmod().attribute("synth:commandline", state.command_line);
    std::string error;
    bool ok;
    {
        QuietStderr quiet(command + " : " + option + "=" + file);
        ok = write_image_verified(image, state.outputs.add(file), OIIO::TypeFloat, error);
    }
    if (!ok)
        throw CliError(command + " : " + option + "=" + state.outputs.final_names(error));
}

} // namespace

void run_method_command(
    CliState& state, const Method& m, const MethodOptions& options, const std::string& modifiers)
{
    const std::string command = "--" + m.name;
    std::vector<StackItem> inputs
        = state.stack.pop(command, m.input_count(options, state.stack.size()));
    std::string error;
    OptionImages files;
    bool ok;
    {
        QuietStderr quiet(command);
        ok = read_option_files(options, state.colors(), files, error, state.threads);
    }
    if (!ok)
        throw CliError(command + " : " + error);
    std::vector<MethodInput> in;
    for (const StackItem& item : inputs)
        in.push_back({ item.kind == ItemKind::Image ? &item.buf : nullptr, item.analysis.get(),
            item.file.empty() ? item.name : item.file,
            item.kind == ItemKind::Material ? item.material.get() : nullptr });
    RunSettings settings;
    settings.seed = state.seed;
    settings.nthreads = state.threads;
    settings.subbands = state.subbands && m.subbands;
    const auto start = std::chrono::steady_clock::now();
    std::shared_ptr<ProgressMeter> meter;
    if (state.progress != ProgressMode::Off && m.output != MethodOutput::Report) {
        meter = std::make_shared<ProgressMeter>(command, state.progress, state.progress_interval);
        print_progress(meter->start());
        settings.progress
            = [meter, start](float f) { print_progress(meter->update(f, seconds_since(start))); };
    }

    MethodResult result;
    ok = run_method(m, options, in, files, settings, result, error);
    if (meter)
        print_progress(meter->finish(ok, seconds_since(start)));
    if (!ok) {
        const bool names_input
            = error.find("sample") != std::string::npos || error.find("image") != std::string::npos;
        throw CliError(command + " : " + error + (names_input ? legend(m, inputs) : ""));
    }
    for (const RunWarning& w : result.warnings) {
        const std::string set = w.option + "=";
        if (modifiers.rfind(set, 0) != 0 && modifiers.find(":" + set) == std::string::npos)
            std::fprintf(stderr, "texsyn WARNING: %s : %s\n", command.c_str(), w.text.c_str());
    }
    if (m.output == MethodOutput::Report) {
        std::fputs(result.report.c_str(), stdout);
        std::fflush(stdout);
        for (StackItem& item : inputs)
            state.stack.push(std::move(item));
        return;
    }

    StackItem item;
    // A material set in gives a material set out (its maps moved together).
    item.kind = result.material ? ItemKind::Material : item_kind(m.output);
    std::vector<std::string> names;
    for (const StackItem& input : inputs)
        names.push_back(short_name(input));
    item.name = result_name(m, names);
    item.recipe = recipe_of(state, m, options, inputs, item.no_recipe);
    // Written like the input its colours come from; a generator's like a float input's:
    // scene-linear in float files, and in the space of untagged integer files (sRGB) in
    // integer ones.
    if (inputs.empty()) {
        item.input_colorspace
            = state.colors().guess_colorspace(OIIO::ImageSpec(1, 1, 3, OIIO::TypeUInt8)).space;
        item.input_format = OIIO::TypeUnknown;
        item.output_colorspace = state.pending_tocolorspace;
    } else {
        const int from = m.colours_from ? m.colours_from(options) : int(inputs.size()) - 1;
        const StackItem& base = inputs[size_t(from)];
        item.input_colorspace = base.input_colorspace;
        item.input_format = base.input_format;
        item.output_colorspace = base.output_colorspace;
    }
    if (result.analysis) {
        result.analysis->colorspace = item.input_colorspace;
        result.analysis->sample_format = item.input_format.c_str();
        item.analysis = std::move(result.analysis);
    }
    item.buf = std::move(result.image);
    item.surface = std::move(result.surface);
    item.material = std::move(result.material);
    if (item.material && !item.buf.initialized())
        item.buf.copy(item.material->maps[0].image);
    item.subbands = std::move(result.subbands);
    if (state.verbose) {
        const double secs = seconds_since(start);
        const std::string made_with = item.buf.initialized()
            ? std::string(item.buf.spec().get_string_attribute("synth:options"))
            : std::string();
        const std::string opts = made_with.empty() ? options.format() : made_with;
        std::string from;
        for (const StackItem& input : inputs)
            from += (from.empty() ? " from " : ", ") + short_name(input);
        std::fprintf(stderr, "texsyn: %s %s%s in %.2f s\n", command.c_str(), opts.c_str(),
            from.c_str(), secs);
        // An operation keeps its input's size unless told otherwise (oiiotool's habit).
        if (const std::string given = options.value("size"); !inputs.empty()
            && item.buf.initialized() && given.find_first_not_of("0x") == std::string::npos
            && !given.empty())
            std::fprintf(stderr, "texsyn: %s size=%dx%d: %s's size (size=WxH sets another)\n",
                command.c_str(), item.buf.spec().width, item.buf.spec().height,
                short_name(inputs[0]).c_str());
        if (!result.notes.empty())
            std::fprintf(stderr, "texsyn: %s %s\n", command.c_str(), result.notes.c_str());
    }
    std::string samples;
    for (const StackItem& input : inputs)
        samples += (samples.empty() ? "" : ",") + short_name(input);
    for (auto& [option, image] : result.files)
        if (!options.value(option).empty()) // (a material's source map is asked for unnamed)
            write_option_file(state, command, option, options.value(option), image, samples);
    state.stack.push(std::move(item));
}

} // namespace texsyn::cli
