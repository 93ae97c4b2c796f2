// SPDX-License-Identifier: Apache-2.0
// Texture transfer (Heeger & Bergen 1995 §5, "apply match-texture to a second image
// rather than noise"): the image's layout with the sample's statistics.
#include "synthesis_pvt.h"

namespace texsyn {

namespace {

bool transfer(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const OIIO::ImageBuf& image,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    std::string error;
    auto fail = [&](const std::string& message) {
        dst.errorfmt("{}", message);
        return false;
    };
    if (!validate_transfer_options(opt, error))
        return fail(error);
    const OIIO::ImageSpec &is = image.spec(), &ss = sample.spec();
    if (image.initialized() && sample.initialized() && is.nchannels != ss.nchannels)
        return fail("the image has " + detail::count_text(is.nchannels, "channel") + ", the sample "
            + std::to_string(ss.nchannels) + ": a transfer needs the same channels");
    // The image fixes the output size, and with it the default number of scales.
    PyramidOptions sized = opt;
    sized.width = is.width;
    sized.height = is.height;
    if (subbands)
        subbands->clear();
    TextureStatistics stats;
    if (!analyze_texture(sample, sized, stats, error, nullptr, subbands))
        return fail(error);
    return synthesize_from_statistics(dst, stats, sized, &image, subbands);
}

} // namespace

bool validate_transfer_options(const PyramidOptions& opt, std::string& error)
{
    if (!opt.validate(error))
        return false;
    if (opt.width || opt.height) {
        error = "size=" + std::to_string(opt.width) + "x" + std::to_string(opt.height)
            + " does not apply: a transfer's output has the image's size";
        return false;
    }
    return true;
}

bool transfer_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const OIIO::ImageBuf& image, const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::guarded(
        dst, "transfer_synthesize", [&] { return transfer(dst, sample, image, opt, subbands); });
}

OIIO::ImageBuf transfer_synthesize(const OIIO::ImageBuf& sample, const OIIO::ImageBuf& image,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::value_form("transfer_synthesize", [&](OIIO::ImageBuf& dst) {
        return transfer_synthesize(dst, sample, image, opt, subbands);
    });
}

} // namespace texsyn
