// SPDX-License-Identifier: Apache-2.0
// What the tool's arguments do to the state: read inputs, run registry commands, write
// outputs. Each throws CliError naming the argument on failure.
#pragma once

#include <string>
#include <vector>

#include <texsyn/methods.h>

#include "cli_state.h"

namespace texsyn::cli {

/// Reads `filename` (an image, converted to scene-linear, or an analysis file) and pushes
/// it.
void push_input(CliState& state, const std::string& filename);

/// Declares the colour space of the input on top of the stack and re-linearises it.
void reinterpret_input(CliState& state, const std::string& colorspace);

/// `--NAME[:modifiers]` of registry row `method` with its parsed `options` (`modifiers` as
/// typed): pops its inputs, runs it (progress as progress_meter.h says, a timing line with
/// -v), prints its warnings (but those about an option the modifiers set), pushes its
/// result (a report is printed and its input stays), and writes the files its output-file
/// options name.
void run_method_command(CliState& state, const Method& method, const MethodOptions& options,
    const std::string& modifiers);

/// Writes the top item for `filename` as its kind says (item_kinds.h), with synth:*
/// metadata, to temporary files committed at the end of the run.
void write_output(CliState& state, const std::string& filename);

/// The writers of the kinds of item (item_kinds.h), each of `item` for -o `filename`: an
/// image in the colour space and pixel type of the policy in docs/colour.md (with
/// --subbands the multi-part inspection EXR); an analysis as *.tsa; a volume as OpenVDB or
/// a slice EXR; a textured mesh as .ply or its UV bake (one image per UDIM tile); a
/// material set as one file per map (material_map_filename), the albedo like an image and
/// the other maps as their numbers.
void write_image_output(CliState& state, StackItem& item, const std::string& filename);
void write_analysis_output(CliState& state, StackItem& item, const std::string& filename);
void write_volume_output(CliState& state, StackItem& item, const std::string& filename);
void write_mesh_output(CliState& state, StackItem& item, const std::string& filename);
void write_material_output(CliState& state, StackItem& item, const std::string& filename);

/// "out_{map}.exr" with `map` in place of every {map}.
std::string material_map_filename(const std::string& pattern, const std::string& map);

/// --recipe FILE: writes the recipe of the top item (a command's result from files), with
/// paths relative to FILE's folder.
void write_recipe(CliState& state, const std::string& filename);

/// --apply-map MAP IMAGE: reads IMAGE (an input like any other), rearranges its pixels by
/// the source map MAP, and pushes the result, which keeps IMAGE's colour space on output.
void run_apply_map(CliState& state, const std::string& command_arg, const std::string& map_file,
    const std::string& image_file);

/// Prints --help, --list-methods and --version text to stdout.
void print_help();
void print_methods();
void print_version();

/// The registry row that `--help TOPIC` asks about (TOPIC is NAME or --NAME); throws
/// CliError naming TOPIC, with a suggestion and the list of methods, if there is none.
const Method& method_for_help(const std::string& topic);

/// Prints `--help NAME` (and `--NAME:help`) to stdout: the row's summary, help text, every
/// option with its allowed values, default and meaning, its example and its doc pages.
void print_method_help(const Method& method);

} // namespace texsyn::cli
