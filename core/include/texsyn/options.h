// SPDX-License-Identifier: Apache-2.0
// Option tables: each method's options are declared once (name, member, range, help) and
// that one declaration drives CLI `:name=value` parsing, --help, recipes, the
// synth:options metadata and the generated docs (STYLE.md "Options are declared once").
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace texsyn {

/// Parses a decimal integer in [lo, hi]; false (with a message naming `name`, the value
/// and the range) otherwise.
bool parse_int_option(std::string_view name, std::string_view text, int64_t lo, int64_t hi,
    int64_t& value, std::string& error);
/// Parses "WxH" with 1 <= W, H <= hi.
bool parse_size_option(std::string_view name, std::string_view text, int hi, int& width,
    int& height, std::string& error);

/// Parses "WxHxD" with 1 <= W, H, D <= hi.
bool parse_size3_option(std::string_view name, std::string_view text, int hi, int& width,
    int& height, int& depth, std::string& error);

/// Parses "a,b,c": 1..max_count decimal numbers, each in [lo, hi].
bool parse_number_list_option(std::string_view name, std::string_view text, float lo, float hi,
    size_t max_count, std::vector<float>& values, std::string& error);
/// "a,b,c" with the shortest text that reads back as the same floats.
std::string format_number_list(const std::vector<float>& values);

/// Parses "a,b,c": 1..max_count decimal integers, each in [lo, hi].
bool parse_int_list_option(std::string_view name, std::string_view text, int lo, int hi,
    size_t max_count, std::vector<int>& values, std::string& error);
/// "a,b,c".
std::string format_int_list(const std::vector<int>& values);

/// False with "size=WxH is out of range (each side 1..max_side)" unless width and height
/// are both 0 (the default: the sample's size) or each in 1..max_side.
bool check_size_range(int width, int height, int max_side, std::string& error);

/// False with "<name>=<value> is out of range (lo..hi)" unless lo <= value <= hi.
bool check_int_range(std::string_view name, int value, int lo, int hi, std::string& error);

/// False with "<name>=a,b,c has 3 values for levels=2 (give 1..2)" unless `values` holds
/// 1..levels values (a per-level list, finest first).
bool check_level_list(
    std::string_view name, const std::vector<int>& values, int levels, std::string& error);

/// Splits "name=value:name=value" into pairs. False (message names the malformed piece)
/// if a piece has no '=' or an empty name.
bool split_option_string(std::string_view text,
    std::vector<std::pair<std::string, std::string>>& pairs, std::string& error);

/// The kind of value an option takes: how a recipe's JSON may write it (docs/recipes.md).
enum class OptionType {
    Integer,  ///< "3" or 3 (an optional integer also "none")
    Real,     ///< "0.5" or 0.5
    Size,     ///< "WxH" (or "WxHxD") or [w, h] (or [w, h, d])
    Integers, ///< "9,7,5", 9 or [9, 7, 5]
    Numbers,  ///< "1,1.5", 1.5 or [1, 1.5]
    Choice,   ///< one of the names in `allowed`
};

/// One option of an options struct T.
template <class T>
struct OptionField {
    std::string name;
    std::string help;
    std::string allowed; ///< human-readable range or choices, e.g. "1..8" or "exact|bins256"
    OptionType type;
    std::function<bool(T&, std::string_view, std::string&)> parse;
    std::function<std::string(const T&)> format;
};

/// The option table of an options struct T.
template <class T>
class OptionTable {
public:
    /// An int member in [lo, hi].
    OptionTable& integer(const char* name, int T::*member, int lo, int hi, const char* help)
    {
        std::string nm = name;
        m_fields.push_back(
            { nm, help, std::to_string(lo) + ".." + std::to_string(hi), OptionType::Integer,
                [=](T& t, std::string_view v, std::string& err) {
                    int64_t x = 0;
                    if (!parse_int_option(nm, v, lo, hi, x, err))
                        return false;
                    t.*member = int(x);
                    return true;
                },
                [=](const T& t) { return std::to_string(t.*member); } });
        return *this;
    }
    /// Two int members written as "WxH", each in [1, hi]; "0x0" is accepted only when
    /// `zero_means` is not empty (it is then described by it).
    OptionTable& size(
        const char* name, int T::*w, int T::*h, int hi, const char* zero_means, const char* help)
    {
        std::string nm = name;
        std::string zero = zero_means;
        m_fields.push_back({ nm, help, "WxH, 1.." + std::to_string(hi), OptionType::Size,
            [=](T& t, std::string_view v, std::string& err) {
                if (!zero.empty() && v == "0x0") {
                    t.*w = t.*h = 0;
                    return true;
                }
                return parse_size_option(nm, v, hi, t.*w, t.*h, err);
            },
            [=](const T& t) { return std::to_string(t.*w) + "x" + std::to_string(t.*h); } });
        return *this;
    }
    /// Three int members written as "WxHxD", each in [1, hi]; "0x0x0" is accepted only
    /// when `zero_means` is not empty (it is then described by it).
    OptionTable& size3(const char* name, int T::*w, int T::*h, int T::*d, int hi,
        const char* zero_means, const char* help)
    {
        std::string nm = name;
        std::string zero = zero_means;
        m_fields.push_back({ nm, help, "WxHxD, 1.." + std::to_string(hi), OptionType::Size,
            [=](T& t, std::string_view v, std::string& err) {
                if (!zero.empty() && v == "0x0x0") {
                    t.*w = t.*h = t.*d = 0;
                    return true;
                }
                return parse_size3_option(nm, v, hi, t.*w, t.*h, t.*d, err);
            },
            [=](const T& t) {
                return std::to_string(t.*w) + "x" + std::to_string(t.*h) + "x"
                    + std::to_string(t.*d);
            } });
        return *this;
    }
    /// An optional int member in [lo, hi]; unset is written (and read) as "none".
    OptionTable& optional_integer(
        const char* name, std::optional<int> T::*member, int lo, int hi, const char* help)
    {
        std::string nm = name;
        m_fields.push_back({ nm, help, std::to_string(lo) + ".." + std::to_string(hi) + "|none",
            OptionType::Integer,
            [=](T& t, std::string_view v, std::string& err) {
                if (v == "none") {
                    (t.*member).reset();
                    return true;
                }
                int64_t x = 0;
                if (!parse_int_option(nm, v, lo, hi, x, err))
                    return false;
                t.*member = int(x);
                return true;
            },
            [=](const T& t) {
                return (t.*member) ? std::to_string(*(t.*member)) : std::string("none");
            } });
        return *this;
    }
    /// A list of up to `max_count` numbers in [lo, hi], written "a,b,c"; an empty list
    /// (the default) is written and read as `empty_text`, which must mean the same as an
    /// empty list wherever it would also parse as numbers.
    OptionTable& numbers(const char* name, std::vector<float> T::*member, float lo, float hi,
        size_t max_count, const char* empty_text, const char* help)
    {
        std::string nm = name;
        std::string empty = empty_text;
        m_fields.push_back({ nm, help,
            "up to " + std::to_string(max_count) + " numbers " + format_number_list({ lo }) + ".."
                + format_number_list({ hi }) + ", comma-separated",
            OptionType::Numbers,
            [=](T& t, std::string_view v, std::string& err) {
                if (v == empty) {
                    (t.*member).clear();
                    return true;
                }
                return parse_number_list_option(nm, v, lo, hi, max_count, t.*member, err);
            },
            [=](const T& t) {
                return (t.*member).empty() ? empty : format_number_list(t.*member);
            } });
        return *this;
    }
    /// A float member in [lo, hi].
    OptionTable& real(const char* name, float T::*member, float lo, float hi, const char* help)
    {
        std::string nm = name;
        m_fields.push_back({ nm, help,
            format_number_list({ lo }) + ".." + format_number_list({ hi }), OptionType::Real,
            [=](T& t, std::string_view v, std::string& err) {
                std::vector<float> x;
                if (!parse_number_list_option(nm, v, lo, hi, 1, x, err))
                    return false;
                t.*member = x[0];
                return true;
            },
            [=](const T& t) { return format_number_list({ t.*member }); } });
        return *this;
    }
    /// A named set of other options' values: `presets` maps each name to a
    /// "name=value:…" text applied through T::table() when the option is read (later
    /// options override it). It is written "none": its effect is in the other options.
    OptionTable& preset(const char* name, std::vector<std::pair<std::string, std::string>> presets,
        const char* help)
    {
        std::string allowed;
        for (const auto& p : presets)
            allowed += (allowed.empty() ? "" : "|") + p.first;
        std::string nm = name;
        m_fields.push_back({ nm, help, allowed, OptionType::Choice,
            [=](T& t, std::string_view v, std::string& err) {
                if (v == "none")
                    return true;
                for (const auto& p : presets)
                    if (p.first == v)
                        return apply_option_text(t, p.second, err);
                err = nm + "=" + std::string(v) + " is not one of " + allowed;
                return false;
            },
            [](const T&) { return std::string("none"); } });
        return *this;
    }

    /// A non-empty list of up to `max_count` integers in [lo, hi], written "a,b,c".
    OptionTable& integers(const char* name, std::vector<int> T::*member, int lo, int hi,
        size_t max_count, const char* help)
    {
        std::string nm = name;
        m_fields.push_back({ nm, help,
            "up to " + std::to_string(max_count) + " integers " + std::to_string(lo) + ".."
                + std::to_string(hi) + ", comma-separated",
            OptionType::Integers,
            [=](T& t, std::string_view v, std::string& err) {
                return parse_int_list_option(nm, v, lo, hi, max_count, t.*member, err);
            },
            [=](const T& t) { return format_int_list(t.*member); } });
        return *this;
    }
    /// A non-empty list of up to `max_count` enum values chosen by name, written "a,b,c".
    template <class E>
    OptionTable& choices(const char* name, std::vector<E> T::*member,
        std::vector<std::pair<std::string, E>> values, size_t max_count, const char* help)
    {
        std::string nm = name;
        std::string allowed;
        for (auto& v : values)
            allowed += (allowed.empty() ? "" : "|") + v.first;
        m_fields.push_back({ nm, help,
            "up to " + std::to_string(max_count) + " of " + allowed + ", comma-separated",
            OptionType::Choice,
            [=](T& t, std::string_view v, std::string& err) {
                std::vector<E> list;
                while (true) {
                    const size_t comma = v.find(',');
                    const std::string_view item = v.substr(0, comma);
                    bool found = false;
                    for (auto& c : values)
                        if (c.first == item) {
                            list.push_back(c.second);
                            found = true;
                        }
                    if (!found) {
                        err = nm + "=" + std::string(item) + " is not one of " + allowed;
                        return false;
                    }
                    if (comma == std::string_view::npos)
                        break;
                    v.remove_prefix(comma + 1);
                }
                if (list.size() > max_count) {
                    err = nm + " has " + std::to_string(list.size()) + " values (at most "
                        + std::to_string(max_count) + ")";
                    return false;
                }
                t.*member = std::move(list);
                return true;
            },
            [=](const T& t) {
                std::string text;
                for (const E& e : t.*member)
                    for (auto& c : values)
                        if (c.second == e)
                            text += (text.empty() ? "" : ",") + c.first;
                return text;
            } });
        return *this;
    }
    /// An enum member chosen by name.
    template <class E>
    OptionTable& choice(const char* name, E T::*member,
        std::vector<std::pair<std::string, E>> values, const char* help)
    {
        std::string nm = name;
        std::string allowed;
        for (auto& v : values)
            allowed += (allowed.empty() ? "" : "|") + v.first;
        m_fields.push_back({ nm, help, allowed, OptionType::Choice,
            [=](T& t, std::string_view v, std::string& err) {
                for (auto& c : values)
                    if (c.first == v) {
                        t.*member = c.second;
                        return true;
                    }
                err = nm + "=" + std::string(v) + " is not one of " + allowed;
                return false;
            },
            [=](const T& t) {
                for (auto& c : values)
                    if (c.second == t.*member)
                        return c.first;
                return std::string("?");
            } });
        return *this;
    }

    /// Every field of `other`, acting on the member `member` (options one method shares
    /// with another, declared once). `help` replaces the help text of the named fields.
    template <class U>
    OptionTable& include(U T::*member, const OptionTable<U>& other,
        const std::vector<std::pair<std::string, std::string>>& help = {})
    {
        for (const OptionField<U>& f : other.fields()) {
            std::string text = f.help;
            for (auto& h : help)
                if (h.first == f.name)
                    text = h.second;
            m_fields.push_back({ f.name, text, f.allowed, f.type,
                [member, parse = f.parse](T& t, std::string_view v, std::string& err) {
                    return parse(t.*member, v, err);
                },
                [member, format = f.format](const T& t) { return format(t.*member); } });
        }
        return *this;
    }

    const std::vector<OptionField<T>>& fields() const { return m_fields; }

    /// The option called `name`, or null.
    /// Applies "name=value:…" (`text`) to `opts` through T::table(); false with a message.
    static bool apply_option_text(T& opts, std::string_view text, std::string& error)
    {
        std::vector<std::pair<std::string, std::string>> pairs;
        if (!split_option_string(text, pairs, error))
            return false;
        for (const auto& [n, v] : pairs)
            if (!T::table().set(opts, n, v, error))
                return false;
        return true;
    }

    const OptionField<T>* find(std::string_view name) const
    {
        for (auto& f : m_fields)
            if (f.name == name)
                return &f;
        return nullptr;
    }

    /// Sets option `name` from `value`; false with a message for an unknown name or a
    /// bad value. The struct is unchanged on failure.
    bool set(T& opts, std::string_view name, std::string_view value, std::string& error) const
    {
        const OptionField<T>* f = find(name);
        if (!f) {
            error = "unknown option '" + std::string(name) + "' (known: " + names() + ")";
            return false;
        }
        T copy = opts;
        if (!f->parse(copy, value, error))
            return false;
        opts = std::move(copy);
        return true;
    }

    /// "name=value:name=value…" with every option, in table order (synth:options).
    std::string format(const T& opts) const
    {
        std::string s;
        for (auto& f : m_fields)
            s += (s.empty() ? "" : ":") + f.name + "=" + f.format(opts);
        return s;
    }

    /// "a, b, c": the option names.
    std::string names() const
    {
        std::string s;
        for (auto& f : m_fields)
            s += (s.empty() ? "" : ", ") + f.name;
        return s;
    }

private:
    std::vector<OptionField<T>> m_fields;
};

} // namespace texsyn
