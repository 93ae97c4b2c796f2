// SPDX-License-Identifier: Apache-2.0
// A method's inputs read from files, the same way for every front end (the tool, recipes,
// the OIIO plugin): samples — images converted to scene-linear with OCIO, or analysis
// files — and the images its input-file options name.
//
// One alpha policy: colour is read un-associated from alpha where the file stores it so
// (PNG, TIFF; flagged "oiio:UnassociatedAlpha") and stays un-associated through the
// conversion, so colour under zero alpha survives; alpha is never colour converted.
#pragma once

#include <memory>
#include <string>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/color.h>
#include <texsyn/methods.h>
#include <texsyn/stats.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// A sample as read from its file: an image or an analysis.
struct Sample {
    std::string filename;
    /// An image: scene-linear float (un-associated from alpha, flagged), the file's
    /// metadata; empty for an analysis.
    OIIO::ImageBuf pixels;
    /// An image: the file's values as read, float (for read_sample's `colorspace` to be
    /// changed afterwards: relinearize_sample).
    OIIO::ImageBuf file_pixels;
    OIIO::TypeDesc file_format;     ///< the file's pixel type (an analysis: its sample's)
    std::string colorspace;         ///< the space the pixels were converted from
    std::string colorspace_reason;  ///< why that space, in words (ColorConfig::Guess)
    std::string colorspace_warning; ///< "" or why that space may be wrong
    std::shared_ptr<const TextureStatistics> analysis; ///< set for an analysis file
};

/// How many float copies of an image sample read_sample() holds at once (the memory check
/// of read_image() counts them).
constexpr int sample_read_copies = 4;

/// Reads `filename`: an analysis file (*.tsa, read_statistics) or an image (read_image),
/// converted from `colorspace` ("" = ColorConfig::guess_colorspace of the file) to the
/// config's scene_linear. Fails (false, `error` naming the file and what is wrong) on a
/// missing, unreadable, truncated or non-image file, NaN/Inf pixels, an unknown colour
/// space, or a colour space given for an analysis (its statistics are already linear).
bool read_sample(const std::string& filename, const ColorConfig& colors,
    const std::string& colorspace, Sample& sample, std::string& error, int nthreads = 0);

/// What read_sample() does with an image file once read_image() has read it (`native`:
/// the file's own spec, of which it says): the sample of `pixels`, converted from
/// `colorspace` ("" = guessed from `native`). Separate so that a front end can tell the
/// file's faults (read_image's) from its pixels'. Fails (false, `error` naming `filename`)
/// on NaN/Inf pixels or an unknown colour space.
bool sample_from_file_pixels(OIIO::ImageBuf pixels, const OIIO::ImageSpec& native,
    const std::string& filename, const ColorConfig& colors, const std::string& colorspace,
    Sample& sample, std::string& error, int nthreads = 0);

/// Makes a sample of an image already in memory (a Python array or ImageBuf) as
/// read_sample() makes one of a file: `pixels` (any pixel type, the values as stored;
/// colour associated with alpha unless flagged "oiio:UnassociatedAlpha") converted from
/// `colorspace` ("" = ColorConfig::guess_colorspace of its spec) to scene_linear; `name`
/// names it in messages. The sample's file_pixels share `pixels`' storage if it is float.
/// Fails (false, `error` naming it) on NaN/Inf pixels or an unknown colour space.
bool sample_from_image(OIIO::ImageBuf pixels, const std::string& name, const ColorConfig& colors,
    const std::string& colorspace, Sample& sample, std::string& error, int nthreads = 0);

/// Converts an image sample's file values again, now taken to be in `colorspace`.
/// Fails (false, `error`) for an unknown space or an analysis.
bool relinearize_sample(Sample& sample, const ColorConfig& colors, const std::string& colorspace,
    std::string& error, int nthreads = 0);

/// Whether input-file option `field` may read `file`: a regular file (a mesh for ReadMesh
/// options, else an image). False with "<option>=<file> : <reason>": no such file, a loop
/// of symbolic links, a directory, or not a regular file (a FIFO, device or socket).
bool check_option_file(const OptionField& field, const std::string& file, std::string& error);

/// Reads the file of every input-file option of `options` that names one: ReadImage files
/// like a sample (scene-linear, the space guessed from the file), ReadData files as their
/// numbers; a ReadMesh file only has to exist (its method reads it). Fails (false,
/// "<option>=<file> : <reason>").
bool read_option_files(const MethodOptions& options, const ColorConfig& colors, OptionImages& files,
    std::string& error, int nthreads = 0);

} // namespace texsyn
#pragma GCC visibility pop
