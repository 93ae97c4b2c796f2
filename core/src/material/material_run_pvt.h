// SPDX-License-Identifier: Apache-2.0
// A material set synthesized by a row that copies pixels: run_method's path for a
// MethodInput::material (methods.h).
#pragma once

#include <string>

#include <texsyn/methods.h>

namespace texsyn::detail {

/// Synthesizes `input.material` with `method` (a row that copies_pixels): the method runs, by
/// run_method, on material_search_image() (named input.name in messages) with
/// settings.source_map set, then apply_material() moves every map by the run's source map;
/// flatten=1 flattens the albedo alone first. `result` is the run's (its files hold the
/// source map "map"), with result.material the synthesized set and result.image its
/// albedo. False with a message as run_method() or apply_material() give.
bool run_on_material(const Method& method, const MethodOptions& options, const MethodInput& input,
    const OptionImages& files, RunSettings settings, MethodResult& result, std::string& error);

} // namespace texsyn::detail
