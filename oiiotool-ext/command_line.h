// SPDX-License-Identifier: Apache-2.0
// The tool's grammar (oiiotool's): global options, inputs, `--NAME[:name=value…]` commands
// from the method registry, -o, --recipe, --apply-map; and the check of a whole command
// line before any work is done, so that a bad one never leaves partial output behind.
#pragma once

#include <texsyn/source_map.h>

#include <string>
#include <utility>
#include <vector>

#include "cli_state.h"

namespace texsyn::cli {

/// Whether `arg` is an option that takes the next argument (--seed N, -o FILE, …).
bool takes_argument(const std::string& arg);

/// Whether `arg` is a flag (-v, --help, …).
bool is_flag(const std::string& arg);

/// "--pyramid:size=8x8" -> ("--pyramid", "size=8x8").
std::pair<std::string, std::string> split_command(const std::string& arg);

/// Whether `arg` is --apply-map, with or without its modifier (--apply-map:normal=opengl).
bool is_apply_map(const std::string& arg);

/// The normal-map convention an --apply-map argument names (none without the modifier);
/// throws CliError for any other modifier or value.
NormalMap apply_map_normal(const std::string& arg);

/// What check_command_line decided.
enum class Early { Run, Exit };

/// Sets the global options from `args`, parses every command's options into
/// state.options, and checks the whole command line as the run will see it: the stack's
/// items (count and kind) for every command and output, the outputs' names and formats,
/// the files options read and write, colour space names. Prints --help (--help METHOD,
/// --METHOD:help), --version or --list-methods (returning Exit). Throws CliError on the
/// first problem.
Early check_command_line(CliState& state, const std::vector<std::string>& args);

} // namespace texsyn::cli
