// SPDX-License-Identifier: Apache-2.0
// The kinds of stack item, each declared once with everything the tool does with it: what
// it is called, which rows make it, which files hold it, whether commands and recipes take
// it, and how -o writes it. The command-line check, the run, -o and --recipe look a kind up
// here and name no kind or method themselves.
#pragma once

#include <string>
#include <vector>

#include <texsyn/methods.h>

#include "stack.h"

namespace texsyn::cli {

struct CliState;

/// One kind of stack item.
struct ItemKindRules {
    ItemKind kind;
    MethodOutput made_by; ///< the output of the rows whose results are of this kind
    const char* text;     ///< "an image", "a solid texture"
    /// What a command's result of this kind is called ("analysis of rust.png"); "" = its
    /// command's name ("pyramid synthesis of rust.png").
    const char* result_noun;
    /// The extension of the files that hold this kind and nothing else (".vdb"), and what
    /// they hold, for messages ("solid textures"); "" if image files hold it.
    const char* own_extension;
    const char* own_files;
    bool recipes; ///< --recipe describes it
    /// Throws CliError (naming `command`) unless the command of `method` may take an item of
    /// this kind, called `name` (`made`: a command's result), as input `index` of `count`.
    void (*check_input)(const std::string& command, const Method& method, int index, int count,
        const std::string& name, bool made);
    /// The files -o `out` writes for an item of this kind whose parts (a material set's
    /// maps) are `parts`; throws CliError if `out` cannot hold it.
    std::vector<std::string> (*output_files)(
        const std::string& out, const std::vector<std::string>& parts);
    /// Writes `item` for -o `out` (output_files() checked `out`).
    void (*write)(CliState& state, StackItem& item, const std::string& out);
};

/// The rules of `kind`.
const ItemKindRules& kind_rules(ItemKind kind);

/// The kind of a row's result: the kind its output makes (a report leaves its input: an
/// image).
ItemKind item_kind(MethodOutput output);

/// "an image", "an analysis", "a solid texture", "a textured mesh" or "a material set".
const char* item_kind_text(ItemKind kind);

/// What the result of `method` on inputs called `inputs` (file names without folders, or
/// results' names) is called: "pyramid synthesis of rust.png", "analysis of rust.png",
/// "material set of bricks.png", "cascade synthesis".
std::string result_name(const Method& method, const std::vector<std::string>& inputs);

/// The files -o `out` writes for the top item, of `kind` with `parts`: a file another
/// kind holds alone (.vdb, .ply, .tsa) is refused, then the kind's own rule applies.
/// Throws CliError.
std::vector<std::string> output_files(
    const std::string& out, ItemKind kind, const std::vector<std::string>& parts);

} // namespace texsyn::cli
