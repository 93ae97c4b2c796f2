// SPDX-License-Identifier: Apache-2.0
#include <texsyn/error_text.h>

#include <algorithm>

namespace texsyn {

namespace {

/// Length of the valid UTF-8 sequence starting at text[i] (2-4 bytes, no overlong forms,
/// surrogates or values past U+10FFFF), or 0 if there is none.
size_t utf8_sequence_length(std::string_view text, size_t i)
{
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    size_t n = 0;
    unsigned char lo = 0x80, hi = 0xbf; // the range of the second byte
    if (lead >= 0xc2 && lead <= 0xdf) {
        n = 2;
    } else if (lead >= 0xe0 && lead <= 0xef) {
        n = 3;
        lo = lead == 0xe0 ? 0xa0 : 0x80;
        hi = lead == 0xed ? 0x9f : 0xbf;
    } else if (lead >= 0xf0 && lead <= 0xf4) {
        n = 4;
        lo = lead == 0xf0 ? 0x90 : 0x80;
        hi = lead == 0xf4 ? 0x8f : 0xbf;
    } else {
        return 0;
    }
    if (i + n > text.size() || byte(i + 1) < lo || byte(i + 1) > hi)
        return 0;
    for (size_t k = 2; k < n; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xbf)
            return 0;
    return n;
}

} // namespace

std::string printable_text(std::string_view text)
{
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        const auto u = static_cast<unsigned char>(text[i]);
        if (u >= 0x20 && u < 0x7f) {
            out += text[i++];
            continue;
        }
        if (const size_t n = u >= 0x80 ? utf8_sequence_length(text, i) : 0) {
            out.append(text.substr(i, n));
            i += n;
            continue;
        }
        const char* hex = "0123456789abcdef";
        out += "\\x";
        out += hex[u >> 4];
        out += hex[u & 15];
        ++i;
    }
    return out;
}

std::string readable_message(std::string_view message)
{
    const std::string text = printable_text(message);
    std::string out;
    out.reserve(std::min<size_t>(text.size(), 1024));
    size_t i = 0;
    while (i < text.size()) {
        const size_t end = std::min(text.find(' ', i), text.size());
        size_t word = end - i;
        if (word > 120) {
            // Quotes and punctuation around the word stay, uncounted: 'aaaa...(N characters)':
            const size_t lead = std::string_view("'\"(").find(text[i]) != std::string_view::npos;
            size_t trail = 0;
            while (trail < 3
                && std::string_view("'\":,)").find(text[end - 1 - trail]) != std::string_view::npos)
                ++trail;
            out.append(text, i, lead + 60);
            out += "...(" + std::to_string(word - lead - trail) + " characters)";
            out.append(text, end - trail, trail);
        } else {
            out.append(text, i, word);
        }
        if (end < text.size())
            out += ' ';
        i = end + 1;
    }
    return out;
}

} // namespace texsyn
