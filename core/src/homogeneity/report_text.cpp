// SPDX-License-Identifier: Apache-2.0
// The homogeneity report as text (texsyn --check).
#include <texsyn/homogeneity.h>

#include <cstdio>

namespace texsyn {

namespace {

template <class... Args>
void append(std::string& out, const char* format, Args... args)
{
    char line[256];
    std::snprintf(line, sizeof(line), format, args...);
    out += line;
}

} // namespace

std::string format_homogeneity_report(const HomogeneityReport& r, const std::string& name)
{
    std::string out;
    append(out, "%s (%dx%d)\n", name.c_str(), r.width, r.height);
    append(out, "  homogeneity score        %6.2f   %s (1 = homogeneous; poor below %.2f)\n",
        r.score, r.poor ? "poor" : "good", homogeneity_poor_score);
    append(out, "  illumination gradient    %6.1f%%  peak-to-peak, %s; limit %.0f%%\n",
        100.0 * r.illumination_amplitude, r.illumination_description.c_str(),
        100.0 * homogeneity_max_illumination_amplitude);
    append(out,
        "  lighting for copying     %6.1f%%  %s; %s (8x8 regions: %.0f%% of their means' "
        "spread explained, lit-out contrast varies %.0f%%; limits %.0f%%, %.0f%%, %.0f%%)\n",
        100.0 * r.illumination_amplitude,
        r.illumination_planar_fraction >= 0.5 ? "a ramp" : "not a ramp",
        r.uneven_for_copying ? "uneven for the copying methods: flatten=1" : "even",
        100.0 * r.lighting_share, 100.0 * r.lit_out_contrast_variation,
        100.0 * homogeneity_max_lighting_for_copying, 100.0 * homogeneity_min_lighting_share,
        100.0 * homogeneity_max_contrast_variation_of_lighting);
    if (r.tiles_x > 0) {
        append(out,
            "  local mean variation     %6.1f%%  over %dx%d tiles of %dx%d px; limit %.0f%%\n",
            100.0 * r.local_mean_variation, r.tiles_x, r.tiles_y, r.tile_size, r.tile_size,
            100.0 * homogeneity_max_local_mean_variation);
        append(out,
            "  local contrast variation %6.1f%%  of each tile's std-dev / mean; limit %.0f%%\n",
            100.0 * r.local_contrast_variation, 100.0 * homogeneity_max_local_contrast_variation);
    }
    for (const std::string& w : r.warnings)
        out += "warning: " + w + "\n";
    return out;
}

} // namespace texsyn
