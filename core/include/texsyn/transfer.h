// SPDX-License-Identifier: Apache-2.0
// Texture transfer: Heeger & Bergen 1995 §5, match-texture applied to an image instead of
// noise (the image's layout with a sample's statistics).
//
// Same conventions as every method (synthesis.h): ImageBufAlgo-style two forms, errors in
// dst, scene-linear float in and out, bit-identical for a seed whatever nthreads is.
#pragma once

#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/pyramid_synthesis.h>
#include <texsyn/stats.h>
#include <texsyn/subbands.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// Checks options for transfer_synthesize: opt.validate(), and no size (the image gives
/// the output's size). False with a message.
bool validate_transfer_options(const PyramidOptions& opt, std::string& error);

/// Texture transfer (§5, "apply match-texture to a second image rather than noise"):
/// analyses `sample` (scales 0 = the most the sample and `image` allow) and runs
/// match-texture starting from `image` decorrelated in the sample's colour basis, so the
/// result keeps the image's layout and takes the sample's statistics. Output: the image's
/// size, the sample's channels; synth:method = "transfer". The image need not tile, so
/// neither does the result. `subbands` as in pyramid_synthesize. Fails if the options
/// do not validate_transfer_options, the image has a different channel count from the
/// sample, or as pyramid_synthesize does.
bool transfer_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const OIIO::ImageBuf& image, const PyramidOptions& opt,
    std::vector<NamedImage>* subbands = nullptr);
OIIO::ImageBuf transfer_synthesize(const OIIO::ImageBuf& sample, const OIIO::ImageBuf& image,
    const PyramidOptions& opt, std::vector<NamedImage>* subbands = nullptr);

/// The same towards an analysis of the sample (e.g. read from an analysis file): its
/// statistics as they are, so its number of scales must suit the image (opt.pyramid,
/// scales and orientations must agree with it, as for synthesize_from_statistics; flatten=1
/// is refused: flatten when analysing). `subbands` receives only the synthesis's subbands.
bool transfer_synthesize(OIIO::ImageBuf& dst, const TextureStatistics& sample,
    const OIIO::ImageBuf& image, const PyramidOptions& opt,
    std::vector<NamedImage>* subbands = nullptr);

} // namespace texsyn
#pragma GCC visibility pop
