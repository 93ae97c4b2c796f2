// SPDX-License-Identifier: Apache-2.0
// The inspection EXR (DESIGN.md "Output files"): one multi-part OpenEXR whose part
// "synth" holds the result and whose further parts hold pyramid subbands.
#pragma once

#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/image.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// A named multi-channel image: one subband of one pyramid (for --subbands output).
struct NamedImage {
    std::string name;  ///< e.g. "sample.s2.o1", "synth.highpass", "synth.L3"
    PlanarImage image; ///< channels pc0, pc1, … (decorrelated colour) plus A if alpha
};

/// Writes `synth` as part "synth" followed by one part per entry of `subbands` (part name
/// = NamedImage::name, float channels as named there) to `filename`. All parts share the
/// display window of the largest part (an OpenEXR rule for multi-part files); smaller
/// parts have their data window at the origin inside it, so stock
/// `oiiotool file.exr --subimage synth.s2.o1 --fullpixels -o band.png` extracts a band.
/// Metadata of `synth` is copied to every part. The file is written atomically (temporary
/// file + rename). Fails (false, `error`) if the file cannot be written.
bool write_subband_exr(const std::string& filename, const OIIO::ImageBuf& synth,
    const std::vector<NamedImage>& subbands, std::string& error);

} // namespace texsyn
#pragma GCC visibility pop
