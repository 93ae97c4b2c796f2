// SPDX-License-Identifier: Apache-2.0
// Texture transfer (Heeger & Bergen 1995 §5, "apply match-texture to a second image
// rather than noise"): the image's layout with the sample's statistics.
#include <texsyn/transfer.h>

#include "pyramid_synthesis/pyramid_synthesis_pvt.h"

namespace texsyn {

namespace {

// The transfer of `image` towards `sample`'s statistics: analysed here from `sample`
// (an image), or given (`analysis`).
bool transfer(OIIO::ImageBuf& dst, const OIIO::ImageBuf* sample, const TextureStatistics* analysis,
    const OIIO::ImageBuf& image, const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    std::string error;
    auto fail = [&](const std::string& message) {
        dst.errorfmt("{}", message);
        return false;
    };
    if (!validate_transfer_options(opt, error))
        return fail(error);
    if (analysis && opt.flatten) // an analysis keeps no pixels to divide
        return fail(detail::flatten_of_analysis_error("the sample"));
    const OIIO::ImageSpec& is = image.spec();
    const int nc = analysis ? analysis->nchannels() : sample->spec().nchannels;
    if (image.initialized() && is.nchannels != nc)
        return fail("the image has " + detail::count_text(is.nchannels, "channel") + ", the sample "
            + std::to_string(nc) + ": a transfer needs the same channels");
    // The image fixes the output size, and with it the default number of scales.
    PyramidOptions sized = opt;
    sized.width = is.width;
    sized.height = is.height;
    if (subbands)
        subbands->clear();
    TextureStatistics stats;
    if (!analysis && !analyze_texture(*sample, sized, stats, error, nullptr, subbands))
        return fail(error);
    return synthesize_from_statistics(dst, analysis ? *analysis : stats, sized, &image, subbands);
}

} // namespace

bool validate_transfer_options(const PyramidOptions& opt, std::string& error)
{
    if (!opt.validate(error))
        return false;
    if (opt.width || opt.height) {
        error = option_error("size", std::to_string(opt.width) + "x" + std::to_string(opt.height),
            "does not apply: a transfer's output has the image's size");
        return false;
    }
    return true;
}

bool transfer_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const OIIO::ImageBuf& image, const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::guarded(dst, "transfer_synthesize",
        [&] { return transfer(dst, &sample, nullptr, image, opt, subbands); });
}

OIIO::ImageBuf transfer_synthesize(const OIIO::ImageBuf& sample, const OIIO::ImageBuf& image,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::value_form("transfer_synthesize", [&](OIIO::ImageBuf& dst) {
        return transfer_synthesize(dst, sample, image, opt, subbands);
    });
}

bool transfer_synthesize(OIIO::ImageBuf& dst, const TextureStatistics& sample,
    const OIIO::ImageBuf& image, const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::guarded(dst, "transfer_synthesize",
        [&] { return transfer(dst, nullptr, &sample, image, opt, subbands); });
}

} // namespace texsyn
