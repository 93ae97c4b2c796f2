// SPDX-License-Identifier: Apache-2.0
// MixOptions: the option table of texture mixtures and the checks that need no sample.
#include <texsyn/mix.h>

#include "pyramid_synthesis/pyramid_synthesis_pvt.h"

#include <numeric>

namespace texsyn {

const OptionTable<MixOptions>& MixOptions::table()
{
    return declared_table<MixOptions>([](OptionTable<MixOptions>& t) {
        using O = MixOptions;
        constexpr int max_samples = 16; // weights=, and the range of the indices
        t.include(&O::synthesis, PyramidOptions::table(),
            { { "size", "output size WxH (default: the first sample's size)" },
                { "scales",
                    "pyramid scales, the same for every sample; 0 = the most that keeps the "
                    "coarsest band of every sample and of the output >= 8 px" } });
        t.optional_integer("palette", &O::palette, 0, max_samples - 1,
            "the sample giving the colour: PCA colour transform, pixel and channel histograms "
            "(with pattern=, or with split= where it defaults to 0)");
        t.optional_integer("pattern", &O::pattern, 0, max_samples - 1,
            "the sample giving the pattern: subband histograms, each colour component in the "
            "sample's own basis (paired with the palette's by rank)");
        t.optional_integer("split", &O::split, 1, 16,
            "two samples: scales >= split and the low-pass come from sample 0, the high-pass "
            "and scales < split from sample 1 (laplacian: levels)");
        t.numbers("weights", &O::weights, 0.0f, 1000.0f, size_t(max_samples), "none",
            "one weight per sample, normalised to sum 1: every histogram is the weighted "
            "Wasserstein barycentre (average quantile function) of the samples'");
    });
}

bool MixOptions::validate(std::string& error) const
{
    if (!table().check(*this, error) || !synthesis.validate(error))
        return false;
    auto fail = [&](const char* name, int value, const std::string& reason) {
        error = option_error(name, std::to_string(value), reason);
        return false;
    };
    const std::string modes = "choose one mode: palette=I:pattern=J, split=S or weights=W0,W1,...";
    if (!weights.empty()) {
        const std::string w = format_number_list(weights);
        for (auto [name, value] : { std::pair { "palette", palette },
                 std::pair { "pattern", pattern }, std::pair { "split", split } })
            if (value)
                return fail(name, *value, "does not go with weights=" + w + " (" + modes + ")");
        if (weights.size() < 2) {
            error = option_error(
                "weights", w, "a mix needs a weight for each of at least two samples");
            return false;
        }
        if (!(std::accumulate(weights.begin(), weights.end(), 0.0) > 0.0)) {
            error = option_error("weights", w, "the weights must not all be 0");
            return false;
        }
        return true;
    }
    if (split && pattern)
        return fail("pattern", *pattern,
            "does not go with split=" + std::to_string(*split) + " (" + modes + ")");
    if (pattern && !palette)
        return fail("pattern", *pattern, "needs palette= (the sample giving the colour)");
    if (palette && !pattern && !split)
        return fail("palette", *palette, "alone is not a mix: add pattern= or split=");
    if (!palette && !split) {
        error = "no mix mode given (" + modes + ")";
        return false;
    }
    const int n = nsamples();
    for (auto [name, value] :
        { std::pair { "palette", palette }, std::pair { "pattern", pattern } })
        if (value && *value >= n)
            return fail(name, *value,
                "out of range 0.." + std::to_string(n - 1) + ": the mix has " + std::to_string(n)
                    + " samples");
    if (pattern && *pattern == *palette)
        return fail("pattern", *pattern, "names the same sample as palette=");
    return !(split && synthesis.scales) || detail::check_split(*split, synthesis.scales, error);
}

} // namespace texsyn
