// SPDX-License-Identifier: Apache-2.0
#include "synthesis_pvt.h"

namespace texsyn {

const OptionTable<PyramidOptions>& PyramidOptions::table()
{
    using O = PyramidOptions;
    static const OptionTable<O> t = [] {
        OptionTable<O> t;
        t.size("size", &O::width, &O::height, 1 << 20, "the sample's size",
            "output size WxH (default: the sample's size)");
        detail::add_iterations_option(t);
        t.choice("pyramid", &O::pyramid,
            { { "steerable", PyramidKind::Steerable }, { "laplacian", PyramidKind::Laplacian } },
            "subband decomposition: steerable (oriented bands) or laplacian");
        t.integer("scales", &O::scales, 0, 16,
            "pyramid scales; 0 = the most that keeps the coarsest band of the sample and of the "
            "output >= 8 px");
        t.integer("orientations", &O::orientations, 1, 8,
            "oriented bands per scale of the steerable pyramid");
        detail::add_matching_options(t);
        t.numbers("gain", &O::gain, 0.0f, 16.0f, 16, "1",
            "contrast gain of each scale's bands, finest first (s0; the high-pass follows s0), "
            "applied to the sample's statistics (paper §6 sliders); missing scales are 1");
        t.numbers("balance", &O::balance, -1.0f, 1.0f, 16, "0",
            "orientation-energy balance of each scale, finest first (steerable only): band k of "
            "K is scaled by 1 + b cos(2 pi k/K); b > 0 favours orientation 0 (vertical "
            "structure), b < 0 orientation K/2");
        t.integer("flatten", &O::flatten, 0, 1,
            "1 = divide the sample by its fitted lighting gradient before analysis "
            "(see texsyn --check and docs/homogeneity.md)");
        return t;
    }();
    return t;
}

bool PyramidOptions::validate(std::string& error) const
{
    if ((width == 0) != (height == 0) || width < 0 || height < 0) {
        error = "size=" + std::to_string(width) + "x" + std::to_string(height)
            + " is not a size (both sides must be >= 1)";
        return false;
    }
    if (iterations < 0 || iterations > 100) {
        error = "iterations=" + std::to_string(iterations) + " is out of range (0..100)";
        return false;
    }
    if (orientations < 1 || orientations > 8) {
        error = "orientations=" + std::to_string(orientations) + " is out of range (1..8)";
        return false;
    }
    if (scales < 0 || scales > 16) {
        error = "scales=" + std::to_string(scales) + " is out of range (0..16)";
        return false;
    }
    for (float g : gain)
        if (!(g > 0.0f && g <= 16.0f)) {
            error = "gain=" + format_number_list(gain) + " : each gain must be in (0, 16]";
            return false;
        }
    for (float b : balance)
        if (!(b >= -1.0f && b <= 1.0f)) {
            error = "balance=" + format_number_list(balance) + " : each value must be in -1..1";
            return false;
        }
    if (!balance.empty() && pyramid != PyramidKind::Steerable) {
        error = "balance= needs pyramid=steerable (the laplacian pyramid has no orientations)";
        return false;
    }
    if (flatten < 0 || flatten > 1) {
        error = "flatten=" + std::to_string(flatten) + " is out of range (0..1)";
        return false;
    }
    if (!fft_backend_available(fft)) {
        error = std::string("fft=") + fft_backend_name(fft)
            + " is not available: texsyn was built without it (-DTEXSYN_WITH_FFTW=ON)";
        return false;
    }
    return true;
}

size_t pyramid_memory_estimate(int width, int height, int nchannels, const PyramidOptions& opt)
{
    // Per output pixel, in bytes: the output planes, the float ImageBuf and its staging
    // copy (12 per channel), and for the one channel being synthesized its image (4), its
    // bands (4 per band pixel: K oriented bands over 4/3 of the area plus the two
    // residuals), one half spectrum per band (4 per band pixel) and the per-level low-pass
    // spectra (about 6).
    double n = double(width) * double(height);
    double bands
        = opt.pyramid == PyramidKind::Steerable ? opt.orientations * 4.0 / 3.0 + 2.0 : 4.0 / 3.0;
    double bytes = n * (12.0 * nchannels + 4.0 + 8.0 * bands + 6.0);
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
