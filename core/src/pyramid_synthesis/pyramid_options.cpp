// SPDX-License-Identifier: Apache-2.0
#include "methods/common_options_pvt.h"
#include "pyramid_synthesis_pvt.h"

namespace texsyn {

const OptionTable<PyramidOptions>& PyramidOptions::table()
{
    return declared_table<PyramidOptions>([](OptionTable<PyramidOptions>& t) {
        using O = PyramidOptions;
        detail::add_output_size(t, "output size WxH (default: the sample's size)", 1 << 20);
        detail::add_iterations_option(t);
        t.choice("pyramid", &O::pyramid,
            { { "steerable", PyramidKind::Steerable }, { "laplacian", PyramidKind::Laplacian } },
            "subband decomposition: steerable (oriented bands) or laplacian");
        detail::add_scale_options(t,
            "pyramid scales; 0 = the most that keeps the coarsest band of the sample and of the "
            "output >= 8 px",
            "oriented bands per scale of the steerable pyramid");
        detail::add_matching_options(t);
        t.numbers("gain", &O::gain, 0.0f, 16.0f, 16, "1",
            "contrast gain of each scale's bands, finest first (s0; the high-pass follows s0), "
            "applied to the sample's statistics (paper §6 sliders); missing scales are 1");
        t.numbers("balance", &O::balance, -1.0f, 1.0f, 16, "0",
            "orientation-energy balance of each scale, finest first (steerable only): band k of "
            "K is scaled by 1 + b cos(2 pi k/K); b > 0 favours orientation 0 (vertical "
            "structure), b < 0 orientation K/2");
        detail::add_flatten(t, "before analysis");
    });
}

bool PyramidOptions::validate(std::string& error) const
{
    if (!table().check(*this, error))
        return false;
    if (!balance.empty() && pyramid != PyramidKind::Steerable) {
        error = option_error("balance", format_number_list(balance),
            "needs pyramid=steerable (the laplacian pyramid has no orientations)");
        return false;
    }
    return detail::check_fft_backend(fft, error);
}

size_t pyramid_memory_estimate(int width, int height, int nchannels, const PyramidOptions& opt)
{
    // Per output pixel, in bytes: the output planes, the float ImageBuf and its staging
    // copy (12 per channel), the copy every front end makes to write or return it (4 per
    // channel), and for the one channel being synthesized its image (4), its bands (4 per
    // band pixel: K oriented bands over 4/3 of the area plus the two residuals), one half
    // spectrum per band (4 per band pixel) and the per-level low-pass spectra (about 6). A
    // quarter more for what the allocator keeps (measured whole processes, RGB, steerable
    // with four orientations: 143 bytes per output pixel at 4096x4096, 151 at 1024x1024;
    // bench/README.md, "Scaling with output size").
    double n = double(width) * double(height);
    double bands
        = opt.pyramid == PyramidKind::Steerable ? opt.orientations * 4.0 / 3.0 + 2.0 : 4.0 / 3.0;
    double bytes = 1.25 * n * (16.0 * nchannels + 4.0 + 8.0 * bands + 6.0);
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

size_t pyramid_analysis_memory_estimate(
    int width, int height, int nchannels, const PyramidOptions& opt)
{
    // Per sample pixel, in bytes: the float sample (4 per channel), its planes and their
    // periodic components (8 per channel), the working set of the channel being analysed
    // (as for a synthesis: its image, bands, spectra), and the statistics kept of every
    // channel: exact histograms hold every band value (4 per band pixel and channel). A
    // quarter more for what the allocator keeps (measured: 2048x2048 RGB, steerable with
    // four orientations, about 210 bytes per pixel for --pyramid and 310 for --analyze).
    double n = double(width) * double(height);
    double bands
        = opt.pyramid == PyramidKind::Steerable ? opt.orientations * 4.0 / 3.0 + 2.0 : 4.0 / 3.0;
    double stats = opt.histogram == HistogramMode::Exact ? 4.0 * nchannels * (bands + 1.0) : 0.0;
    double bytes = 1.25 * n * (12.0 * nchannels + 4.0 + 8.0 * bands + 6.0 + stats);
    return bytes > 1e18 ? size_t(1e18) : size_t(bytes);
}

} // namespace texsyn
