// SPDX-License-Identifier: Apache-2.0
// --check: prints the homogeneity report of the current image (Heeger & Bergen 1995 §6).
#include "cli_state.h"

#include <cstdio>

#include <texsyn/homogeneity.h>

namespace texsyn::cli {

void run_check(CliState& state, const std::string& command)
{
    const StackImage& img = state.top(command);
    if (img.statistics)
        throw CliError(command + " : " + img.sources[0]
            + " is an analysis, not an image (check the sample it was made from)");
    PlanarImage planes;
    std::string error;
    if (!planes_from_imagebuf(img.buf, planes, error))
        throw CliError(command + " : " + error);
    const HomogeneityReport r = check_homogeneity(planes, state.threads);
    const std::string name = img.file_pixels.initialized()
        ? img.sources[0]
        : "the synthesis from " + sample_names(img);
    std::printf("%s (%dx%d)\n", name.c_str(), r.width, r.height);
    std::printf("  homogeneity score        %6.2f   %s (1 = homogeneous; poor below %.2f)\n",
        r.score, r.poor ? "poor" : "good", homogeneity_poor_score);
    std::printf("  illumination gradient    %6.1f%%  peak-to-peak, %s; limit %.0f%%\n",
        100.0 * r.illumination_amplitude, r.illumination_description.c_str(),
        100.0 * homogeneity_max_illumination_amplitude);
    if (r.tiles_x > 0) {
        std::printf(
            "  local mean variation     %6.1f%%  over %dx%d tiles of %dx%d px; limit %.0f%%\n",
            100.0 * r.local_mean_variation, r.tiles_x, r.tiles_y, r.tile_size, r.tile_size,
            100.0 * homogeneity_max_local_mean_variation);
        std::printf(
            "  local contrast variation %6.1f%%  of each tile's std-dev / mean; limit %.0f%%\n",
            100.0 * r.local_contrast_variation, 100.0 * homogeneity_max_local_contrast_variation);
    }
    for (const std::string& w : r.warnings)
        std::printf("warning: %s\n", w.c_str());
    std::fflush(stdout);
}

} // namespace texsyn::cli
