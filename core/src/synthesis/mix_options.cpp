// SPDX-License-Identifier: Apache-2.0
// MixOptions: the option table of texture mixtures and the checks that need no sample.
#include "synthesis_pvt.h"

#include <numeric>

namespace texsyn {

namespace {

// Largest number of samples a mix takes (weights=, and the range of the indices).
constexpr int kMaxSamples = 16;

std::string setting(const char* name, int value)
{
    return std::string(name) + "=" + std::to_string(value);
}

} // namespace

const OptionTable<MixOptions>& MixOptions::table()
{
    using O = MixOptions;
    static const OptionTable<O> t = [] {
        OptionTable<O> t;
        t.include(&O::synthesis, PyramidOptions::table(),
            { { "size", "output size WxH (default: the first sample's size)" },
                { "scales",
                    "pyramid scales, the same for every sample; 0 = the most that keeps the "
                    "coarsest band of every sample and of the output >= 8 px" } });
        t.optional_integer("palette", &O::palette, 0, kMaxSamples - 1,
            "the sample giving the colour: PCA colour transform, pixel and channel histograms "
            "(with pattern=, or with split= where it defaults to 0)");
        t.optional_integer("pattern", &O::pattern, 0, kMaxSamples - 1,
            "the sample giving the pattern: subband histograms, each colour component in the "
            "sample's own basis (paired with the palette's by rank)");
        t.optional_integer("split", &O::split, 1, 16,
            "two samples: scales >= split and the low-pass come from sample 0, the high-pass "
            "and scales < split from sample 1 (laplacian: levels)");
        t.numbers("weights", &O::weights, 0.0f, 1000.0f, size_t(kMaxSamples), "none",
            "one weight per sample, normalised to sum 1: every histogram is the weighted "
            "Wasserstein barycentre (average quantile function) of the samples'");
        return t;
    }();
    return t;
}

bool MixOptions::validate(std::string& error) const
{
    if (!synthesis.validate(error))
        return false;
    auto fail = [&](const std::string& message) {
        error = message;
        return false;
    };
    const std::string modes = "choose one mode: palette=I:pattern=J, split=S or weights=W0,W1,...";
    if (!weights.empty()) {
        const std::string w = "weights=" + format_number_list(weights);
        for (auto [name, value] : { std::pair { "palette", palette },
                 std::pair { "pattern", pattern }, std::pair { "split", split } })
            if (value)
                return fail(setting(name, *value) + " does not go with " + w + " (" + modes + ")");
        if (weights.size() < 2)
            return fail(w + " : a mix needs a weight for each of at least two samples");
        for (float x : weights)
            if (!(x >= 0.0f))
                return fail(w + " : each weight must be >= 0");
        if (!(std::accumulate(weights.begin(), weights.end(), 0.0) > 0.0))
            return fail(w + " : the weights must not all be 0");
        return true;
    }
    if (split && pattern)
        return fail(setting("pattern", *pattern) + " does not go with " + setting("split", *split)
            + " (" + modes + ")");
    if (pattern && !palette)
        return fail(
            setting("pattern", *pattern) + " needs palette= (the sample giving the colour)");
    if (palette && !pattern && !split)
        return fail(setting("palette", *palette) + " alone is not a mix: add pattern= or split=");
    if (!palette && !split)
        return fail("no mix mode given (" + modes + ")");
    const int n = nsamples();
    for (auto [name, value] :
        { std::pair { "palette", palette }, std::pair { "pattern", pattern } })
        if (value && (*value < 0 || *value >= n))
            return fail(setting(name, *value) + " is out of range: the mix has " + std::to_string(n)
                + " samples (0.." + std::to_string(n - 1) + ")");
    if (pattern && *pattern == *palette)
        return fail(setting("palette", *palette) + " and " + setting("pattern", *pattern)
            + " name the same sample");
    return !(split && synthesis.scales) || detail::check_split(*split, synthesis.scales, error);
}

} // namespace texsyn
