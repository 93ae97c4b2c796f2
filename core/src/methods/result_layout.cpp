// SPDX-License-Identifier: Apache-2.0
// A result's layout before the run (what the OIIO plugin's open() answers), and the check
// that every run keeps to it.
#include <texsyn/methods.h>

#include <algorithm>
#include <cstdio>

#include <texsyn/image.h>
#include <texsyn/stats.h>

#include "result_layout_pvt.h"

namespace texsyn {

namespace {

// The usual rule: size= where given (each side; 0 = the input's), else the size of the
// input the colours come from, with its channels; the result tiles.
bool usual_layout(const Method& method, const MethodOptions& options,
    const std::vector<InputLayout>& inputs, ResultLayout& layout, std::string&)
{
    if (inputs.empty()) {
        detail::apply_size_option(options, layout);
        return true;
    }
    const int last = int(inputs.size()) - 1;
    const int i = method.colours_from ? method.colours_from(options) : last;
    layout = detail::layout_from_input(inputs[size_t(std::min(std::max(i, 0), last))], options);
    return true;
}

} // namespace

namespace detail {

ResultLayout layout_from_input(const InputLayout& from, const MethodOptions& options)
{
    ResultLayout layout;
    layout.width = from.width;
    layout.height = from.height;
    layout.channelnames = from.channelnames;
    apply_size_option(options, layout);
    return layout;
}

void apply_size_option(const MethodOptions& options, ResultLayout& layout)
{
    int w = 0, h = 0, d = 0;
    const std::string size = options.value("size");
    const int n = std::sscanf(size.c_str(), "%dx%dx%d", &w, &h, &d);
    if (n >= 2) {
        layout.width = w ? w : layout.width;
        layout.height = h ? h : layout.height;
    }
    if (n == 3 && d)
        layout.depth = d;
}

bool check_result_layout(const Method& method, const MethodOptions& options,
    const std::vector<MethodInput>& inputs, MethodResult& result, std::string& error)
{
    if (!method.makes_recipes() || !result.image.initialized())
        return true;
    std::vector<InputLayout> shapes;
    for (const MethodInput& in : inputs)
        shapes.push_back(input_layout(in));
    ResultLayout want;
    if (!result_layout(method, options, shapes, want, error))
        return false;
    const OIIO::ImageSpec& got = result.image.spec();
    if (got.width == want.width && got.height == want.height && got.depth == want.depth
        && got.channelnames == want.channelnames) {
        if (!want.wrapmodes().empty())
            result.image.specmod().attribute("wrapmodes", want.wrapmodes());
        return true;
    }
    auto text = [](int w, int h, int d, const std::vector<std::string>& names) {
        std::string s = std::to_string(w) + "x" + std::to_string(h);
        if (d > 1)
            s += "x" + std::to_string(d);
        s += " (";
        for (size_t i = 0; i < names.size(); ++i)
            s += (i ? "," : "") + names[i];
        return s + ")";
    };
    error = method.name + ": internal error: the result is "
        + text(got.width, got.height, got.depth, got.channelnames) + ", its layout rule said "
        + text(want.width, want.height, want.depth, want.channelnames);
    return false;
}

} // namespace detail

InputLayout input_layout(const MethodInput& input)
{
    InputLayout l;
    if (input.analysis) {
        l.width = input.analysis->sample_width;
        l.height = input.analysis->sample_height;
        l.channelnames = input.analysis->channel_names;
    } else if (input.image) {
        const OIIO::ImageSpec& spec = input.image->spec();
        l.width = spec.width;
        l.height = spec.height;
        l.channelnames = spec.channelnames;
    }
    return l;
}

bool result_layout(const Method& method, const MethodOptions& options,
    const std::vector<InputLayout>& inputs, ResultLayout& layout, std::string& error)
{
    if (!method.makes_recipes()) {
        error = method.name + " makes no image";
        return false;
    }
    if (!options.validate(error))
        return false;
    const int n = int(inputs.size());
    if (const int wanted = method.input_count(options, n); n != wanted) {
        error = method.name + " takes " + std::to_string(wanted) + " input"
            + (wanted == 1 ? "" : "s") + ", got " + std::to_string(n);
        return false;
    }
    layout = ResultLayout();
    return method.layout ? method.layout(options, inputs, layout, error)
                         : usual_layout(method, options, inputs, layout, error);
}

} // namespace texsyn
