// SPDX-License-Identifier: Apache-2.0
// Where each band of a pyramid sits (scale, orientation): what the §6 sliders and the
// §5 low/high-band mixtures select bands by.
#include "pyramid_synthesis_pvt.h"

namespace texsyn::detail {

BandPosition band_position(PyramidKind kind, int orientations, int band, int nbands)
{
    if (kind == PyramidKind::Laplacian) // "L0" … "L<S-1>", "lowpass"
        return { band, 0 };
    if (band == 0) // "highpass"
        return { -1, 0 };
    if (band == nbands - 1) // "lowpass"
        return { (nbands - 2) / orientations, 0 };
    return { (band - 1) / orientations, (band - 1) % orientations }; // "s<scale>.o<k>"
}

bool check_split(int split, int scales, std::string& error)
{
    if (split >= 1 && split <= scales)
        return true;
    error = option_error("split", std::to_string(split),
        "out of range 1.." + std::to_string(scales) + ": the pyramid has " + std::to_string(scales)
            + " scales");
    return false;
}

} // namespace texsyn::detail
