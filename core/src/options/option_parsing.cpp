// SPDX-License-Identifier: Apache-2.0
#include <texsyn/options.h>

#include <algorithm>
#include <charconv>
#include <cstdint>

namespace texsyn {

bool parse_int_option(std::string_view name, std::string_view text, int64_t lo, int64_t hi,
    int64_t& value, std::string& error)
{
    int64_t v = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
        error = std::string(name) + "=" + std::string(text) + " is not an integer";
        return false;
    }
    if (v < lo || v > hi) {
        error = std::string(name) + "=" + std::string(text) + " is out of range ("
            + std::to_string(lo) + ".." + std::to_string(hi) + ")";
        return false;
    }
    value = v;
    return true;
}

namespace {

// Parses "AxBx…" with exactly `n` non-negative integers into `dims`; then checks each is in
// [1, hi]. `example` is a well-formed size for the message.
bool parse_dims(std::string_view name, std::string_view text, size_t n, int hi, const char* example,
    int64_t* dims, std::string& error)
{
    std::string_view rest = text;
    std::string ignored;
    for (size_t i = 0; i < n; ++i) {
        const size_t x = i + 1 < n ? rest.find('x') : rest.size();
        if (x == std::string_view::npos
            || !parse_int_option(name, rest.substr(0, x), 0, INT64_MAX, dims[i], ignored)) {
            error = std::string(name) + "=" + std::string(text) + " is not a size (expected "
                + example + ")";
            return false;
        }
        rest.remove_prefix(std::min(rest.size(), x + 1));
    }
    for (size_t i = 0; i < n; ++i)
        if (dims[i] < 1 || dims[i] > hi) {
            error = std::string(name) + "=" + std::string(text) + " is out of range (each side 1.."
                + std::to_string(hi) + ")";
            return false;
        }
    return true;
}

} // namespace

bool parse_size_option(std::string_view name, std::string_view text, int hi, int& width,
    int& height, std::string& error)
{
    int64_t dims[2];
    if (!parse_dims(name, text, 2, hi, "WxH, e.g. 1024x1024", dims, error))
        return false;
    width = int(dims[0]);
    height = int(dims[1]);
    return true;
}

bool parse_size3_option(std::string_view name, std::string_view text, int hi, int& width,
    int& height, int& depth, std::string& error)
{
    int64_t dims[3];
    if (!parse_dims(name, text, 3, hi, "WxHxD, e.g. 128x128x128", dims, error))
        return false;
    width = int(dims[0]);
    height = int(dims[1]);
    depth = int(dims[2]);
    return true;
}

namespace {

// Parses "a,b,c" into `values` with parse_piece(piece, value, error) for each piece, then
// checks there are at most max_count; `values` is unchanged on failure.
template <class T, class ParsePiece>
bool parse_list(std::string_view name, std::string_view text, size_t max_count,
    std::vector<T>& values, std::string& error, ParsePiece&& parse_piece)
{
    std::vector<T> v;
    std::string_view rest = text;
    while (true) {
        const size_t comma = rest.find(',');
        T x {};
        if (!parse_piece(rest.substr(0, comma), x, error))
            return false;
        v.push_back(x);
        if (comma == std::string_view::npos)
            break;
        rest.remove_prefix(comma + 1);
    }
    if (v.size() > max_count) {
        error = std::string(name) + "=" + std::string(text) + " has " + std::to_string(v.size())
            + " values (at most " + std::to_string(max_count) + ")";
        return false;
    }
    values = std::move(v);
    return true;
}

} // namespace

bool parse_number_list_option(std::string_view name, std::string_view text, float lo, float hi,
    size_t max_count, std::vector<float>& values, std::string& error)
{
    return parse_list(name, text, max_count, values, error,
        [&](std::string_view piece, float& x, std::string& err) {
            auto [end, ec] = std::from_chars(piece.data(), piece.data() + piece.size(), x);
            if (piece.empty() || ec != std::errc() || end != piece.data() + piece.size()) {
                err = std::string(name) + "=" + std::string(text)
                    + " is not a list of numbers (expected e.g. 1,1,1.5)";
                return false;
            }
            if (!(x >= lo && x <= hi)) {
                err = std::string(name) + "=" + std::string(text) + " : " + std::string(piece)
                    + " is out of range (" + format_number_list({ lo }) + ".."
                    + format_number_list({ hi }) + ")";
                return false;
            }
            return true;
        });
}

std::string format_number_list(const std::vector<float>& values)
{
    std::string s;
    for (float x : values) {
        char buf[32];
        auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), x);
        s += (s.empty() ? "" : ",") + std::string(buf, ec == std::errc() ? end : buf);
    }
    return s;
}

bool parse_int_list_option(std::string_view name, std::string_view text, int lo, int hi,
    size_t max_count, std::vector<int>& values, std::string& error)
{
    return parse_list(name, text, max_count, values, error,
        [&](std::string_view piece, int& x, std::string& err) {
            int64_t v = 0;
            if (parse_int_option(name, piece, lo, hi, v, err)) {
                x = int(v);
                return true;
            }
            const bool integer = err.find("out of range") != std::string::npos;
            err = std::string(name) + "=" + std::string(text) + " : " + std::string(piece)
                + (integer ? " is out of range (" + std::to_string(lo) + ".." + std::to_string(hi)
                            + ")"
                           : std::string(" is not an integer")
                            + (max_count > 1 ? " (expected e.g. 9,7,5)" : ""));
            return false;
        });
}

std::string format_int_list(const std::vector<int>& values)
{
    std::string s;
    for (int x : values)
        s += (s.empty() ? "" : ",") + std::to_string(x);
    return s;
}

bool split_option_string(std::string_view text,
    std::vector<std::pair<std::string, std::string>>& pairs, std::string& error)
{
    pairs.clear();
    while (!text.empty()) {
        size_t colon = text.find(':');
        std::string_view piece = text.substr(0, colon);
        size_t eq = piece.find('=');
        if (eq == std::string_view::npos || eq == 0) {
            error = "malformed option '" + std::string(piece) + "' (expected name=value)";
            return false;
        }
        pairs.emplace_back(std::string(piece.substr(0, eq)), std::string(piece.substr(eq + 1)));
        if (colon == std::string_view::npos)
            break;
        text.remove_prefix(colon + 1);
    }
    return true;
}

bool check_size_range(int width, int height, int max_side, std::string& error)
{
    if (width == 0 && height == 0)
        return true;
    if (width >= 1 && height >= 1 && width <= max_side && height <= max_side)
        return true;
    error = "size=" + std::to_string(width) + "x" + std::to_string(height)
        + " is out of range (each side 1.." + std::to_string(max_side) + ")";
    return false;
}

bool check_int_range(std::string_view name, int value, int lo, int hi, std::string& error)
{
    if (value >= lo && value <= hi)
        return true;
    error = std::string(name) + "=" + std::to_string(value) + " is out of range ("
        + std::to_string(lo) + ".." + std::to_string(hi) + ")";
    return false;
}

bool check_level_list(
    std::string_view name, const std::vector<int>& values, int levels, std::string& error)
{
    if (!values.empty() && int(values.size()) <= levels)
        return true;
    error = std::string(name) + "=" + format_int_list(values) + " has "
        + std::to_string(values.size()) + " values for levels=" + std::to_string(levels)
        + " (give 1.." + std::to_string(levels) + ")";
    return false;
}

} // namespace texsyn
