// SPDX-License-Identifier: Apache-2.0
// Helpers of the layout rules (methods.h, ResultLayout) for the rows and run_method().
#pragma once

#include <string>
#include <vector>

#include <texsyn/methods.h>

namespace texsyn::detail {

/// The usual layout from input `from`: its size and channels, then size= where given; it
/// tiles.
ResultLayout layout_from_input(const InputLayout& from, const MethodOptions& options);

/// Applies the option size= ("WxH" or "WxHxD"; a 0 side keeps the layout's) to `layout`.
void apply_size_option(const MethodOptions& options, ResultLayout& layout);

/// Checks an image or volume result of `method` against result_layout() for its inputs
/// (false with an "internal error" message naming both layouts if they differ) and tags a
/// result that tiles with wrapmodes "periodic,periodic".
bool check_result_layout(const Method& method, const MethodOptions& options,
    const std::vector<MethodInput>& inputs, MethodResult& result, std::string& error);

} // namespace texsyn::detail
