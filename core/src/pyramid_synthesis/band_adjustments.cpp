// SPDX-License-Identifier: Apache-2.0
// Heeger & Bergen §6's "slider for each parameter": per-scale contrast gain and
// orientation-energy balance, applied to the sample's band statistics.
#include "pyramid_synthesis_pvt.h"

#include <algorithm>
#include <cmath>

namespace texsyn::detail {

namespace {

float list_value(const std::vector<float>& list, int scale, float fallback)
{
    return scale < int(list.size()) ? list[size_t(scale)] : fallback;
}

} // namespace

float band_gain(const PyramidOptions& opt, int band, int nbands)
{
    if (band == nbands - 1) // the low-pass residual
        return 1.0f;
    const BandPosition pos = band_position(opt.pyramid, opt.orientations, band, nbands);
    const int scale = std::max(0, pos.scale); // the high-pass residual follows the finest scale
    const double b = list_value(opt.balance, scale, 0.0f);
    const int k = opt.orientations;
    const double tilt = opt.pyramid == PyramidKind::Steerable && pos.scale >= 0
        ? 1.0 + b * std::cos(2.0 * M_PI * pos.orientation / k)
        : 1.0;
    return float(double(list_value(opt.gain, scale, 1.0f)) * tilt);
}

bool check_band_adjustments(const PyramidOptions& opt, int scales, std::string& error)
{
    for (auto [name, list] :
        { std::pair { "gain", &opt.gain }, std::pair { "balance", &opt.balance } })
        if (int(list->size()) > scales) {
            error = option_error(name, format_number_list(*list),
                std::to_string(list->size()) + " values but the pyramid has "
                    + std::to_string(scales) + " scales");
            return false;
        }
    return true;
}

} // namespace texsyn::detail
