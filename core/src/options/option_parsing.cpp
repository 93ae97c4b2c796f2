// SPDX-License-Identifier: Apache-2.0
// The option kinds: text <-> value, range checks and every option message, written once.
#include <texsyn/options.h>

#include <texsyn/error_text.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>

namespace texsyn {

std::string option_error(std::string_view name, std::string_view shown, std::string_view reason)
{
    return std::string(name) + "=" + std::string(shown) + " : " + std::string(reason);
}

namespace {

// "lo..hi" with numbers in their shortest exact form.
std::string range_text(double lo, double hi, bool integral)
{
    if (integral)
        return std::to_string(int64_t(lo)) + ".." + std::to_string(int64_t(hi));
    return format_number_list({ float(lo) }) + ".." + format_number_list({ float(hi) });
}

// A decimal integer; one too large for int64 is clamped to it (so that the range check
// calls it out of range, not "not an integer").
bool parse_integer(std::string_view text, int64_t& value)
{
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || end != text.data() + text.size())
        return false;
    if (ec == std::errc::result_out_of_range)
        value = text[0] == '-' ? INT64_MIN : INT64_MAX;
    return ec == std::errc() || ec == std::errc::result_out_of_range;
}

// A decimal integer, clamped to the range of int (no option's range reaches its ends).
bool parse_int32(std::string_view text, int& value)
{
    int64_t x = 0;
    if (!parse_integer(text, x))
        return false;
    value = int(std::clamp<int64_t>(x, INT32_MIN, INT32_MAX));
    return true;
}

// False with option_error(name, shown, why) unless `why` is empty.
bool reported(
    std::string_view name, std::string_view shown, const std::string& why, std::string& error)
{
    if (!why.empty())
        error = option_error(name, shown, why);
    return why.empty();
}

// A decimal number; one beyond float's range becomes +-inf (or 0 if too small), which the
// range check then reports.
bool parse_real(std::string_view text, float& value)
{
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || end != text.data() + text.size())
        return false;
    if (ec == std::errc::result_out_of_range)
        value = float(std::strtod(std::string(text).c_str(), nullptr));
    return ec == std::errc() || ec == std::errc::result_out_of_range;
}

// Why `v` is not allowed ("" if it is): the reason shared by single values and list items.
std::string integer_problem(int64_t v, int lo, int hi, bool odd)
{
    if (v < lo || v > hi)
        return "out of range " + range_text(lo, hi, true);
    if (odd && v % 2 == 0)
        return "not odd";
    return "";
}

std::string real_problem(float v, float lo, float hi)
{
    if (!(v >= lo && v <= hi))
        return "out of range " + range_text(lo, hi, false);
    return "";
}

std::string choice_list(const std::vector<std::string>& names)
{
    std::string s;
    for (const std::string& n : names)
        s += (s.empty() ? "" : "|") + n;
    return s;
}

// Splits "a,b,c" into its items (an empty text is one empty item).
std::vector<std::string_view> split_list(std::string_view text)
{
    std::vector<std::string_view> items;
    while (true) {
        const size_t comma = text.find(',');
        items.push_back(text.substr(0, comma));
        if (comma == std::string_view::npos)
            return items;
        text.remove_prefix(comma + 1);
    }
}

// Checks a list's length and each item (`problem(i)` is "" or why item i is not allowed).
template <class Problem>
bool check_list(const OptionField& f, std::string_view shown, size_t count,
    const std::vector<std::string>& item_text, Problem&& problem, std::string& error)
{
    if (count > f.max_count) {
        error = option_error(f.name, shown,
            std::to_string(count) + " values (at most " + std::to_string(f.max_count) + ")");
        return false;
    }
    // Items are named only in a list of several.
    for (size_t i = 0; i < count; ++i)
        if (std::string why = problem(i); !why.empty()) {
            error = option_error(f.name, shown, count == 1 ? why : item_text[i] + " is " + why);
            return false;
        }
    return true;
}

std::vector<std::string> int_texts(const std::vector<int>& v)
{
    std::vector<std::string> t;
    for (int x : v)
        t.push_back(std::to_string(x));
    return t;
}

std::vector<std::string> real_texts(const std::vector<float>& v)
{
    std::vector<std::string> t;
    for (float x : v)
        t.push_back(format_number_list({ x }));
    return t;
}

} // namespace

bool parse_int_option(std::string_view name, std::string_view text, int64_t lo, int64_t hi,
    int64_t& value, std::string& error)
{
    int64_t v = 0;
    if (!parse_integer(text, v)) {
        error = option_error(name, text, "not an integer");
        return false;
    }
    if (v < lo || v > hi) {
        error = option_error(
            name, text, "out of range " + std::to_string(lo) + ".." + std::to_string(hi));
        return false;
    }
    value = v;
    return true;
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

bool check_level_list(
    std::string_view name, std::string_view shown, size_t count, int levels, std::string& error)
{
    if (count >= 1 && int(count) <= levels)
        return true;
    error = option_error(name, shown,
        std::to_string(count) + " values for levels=" + std::to_string(levels) + " (give 1.."
            + std::to_string(levels) + ")");
    return false;
}

// ---- OptionList ----

const OptionField* OptionList::find(std::string_view name) const
{
    for (const OptionField& f : m_fields)
        if (f.name == name)
            return &f;
    return nullptr;
}

std::string OptionList::names() const
{
    std::string s;
    for (const OptionField& f : m_fields)
        s += (s.empty() ? "" : ", ") + f.name;
    return s;
}

bool OptionList::set(
    void* opts, std::string_view name, std::string_view value, std::string& error) const
{
    const OptionField* f = find(name);
    if (!f) {
        std::vector<std::string> known;
        for (const OptionField& field : m_fields)
            known.push_back(field.name);
        const std::string guess = closest_name(name, known);
        error = option_error(name, value,
            !guess.empty()
                ? "unknown option '" + std::string(name) + "' (did you mean " + guess + "?)"
                : known.empty() ? "unknown option (it takes none)"
                                : "unknown option (known: " + names() + ")");
        return false;
    }
    return f->parse(opts, value, error);
}

bool OptionList::apply(void* opts, std::string_view text, std::string& error) const
{
    std::vector<std::pair<std::string, std::string>> pairs;
    if (!split_option_string(text, pairs, error))
        return false;
    for (size_t i = 0; i < pairs.size(); ++i) {
        for (size_t j = 0; j < i; ++j)
            if (pairs[j].first == pairs[i].first) {
                error = option_error(pairs[i].first, pairs[i].second, "given twice");
                return false;
            }
        if (!set(opts, pairs[i].first, pairs[i].second, error))
            return false;
    }
    return true;
}

std::string OptionList::format(const void* opts) const
{
    std::string s;
    for (const OptionField& f : m_fields)
        if (f.file == FileUse::None)
            s += (s.empty() ? "" : ":") + f.name + "=" + f.format(opts);
    return s;
}

bool OptionList::check(const void* opts, std::string& error) const
{
    for (const OptionField& f : m_fields)
        if (!f.check(opts, error))
            return false;
    return true;
}

// ---- the kinds ----

namespace detail {

namespace {

// A field's description: what every kind sets.
OptionField described(std::string name, std::string help, OptionType type, std::string allowed,
    double lo = 0.0, double hi = 0.0)
{
    OptionField f;
    f.name = std::move(name);
    f.help = std::move(help);
    f.type = type;
    f.allowed = std::move(allowed);
    f.lo = lo;
    f.hi = hi;
    return f;
}

// A field whose value is checked by `problem(value, shown)` both when parsed and when set
// in code: parse = syntax, then the check, then the assignment.
template <class V>
void bind_member(OptionField& f, MemberAccess<V> member,
    std::function<bool(std::string_view, V&, std::string&)> syntax,
    std::function<std::string(const V&)> text,
    std::function<bool(const V&, std::string_view, std::string&)> problem)
{
    f.parse = [member, syntax, problem](void* t, std::string_view v, std::string& error) {
        V value {};
        if (!syntax(v, value, error) || !problem(value, v, error))
            return false;
        *member(t) = std::move(value);
        return true;
    };
    f.format = [member, text](const void* t) { return text(*member(t)); };
    f.check = [member, text, problem](const void* t, std::string& error) {
        return problem(*member(t), text(*member(t)), error);
    };
}

} // namespace

OptionField integer_field(
    std::string name, int lo, int hi, bool odd, std::string help, MemberAccess<int> member)
{
    OptionField f = described(name, std::move(help), OptionType::Integer,
        range_text(lo, hi, true) + (odd ? ", odd" : ""), lo, hi);
    f.odd = odd;
    bind_member<int>(
        f, std::move(member),
        [name](std::string_view v, int& out, std::string& error) {
            return parse_int32(v, out) || reported(name, v, "not an integer", error);
        },
        [](const int& v) { return std::to_string(v); },
        [name, lo, hi, odd](const int& v, std::string_view shown, std::string& error) {
            return reported(name, shown, integer_problem(v, lo, hi, odd), error);
        });
    return f;
}

OptionField optional_integer_field(std::string name, int lo, int hi, std::string help,
    MemberAccess<std::optional<int>> member, std::string unset)
{
    OptionField f = described(
        name, std::move(help), OptionType::Integer, range_text(lo, hi, true) + "|" + unset, lo, hi);
    f.none = unset;
    bind_member<std::optional<int>>(
        f, std::move(member),
        [name, unset](std::string_view v, std::optional<int>& out, std::string& error) {
            int x = 0;
            if (v == unset) {
                out.reset();
                return true;
            }
            if (!parse_int32(v, x))
                return reported(name, v, "not an integer (or " + unset + ")", error);
            out = x;
            return true;
        },
        [unset](const std::optional<int>& v) { return v ? std::to_string(*v) : unset; },
        [name, lo, hi](const std::optional<int>& v, std::string_view shown, std::string& error) {
            return reported(name, shown, v ? integer_problem(*v, lo, hi, false) : "", error);
        });
    return f;
}

OptionField real_field(
    std::string name, float lo, float hi, std::string help, MemberAccess<float> member)
{
    OptionField f
        = described(name, std::move(help), OptionType::Real, range_text(lo, hi, false), lo, hi);
    bind_member<float>(
        f, std::move(member),
        [name](std::string_view v, float& out, std::string& error) {
            if (!parse_real(v, out)) {
                error = option_error(name, v, "not a number");
                return false;
            }
            return true;
        },
        [](const float& v) { return format_number_list({ v }); },
        [name, lo, hi](const float& v, std::string_view shown, std::string& error) {
            return reported(name, shown, real_problem(v, lo, hi), error);
        });
    return f;
}

OptionField size_field(std::string name, int hi, std::string zero_means, std::string help,
    std::vector<MemberAccess<int>> sides)
{
    const size_t n = sides.size();
    OptionField f;
    f.name = name;
    f.help = std::move(help);
    f.type = OptionType::Size;
    f.allowed = std::string(n == 2 ? "WxH" : "WxHxD") + ", each 1.." + std::to_string(hi)
        + (zero_means.empty() ? ""
                : n == 2      ? " or 0x0"
                              : " or 0x0x0");
    f.lo = 1;
    f.hi = hi;
    f.max_count = n;
    const bool zero_ok = !zero_means.empty();
    const std::string example = n == 2 ? "WxH, e.g. 1024x1024" : "WxHxD, e.g. 128x128x128";
    auto problem = [name, hi, zero_ok](
                       const std::vector<int>& v, std::string_view shown, std::string& error) {
        const bool zero = std::all_of(v.begin(), v.end(), [](int x) { return x == 0; });
        if (zero && zero_ok)
            return true;
        for (int x : v)
            if (x < 1 || x > hi) {
                error = option_error(
                    name, shown, "out of range 1.." + std::to_string(hi) + " (each side)");
                return false;
            }
        return true;
    };
    auto text = [](const std::vector<int>& v) {
        std::string s;
        for (int x : v)
            s += (s.empty() ? "" : "x") + std::to_string(x);
        return s;
    };
    auto get = [sides](const void* t) {
        std::vector<int> v;
        for (const auto& side : sides)
            v.push_back(*side(t));
        return v;
    };
    f.parse = [sides, name, n, example, problem](void* t, std::string_view v, std::string& error) {
        std::vector<int> dims;
        std::string_view rest = v;
        for (size_t i = 0; i < n; ++i) {
            const size_t x = i + 1 < n ? rest.find('x') : rest.size();
            int64_t d = 0;
            if (x == std::string_view::npos || !parse_integer(rest.substr(0, x), d) || d < 0) {
                error = option_error(name, v, "not a size (expected " + example + ")");
                return false;
            }
            dims.push_back(int(std::min<int64_t>(d, INT32_MAX))); // the limits refuse it

            rest.remove_prefix(std::min(rest.size(), x + 1));
        }
        if (!problem(dims, v, error))
            return false;
        for (size_t i = 0; i < n; ++i)
            *sides[i](t) = dims[i];
        return true;
    };
    f.format = [get, text](const void* t) { return text(get(t)); };
    f.check = [get, text, problem](const void* t, std::string& error) {
        const std::vector<int> v = get(t);
        return problem(v, text(v), error);
    };
    return f;
}

OptionField integers_field(std::string name, int lo, int hi, bool odd, size_t max_count,
    std::string empty_text, std::string help, MemberAccess<std::vector<int>> member)
{
    OptionField f = described(name, std::move(help), OptionType::Integers,
        "up to " + std::to_string(max_count) + (odd ? " odd" : "") + " integers "
            + range_text(lo, hi, true) + ", comma-separated"
            + (empty_text.empty() ? "" : ", or " + empty_text),
        lo, hi);
    f.odd = odd;
    f.max_count = max_count;
    f.none = empty_text;
    const OptionField limits = f;
    bind_member<std::vector<int>>(
        f, std::move(member),
        [name, empty_text](std::string_view v, std::vector<int>& out, std::string& error) {
            if (!empty_text.empty() && v == empty_text)
                return true;
            for (std::string_view item : split_list(v)) {
                int x = 0;
                if (!parse_int32(item, x)) {
                    const bool several = v.find(',') != std::string_view::npos;
                    error = option_error(name, v,
                        (!several              ? std::string("not")
                                : item.empty() ? std::string("an empty value is not")
                                               : std::string(item) + " is not")
                            + " an integer (expected e.g. 9,7,5"
                            + (empty_text.empty() ? "" : " or " + empty_text) + ")");
                    return false;
                }
                out.push_back(x);
            }
            return true;
        },
        [empty_text](const std::vector<int>& v) {
            return v.empty() && !empty_text.empty() ? empty_text : format_int_list(v);
        },
        [limits, lo, hi, odd](
            const std::vector<int>& v, std::string_view shown, std::string& error) {
            if (v.empty()) {
                if (!limits.none.empty())
                    return true;
                error = option_error(limits.name, shown, "needs at least one value");
                return false;
            }
            return check_list(
                limits, shown, v.size(), int_texts(v),
                [&](size_t i) { return integer_problem(v[i], lo, hi, odd); }, error);
        });
    return f;
}

OptionField numbers_field(std::string name, float lo, float hi, size_t max_count,
    std::string empty_text, std::string help, MemberAccess<std::vector<float>> member)
{
    OptionField f = described(name, std::move(help), OptionType::Numbers,
        "up to " + std::to_string(max_count) + " numbers " + range_text(lo, hi, false)
            + ", comma-separated",
        lo, hi);
    f.max_count = max_count;
    f.none = empty_text;
    const OptionField limits = f;
    bind_member<std::vector<float>>(
        f, std::move(member),
        [name, empty_text](std::string_view v, std::vector<float>& out, std::string& error) {
            if (v == empty_text)
                return true;
            for (std::string_view item : split_list(v)) {
                float x = 0.0f;
                if (!parse_real(item, x)) {
                    error = option_error(name, v, "not a list of numbers (expected e.g. 1,1,1.5)");
                    return false;
                }
                out.push_back(x);
            }
            return true;
        },
        [empty_text](
            const std::vector<float>& v) { return v.empty() ? empty_text : format_number_list(v); },
        [limits, lo, hi](const std::vector<float>& v, std::string_view shown, std::string& error) {
            return check_list(
                limits, shown, v.size(), real_texts(v),
                [&](size_t i) { return real_problem(v[i], lo, hi); }, error);
        });
    return f;
}

OptionField choice_field(std::string name, std::vector<std::string> names, std::string help,
    std::function<size_t(const void*)> get, std::function<void(void*, size_t)> set)
{
    OptionField f = described(name, std::move(help), OptionType::Choice, choice_list(names));
    f.choices = names;
    f.parse = [name, names, set](void* t, std::string_view v, std::string& error) {
        for (size_t i = 0; i < names.size(); ++i)
            if (names[i] == v) {
                set(t, i);
                return true;
            }
        error = option_error(name, v, "not one of " + choice_list(names));
        return false;
    };
    f.format = [names, get](const void* t) { return names[get(t)]; };
    f.check = [](const void*, std::string&) { return true; }; // an enum is always a choice
    return f;
}

OptionField choices_field(std::string name, std::vector<std::string> names, size_t max_count,
    std::string help, std::function<std::vector<size_t>(const void*)> get,
    std::function<void(void*, std::vector<size_t>)> set)
{
    OptionField f = described(name, std::move(help), OptionType::Choices,
        "up to " + std::to_string(max_count) + " of " + choice_list(names) + ", comma-separated");
    f.choices = names;
    f.max_count = max_count;
    auto text = [names](const std::vector<size_t>& list) {
        std::string s;
        for (size_t i : list)
            s += (s.empty() ? "" : ",") + names[i];
        return s;
    };
    auto problem = [name, max_count](size_t count, std::string_view shown, std::string& error) {
        if (count >= 1 && count <= max_count)
            return true;
        error = option_error(name, shown,
            std::to_string(count) + " values (give 1.." + std::to_string(max_count) + ")");
        return false;
    };
    f.parse = [name, names, set, problem](void* t, std::string_view v, std::string& error) {
        std::vector<size_t> list;
        for (std::string_view item : split_list(v)) {
            const auto it = std::find(names.begin(), names.end(), item);
            if (it == names.end()) {
                const bool several = v.find(',') != std::string_view::npos;
                error = option_error(name, v,
                    (several ? std::string(item) + " is not" : std::string("not")) + " one of "
                        + choice_list(names));
                return false;
            }
            list.push_back(size_t(it - names.begin()));
        }
        if (!problem(list.size(), v, error))
            return false;
        set(t, std::move(list));
        return true;
    };
    f.format = [get, text](const void* t) { return text(get(t)); };
    f.check = [get, text, problem](const void* t, std::string& error) {
        const std::vector<size_t> list = get(t);
        return problem(list.size(), text(list), error);
    };
    return f;
}

OptionField preset_field(std::string name, std::vector<std::pair<std::string, std::string>> presets,
    std::string help, std::function<bool(void*, std::string_view, std::string&)> apply)
{
    std::vector<std::string> names;
    for (const auto& p : presets)
        names.push_back(p.first);
    OptionField f = described(name, std::move(help), OptionType::Choice, choice_list(names));
    f.choices = names;
    f.none = "none";
    f.preset = true;
    f.parse = [name, presets, apply, allowed = f.allowed](
                  void* t, std::string_view v, std::string& error) {
        if (v == "none")
            return true;
        for (const auto& p : presets)
            if (p.first == v)
                return apply(t, p.second, error);
        error = option_error(name, v, "not one of " + allowed);
        return false;
    };
    f.format = [](const void*) { return std::string("none"); };
    f.check = [](const void*, std::string&) { return true; };
    return f;
}

OptionField file_field(std::string name, FileUse use, std::string extension, std::string help,
    MemberAccess<std::string> member)
{
    OptionField f = described(name, std::move(help),
        use == FileUse::Write ? OptionType::OutputFile : OptionType::InputFile,
        extension.empty() ? "a file name" : "a file name *" + extension);
    f.file = use;
    f.extension = extension;
    auto problem
        = [name, extension](const std::string& v, std::string_view shown, std::string& error) {
              // "" is the field's unset value; a name must hold more than the extension.
              if (extension.empty() || v.empty()
                  || (v.size() > extension.size()
                      && std::equal(extension.rbegin(), extension.rend(), v.rbegin(),
                          [](char a, char b) { return std::tolower(a) == std::tolower(b); })))
                  return true;
              error = option_error(name, shown, "name it *" + extension);
              return false;
          };
    f.parse = [name, member, problem](void* t, std::string_view v, std::string& error) {
        if (v.empty()) {
            error = option_error(name, v, "needs a file name");
            return false;
        }
        if (!problem(std::string(v), v, error))
            return false;
        *member(t) = std::string(v);
        return true;
    };
    f.format = [member](const void* t) { return *member(t); };
    f.check = [member, problem](const void* t, std::string& error) {
        return problem(*member(t), *member(t), error);
    };
    return f;
}

OptionField nested_field(
    const OptionField& field, std::function<void*(const void*)> member, std::string help)
{
    OptionField f = field;
    f.help = std::move(help);
    f.parse = [parse = field.parse, member](void* t, std::string_view v, std::string& error) {
        return parse(member(t), v, error);
    };
    f.format = [format = field.format, member](const void* t) { return format(member(t)); };
    f.check = [check = field.check, member](
                  const void* t, std::string& error) { return check(member(t), error); };
    return f;
}

} // namespace detail

} // namespace texsyn
