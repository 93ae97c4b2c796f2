// SPDX-License-Identifier: Apache-2.0
// Texture mixtures (Heeger & Bergen 1995 §5): match-texture from noise towards the
// statistics mix_statistics makes from several samples.
#include <texsyn/mix.h>

#include "pyramid_synthesis/pyramid_synthesis_pvt.h"

namespace texsyn {

namespace {

bool mix(OIIO::ImageBuf& dst, const std::vector<MixSample>& samples, const MixOptions& opt,
    std::vector<NamedImage>* subbands)
{
    TextureStatistics stats;
    std::string error;
    if (!mix_statistics(samples, opt, stats, error)) {
        dst.errorfmt("{}", error);
        return false;
    }
    if (subbands)
        subbands->clear();
    if (!synthesize_from_statistics(dst, stats, opt.synthesis, nullptr, subbands))
        return false;
    MixOptions resolved = opt;
    resolved.synthesis.width = dst.spec().width;
    resolved.synthesis.height = dst.spec().height;
    resolved.synthesis.scales = stats.scales;
    if (opt.split)
        resolved.palette = opt.palette.value_or(0);
    dst.specmod().attribute("synth:method", "mix");
    dst.specmod().attribute("synth:options", MixOptions::table().format(resolved));
    return true;
}

} // namespace

bool mix_synthesize(OIIO::ImageBuf& dst, const std::vector<MixSample>& samples,
    const MixOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::guarded(dst, "mix_synthesize", [&] { return mix(dst, samples, opt, subbands); });
}

OIIO::ImageBuf mix_synthesize(
    const std::vector<MixSample>& samples, const MixOptions& opt, std::vector<NamedImage>* subbands)
{
    return detail::value_form("mix_synthesize",
        [&](OIIO::ImageBuf& dst) { return mix_synthesize(dst, samples, opt, subbands); });
}

} // namespace texsyn
