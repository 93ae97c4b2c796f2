// SPDX-License-Identifier: Apache-2.0
#include <texsyn/methods.h>

#include <texsyn/error_text.h>

namespace texsyn {

MethodOptions::MethodOptions(const MethodOptions& other)
    : m_holder(other.m_holder ? other.m_holder->clone() : nullptr)
{ }

MethodOptions& MethodOptions::operator=(const MethodOptions& other)
{
    if (this != &other)
        m_holder = other.m_holder ? other.m_holder->clone() : nullptr;
    return *this;
}

MethodOptions::~MethodOptions() = default;

const OptionList& MethodOptions::table() const
{
    static const OptionList none;
    return m_holder ? m_holder->table() : none;
}

bool MethodOptions::set(std::string_view name, std::string_view value, std::string& error)
{
    if (!m_holder) {
        error = option_error(name, value, "unknown option (there are none)");
        return false;
    }
    return m_holder->table().set(m_holder->data(), name, value, error);
}

bool MethodOptions::apply(std::string_view text, std::string& error)
{
    bool ok;
    if (!m_holder) {
        std::vector<std::pair<std::string, std::string>> pairs;
        ok = split_option_string(text, pairs, error)
            && (pairs.empty() || set(pairs[0].first, pairs[0].second, error));
    } else {
        ok = m_holder->table().apply(m_holder->data(), text, error);
    }
    if (!ok)
        error = printable_text(error);
    return ok;
}

std::string MethodOptions::value(std::string_view name) const
{
    const OptionField* f = m_holder ? m_holder->table().find(name) : nullptr;
    return f ? f->format(m_holder->data()) : std::string();
}

std::string MethodOptions::format() const
{
    return m_holder ? m_holder->table().format(m_holder->data()) : std::string();
}

bool MethodOptions::validate(std::string& error) const
{
    if (!m_holder || m_holder->validate(error))
        return true;
    error = printable_text(error);
    return false;
}

} // namespace texsyn
