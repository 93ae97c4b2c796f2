// SPDX-License-Identifier: Apache-2.0
// Option tables: each method's options are declared once — name, member, range, help — and
// that one declaration drives `:name=value` parsing, the range checks of validate(),
// --help, recipes and their JSON schema, the synth:options metadata and the generated docs.
//
// Rules for everything here:
//  - An option's range is written once, in its table; OptionList::check() enforces it on
//    options set in code, set() on options read from text. validate() adds only the rules
//    that involve several options.
//  - Every message has one shape: "<name>=<value> : <what is wrong>", the value as the user
//    typed it (or, for a value set in code, in its shortest exact form), e.g.
//    "penalty=17 : out of range 0..16", "n=9,8 : 8 is not odd".
//  - A failed set() leaves the options unchanged.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// The kind of value an option takes: how text and a recipe's JSON may write it
/// (docs/recipes.md), and how front ends present it.
enum class OptionType {
    Integer,    ///< "3" or 3 (an optional integer also "none")
    Real,       ///< "0.5" or 0.5
    Size,       ///< "WxH" (or "WxHxD") or [w, h] (or [w, h, d])
    Integers,   ///< "9,7,5", 9 or [9, 7, 5]
    Numbers,    ///< "1,1.5", 1.5 or [1, 1.5]
    Choice,     ///< one of `choices` ("a|b" in `allowed`)
    Choices,    ///< a list of `choices`, "a,b"
    InputFile,  ///< a file the method reads besides its inputs (see OptionField::file)
    OutputFile, ///< a file the method writes besides its result (see OptionField::file)
};

/// How a file option's file is used.
enum class FileUse {
    None,      ///< not a file option
    ReadImage, ///< an image read like an input: converted to scene-linear
    ReadData,  ///< an image read as its numbers, with no colour conversion (control images)
    ReadMesh,  ///< a triangle mesh (OBJ or PLY) the method reads itself
    Write,     ///< an image the method writes (e.g. a source map)
};

/// One option of an options struct: its description, and how to read, write and check
/// it in a struct reached through a `void*` (OptionTable<T> keeps the types straight).
struct OptionField {
    std::string name;
    std::string help;
    std::string allowed; ///< human-readable range or choices, e.g. "0..16" or "exact|bins256"
    OptionType type = OptionType::Integer;
    double lo = 0.0, hi = 0.0;        ///< the range of each number (sizes: of each side)
    bool odd = false;                 ///< integers must be odd
    size_t max_count = 1;             ///< lists: at most this many values; sizes: 2 or 3 sides
    std::vector<std::string> choices; ///< Choice, Choices
    std::string none; ///< the text meaning "unset" or "empty" ("none"), or "" if none is
    /// A named set of other options' values (OptionTable::preset): where options have no
    /// order (a recipe's JSON), it is applied before them so that they override it.
    bool preset = false;
    /// The same option, with the same meaning, in every table that has it (the options
    /// several methods share): what a recipe that changes its method carries over.
    bool shared = false;
    FileUse file = FileUse::None;
    std::string extension; ///< OutputFile: the file name must end in it (".exr"), or ""

    /// Parses `text` into the struct (syntax and range); false with a message.
    std::function<bool(void*, std::string_view, std::string&)> parse;
    /// The value in the struct as text (what parse() reads back to the same value).
    std::function<std::string(const void*)> format;
    /// Checks the value in the struct against the range; false with a message.
    std::function<bool(const void*, std::string&)> check;
};

/// The options of one options struct, untyped: what front ends and docs iterate.
class OptionList {
public:
    const std::vector<OptionField>& fields() const { return m_fields; }
    /// The option called `name`, or null.
    const OptionField* find(std::string_view name) const;
    /// "a, b, c": the option names.
    std::string names() const;

    /// Sets option `name` of `opts` from `value`; false with a message for an unknown name
    /// or a bad value, `opts` unchanged.
    bool set(void* opts, std::string_view name, std::string_view value, std::string& error) const;
    /// Applies "name=value:name=value" (each name at most once); false with a message,
    /// `opts` then holds the options before the failing one.
    bool apply(void* opts, std::string_view text, std::string& error) const;
    /// "name=value:…" with every option but the file options, in table order
    /// (synth:options).
    std::string format(const void* opts) const;
    /// Checks every option's value against its range; false with the first message.
    bool check(const void* opts, std::string& error) const;

protected:
    std::vector<OptionField> m_fields;
};

namespace detail {

/// How a field reaches its member from the struct's address.
template <class V>
using MemberAccess = std::function<V*(const void*)>;

// Field makers (option_parsing.cpp): the description and the text <-> value logic, written
// once for every table.
OptionField integer_field(
    std::string name, int lo, int hi, bool odd, std::string help, MemberAccess<int> member);
OptionField optional_integer_field(std::string name, int lo, int hi, std::string help,
    MemberAccess<std::optional<int>> member, std::string unset);
OptionField real_field(
    std::string name, float lo, float hi, std::string help, MemberAccess<float> member);
OptionField size_field(std::string name, int hi, std::string zero_means, std::string help,
    std::vector<MemberAccess<int>> sides);
OptionField integers_field(std::string name, int lo, int hi, bool odd, size_t max_count,
    std::string empty_text, std::string help, MemberAccess<std::vector<int>> member);
OptionField numbers_field(std::string name, float lo, float hi, size_t max_count,
    std::string empty_text, std::string help, MemberAccess<std::vector<float>> member);
OptionField choice_field(std::string name, std::vector<std::string> names, std::string help,
    std::function<size_t(const void*)> get, std::function<void(void*, size_t)> set);
OptionField choices_field(std::string name, std::vector<std::string> names, size_t max_count,
    std::string help, std::function<std::vector<size_t>(const void*)> get,
    std::function<void(void*, std::vector<size_t>)> set);
OptionField preset_field(std::string name, std::vector<std::pair<std::string, std::string>> presets,
    std::string help, std::function<bool(void*, std::string_view, std::string&)> apply);
OptionField file_field(std::string name, FileUse use, std::string extension, std::string help,
    MemberAccess<std::string> member);
/// `field` acting on the struct at `member(outer)` (options shared by two structs).
OptionField nested_field(
    const OptionField& field, std::function<void*(const void*)> member, std::string help);

} // namespace detail

/// The option table of an options struct T. Built once (a function-local static), then
/// immutable; thread safe to read.
template <class T>
class OptionTable : public OptionList {
public:
    /// An int member in [lo, hi] (odd values only if `odd`).
    OptionTable& integer(const char* name, int T::*m, int lo, int hi, const char* help)
    {
        return add(detail::integer_field(name, lo, hi, false, help, access(m)));
    }
    OptionTable& odd_integer(const char* name, int T::*m, int lo, int hi, const char* help)
    {
        return add(detail::integer_field(name, lo, hi, true, help, access(m)));
    }
    /// An optional int member in [lo, hi]; unset is written (and read) as `unset` ("none",
    /// or e.g. "auto" where the method then chooses).
    OptionTable& optional_integer(const char* name, std::optional<int> T::*m, int lo, int hi,
        const char* help, const char* unset = "none")
    {
        return add(detail::optional_integer_field(name, lo, hi, help, access(m), unset));
    }
    /// A float member in [lo, hi].
    OptionTable& real(const char* name, float T::*m, float lo, float hi, const char* help)
    {
        return add(detail::real_field(name, lo, hi, help, access(m)));
    }
    /// Two int members written "WxH", each in [1, hi]; "0x0" is accepted only when
    /// `zero_means` is not empty (it is then described by it).
    OptionTable& size(
        const char* name, int T::*w, int T::*h, int hi, const char* zero_means, const char* help)
    {
        return add(detail::size_field(name, hi, zero_means, help, { access(w), access(h) }));
    }
    /// Three int members written "WxHxD", likewise.
    OptionTable& size3(const char* name, int T::*w, int T::*h, int T::*d, int hi,
        const char* zero_means, const char* help)
    {
        return add(
            detail::size_field(name, hi, zero_means, help, { access(w), access(h), access(d) }));
    }
    /// A list of up to `max_count` integers in [lo, hi], written "a,b,c": non-empty, or
    /// empty written and read as `empty_text` if that is given ("auto": the method
    /// chooses).
    OptionTable& integers(const char* name, std::vector<int> T::*m, int lo, int hi,
        size_t max_count, const char* help, const char* empty_text = "")
    {
        return add(
            detail::integers_field(name, lo, hi, false, max_count, empty_text, help, access(m)));
    }
    OptionTable& odd_integers(const char* name, std::vector<int> T::*m, int lo, int hi,
        size_t max_count, const char* help, const char* empty_text = "")
    {
        return add(
            detail::integers_field(name, lo, hi, true, max_count, empty_text, help, access(m)));
    }
    /// A list of up to `max_count` numbers in [lo, hi], written "a,b,c"; an empty list is
    /// written and read as `empty_text`.
    OptionTable& numbers(const char* name, std::vector<float> T::*m, float lo, float hi,
        size_t max_count, const char* empty_text, const char* help)
    {
        return add(detail::numbers_field(name, lo, hi, max_count, empty_text, help, access(m)));
    }
    /// An enum member chosen by name.
    template <class E>
    OptionTable& choice(
        const char* name, E T::*m, std::vector<std::pair<std::string, E>> values, const char* help)
    {
        return add(detail::choice_field(
            name, names_of(values), help,
            [m, values](const void* t) {
                for (size_t i = 0; i < values.size(); ++i)
                    if (values[i].second == static_cast<const T*>(t)->*m)
                        return i;
                return size_t(0);
            },
            [m, values](void* t, size_t i) { static_cast<T*>(t)->*m = values[i].second; }));
    }
    /// A non-empty list of up to `max_count` enum values chosen by name, written "a,b,c".
    template <class E>
    OptionTable& choices(const char* name, std::vector<E> T::*m,
        std::vector<std::pair<std::string, E>> values, size_t max_count, const char* help)
    {
        return add(detail::choices_field(
            name, names_of(values), max_count, help,
            [m, values](const void* t) {
                std::vector<size_t> list;
                for (const E& e : static_cast<const T*>(t)->*m)
                    for (size_t i = 0; i < values.size(); ++i)
                        if (values[i].second == e)
                            list.push_back(i);
                return list;
            },
            [m, values](void* t, std::vector<size_t> list) {
                std::vector<E>& out = static_cast<T*>(t)->*m;
                out.clear();
                for (size_t i : list)
                    out.push_back(values[i].second);
            }));
    }
    /// A named set of other options' values: each preset is a "name=value:…" text applied
    /// through T::table() where the option is read (later options override it). Written
    /// "none": its effect is in the other options.
    OptionTable& preset(const char* name, std::vector<std::pair<std::string, std::string>> presets,
        const char* help)
    {
        return add(detail::preset_field(
            name, std::move(presets), help, [](void* t, std::string_view text, std::string& error) {
                return T::table().apply(t, text, error);
            }));
    }
    /// A file the method reads (`use` ReadImage, ReadData or ReadMesh) or writes (Write; its name
    /// must end in `extension` if that is not empty); "" = none.
    OptionTable& file(
        const char* name, std::string T::*m, FileUse use, const char* extension, const char* help)
    {
        return add(detail::file_field(name, use, extension, help, access(m)));
    }
    /// Every field of `other`, acting on the member `member` (options one struct shares
    /// with another, declared once). `help` replaces the help text of the named fields.
    template <class U>
    OptionTable& include(U T::*member, const OptionTable<U>& other,
        const std::vector<std::pair<std::string, std::string>>& help = {})
    {
        for (const OptionField& f : other.fields()) {
            std::string text = f.help;
            for (const auto& h : help)
                if (h.first == f.name)
                    text = h.second;
            add(detail::nested_field(
                f,
                [member](const void* t) -> void* {
                    return &(const_cast<T*>(static_cast<const T*>(t))->*member);
                },
                text));
        }
        return *this;
    }
    /// Marks the field added last as shared (OptionField::shared).
    OptionTable& shared()
    {
        m_fields.back().shared = true;
        return *this;
    }
    /// The fields of `other` (a table of the same struct) named in `names`, in its order.
    OptionTable& subset(const OptionTable& other, const std::vector<std::string>& names)
    {
        for (const OptionField& f : other.fields())
            for (const std::string& n : names)
                if (f.name == n)
                    add(f);
        return *this;
    }

    using OptionList::apply;
    using OptionList::check;
    using OptionList::format;
    using OptionList::set;
    bool set(T& opts, std::string_view name, std::string_view value, std::string& error) const
    {
        return OptionList::set(&opts, name, value, error);
    }
    bool apply(T& opts, std::string_view text, std::string& error) const
    {
        return OptionList::apply(&opts, text, error);
    }
    std::string format(const T& opts) const { return OptionList::format(&opts); }
    bool check(const T& opts, std::string& error) const { return OptionList::check(&opts, error); }

private:
    OptionTable& add(OptionField f)
    {
        m_fields.push_back(std::move(f));
        return *this;
    }
    template <class V>
    static detail::MemberAccess<V> access(V T::*m)
    {
        return [m](const void* t) { return &(const_cast<T*>(static_cast<const T*>(t))->*m); };
    }
    template <class E>
    static std::vector<std::string> names_of(const std::vector<std::pair<std::string, E>>& values)
    {
        std::vector<std::string> names;
        for (const auto& v : values)
            names.push_back(v.first);
        return names;
    }
};

/// The table of T that `declare` (a lambda adding T's fields) fills, built once on first
/// use: what an options struct's static table() returns. Each lambda is its own table.
template <class T, class Declare>
const OptionTable<T>& declared_table(Declare declare)
{
    static const OptionTable<T> table = [&] {
        OptionTable<T> t;
        declare(t);
        return t;
    }();
    return table;
}

/// The value of a per-level list option at `level`: levels the list does not reach repeat
/// its last value; `fallback` for an empty list.
template <class V>
V at_level(const std::vector<V>& list, int level, V fallback)
{
    return list.empty() ? fallback
                        : list[size_t(level < int(list.size()) ? level : int(list.size()) - 1)];
}

/// "<name>=<shown> : <reason>": the one shape of every option message.
std::string option_error(std::string_view name, std::string_view shown, std::string_view reason);

/// Parses a decimal integer in [lo, hi]; false with option_error(name, text, …) otherwise.
bool parse_int_option(std::string_view name, std::string_view text, int64_t lo, int64_t hi,
    int64_t& value, std::string& error);

/// "a,b,c" with the shortest text that reads back as the same floats.
std::string format_number_list(const std::vector<float>& values);
/// "a,b,c".
std::string format_int_list(const std::vector<int>& values);

/// Splits "name=value:name=value" into pairs. False (message names the malformed piece)
/// if a piece has no '=' or an empty name.
bool split_option_string(std::string_view text,
    std::vector<std::pair<std::string, std::string>>& pairs, std::string& error);

/// False with "<name>=a,b,c : 3 values for levels=2 (give 1..2)" unless `count` is
/// 1..levels (a per-level list); `shown` is the list as text.
bool check_level_list(
    std::string_view name, std::string_view shown, size_t count, int levels, std::string& error);

} // namespace texsyn
#pragma GCC visibility pop
