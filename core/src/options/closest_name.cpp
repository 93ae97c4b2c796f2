// SPDX-License-Identifier: Apache-2.0
// "Did you mean …?": the known name nearest a misspelt one.
#include <texsyn/error_text.h>

#include <algorithm>
#include <cctype>

namespace texsyn {

namespace {

std::string lower(std::string_view text)
{
    std::string s(text);
    for (char& c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Damerau–Levenshtein distance in its optimal-string-alignment form: insertions, deletions,
// substitutions and swaps of two neighbours each cost 1 (what typing slips are).
size_t edit_distance(const std::string& a, const std::string& b)
{
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i)
        d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j)
        d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            d[i][j] = std::min({ d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost });
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

} // namespace

std::string closest_name(std::string_view word, const std::vector<std::string>& names)
{
    // A word far longer than any name is no slip of the keyboard (and would cost time).
    if (word.size() > 64)
        return "";
    const std::string w = lower(word);
    const size_t limit = std::max<size_t>(2, w.size() / 3);
    std::string best;
    size_t best_distance = limit + 1;
    for (const std::string& name : names) {
        if (name == word)
            return "";
        const size_t d = edit_distance(w, lower(name));
        if (d < best_distance) {
            best = name;
            best_distance = d;
        }
    }
    return best;
}

} // namespace texsyn
