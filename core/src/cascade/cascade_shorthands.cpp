// SPDX-License-Identifier: Apache-2.0
// The cascade's shorthand forms of its modifiers (cascade_pvt.h).
#include "cascade_pvt.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace texsyn::detail {

namespace {

bool starts_number(const std::string& v)
{
    return !v.empty()
        && (std::isdigit(static_cast<unsigned char>(v[0])) || v[0] == '-' || v[0] == '.'
            || v[0] == '+');
}

} // namespace

std::string cascade_shorthands(const std::string& modifiers)
{
    std::vector<std::string> pieces;
    std::string piece;
    for (char c : modifiers + ":") {
        if (c != ':') {
            piece += c;
            continue;
        }
        if (!piece.empty())
            pieces.push_back(piece);
        piece.clear();
    }
    bool has_ksize = false;
    for (const std::string& p : pieces)
        has_ksize = has_ksize || p.rfind("ksize=", 0) == 0;
    std::string out, previous;
    for (const std::string& p : pieces) {
        std::string rewritten = p;
        const size_t eq = p.find('=');
        const std::string key = p.substr(0, eq),
                          value = eq == std::string::npos ? "" : p.substr(eq + 1);
        if (eq == std::string::npos && previous.rfind("map=", 0) == 0 && previous.size() >= 5
            && previous.compare(previous.size() - 5, 5, "curve") == 0) {
            rewritten = "curve=" + p;
        } else if (key == "kernel" && starts_number(value)) {
            const size_t n = size_t(std::count(value.begin(), value.end(), ',')) + 1;
            const int side = int(std::lround(std::sqrt(double(n))));
            rewritten = "kernel=custom:weights=" + value;
            if (!has_ksize && size_t(side * side) == n)
                rewritten += ":ksize=" + std::to_string(side);
        } else if (key == "ramp") {
            const std::string ext = std::filesystem::path(value).extension().string();
            if (ext.size() > 1 && std::all_of(ext.begin() + 1, ext.end(), [](char c) {
                    return std::isalpha(static_cast<unsigned char>(c));
                }))
                rewritten = "palette=" + value;
        }
        out += (out.empty() ? "" : ":") + rewritten;
        previous = p;
    }
    return out;
}

} // namespace texsyn::detail
