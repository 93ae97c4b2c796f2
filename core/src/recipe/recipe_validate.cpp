// SPDX-License-Identifier: Apache-2.0
// Whether a recipe can run: its method, options, samples and colour spaces agree.
#include <texsyn/recipe.h>

#include <texsyn/error_text.h>
#include <texsyn/io.h>
#include <texsyn/stats.h>

namespace texsyn {

namespace {

// How many samples the recipe's method takes, as text for messages ("1", "0 or 1", …).
std::string sample_count_text(const Method& m, const MethodOptions& options)
{
    if (m.inputs == MethodInputs::OptionalImage)
        return "0 or 1";
    return std::to_string(m.input_count(options, 0));
}

} // namespace

bool Recipe::validate(std::string& error) const
{
    const Method* m = row();
    if (!m || !m->makes_recipes()) {
        error = option_error("method", printable_text(method), "not one of " + method_names());
        return false;
    }
    const MethodOptions options = this->options ? this->options : m->defaults();
    if (!options.validate(error))
        return false;
    const int n = int(samples.size());
    const bool count_ok
        = m->inputs == MethodInputs::OptionalImage ? n <= 1 : n == m->input_count(options, n);
    if (!count_ok) {
        error = n == 0 ? "the recipe names no sample (\"sample\": \"file.png\"); method " + method
                + " takes " + sample_count_text(*m, options)
                       : "method " + method + " takes " + sample_count_text(*m, options) + " sample"
                + (m->input_count(options, n) == 1 ? "" : "s") + ", the recipe names "
                + std::to_string(n) + " (\"sample\": [\"a.png\", \"b.png\", ...])";
        return false;
    }
    for (int i = 0; i < n; ++i)
        if (is_analysis_filename(samples[size_t(i)]) && !m->accepts_analysis(i)) {
            error = option_error("sample", printable_text(samples[size_t(i)]),
                "an analysis file (.tsa) is for the pyramid methods' samples; method " + method
                    + " needs an image here");
            return false;
        }
    if (iscolorspace.size() > 1 && int(iscolorspace.size()) != n) {
        error = "iscolorspace: give one colour space for all samples or one per sample ("
            + std::to_string(n) + "), not " + std::to_string(iscolorspace.size());
        return false;
    }
    if (subbands && !m->subbands) {
        std::string with;
        for (const Method* other : methods())
            if (other->subbands)
                with += (with.empty() ? "" : ", ") + other->name;
        error = option_error(
            "subbands", "1", "method " + method + " has no subbands (only " + with + " do)");
        return false;
    }
    return true;
}

} // namespace texsyn
