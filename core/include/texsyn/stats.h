// SPDX-License-Identifier: Apache-2.0
// The statistics the pyramid method takes from a sample (Heeger & Bergen 1995 §3.3, §3.5)
// and the analysis files (.tsa) that store them (docs/analysis-files.md).
//
// Analysis (synthesis.h analyze_texture) makes a TextureStatistics; synthesis
// (synthesize_from_statistics) needs nothing else, so a saved analysis synthesizes exactly
// what the sample would: the quantile tables are kept whole, never binned.
#pragma once

#include <string>
#include <vector>

#include <texsyn/color.h>
#include <texsyn/histogram.h>
#include <texsyn/pyramid.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// What match-texture imposes on one synthesized component: a decorrelated colour
/// component ("pc0", "pc1", …), alpha ("A") or an extra channel (its own name).
struct ComponentStatistics {
    std::string name;
    bool constant = false; ///< carries no variance: synthesized as `mean`, no tables
    float mean = 0.0f;
    QuantileTable pixels;             ///< the component's histogram (empty if constant)
    std::vector<QuantileTable> bands; ///< one per subband in band order (empty if constant)
};

/// Everything the pyramid method needs to synthesize a texture.
struct TextureStatistics {
    int sample_width = 0;  ///< the analysed sample's size (informational, and the default
    int sample_height = 0; ///< output size)
    PyramidKind pyramid = PyramidKind::Steerable;
    int scales = 0;       ///< fixed at analysis time: the bands' pyramid has this many
    int orientations = 4; ///< steerable bands per scale (unused by laplacian)
    std::vector<std::string> band_names;    ///< the pyramid's band names, in order
    std::vector<std::string> channel_names; ///< the sample's channels
    int alpha_channel = -1;                 ///< index in channel_names, or -1
    bool unassociated_alpha = false;        ///< the sample said "oiio:UnassociatedAlpha"
    std::string colorspace;                 ///< the sample's colour space before linearisation
    std::string source;                     ///< the sample's file name, if known
    std::string sample_format; ///< the sample file's pixel type ("uint8", …), if known
    bool flattened = false;    ///< the sample\'s lighting was divided out (flatten=1)
    ColorTransform color;      ///< §3.5 PCA of the colour channels
    std::vector<ComponentStatistics> components; ///< one per channel, decorrelated
    std::vector<QuantileTable> channels;         ///< per sample channel (the final match)

    int nchannels() const { return int(channel_names.size()); }
};

/// The analysis file format's version (the "version" key of the header).
constexpr int analysis_file_version = 2;

/// Writes `stats` to `filename` (atomically: temporary file, then rename). False with a
/// message on an I/O error.
bool write_statistics(
    const std::string& filename, const TextureStatistics& stats, std::string& error);

/// Reads an analysis file. Fails (false, `error` says what is wrong and where) on a file
/// that is not an analysis file, a different version, a malformed or inconsistent header,
/// truncated or corrupted data (checksum), or non-finite / unsorted tables. `stats` is
/// untouched on failure.
bool read_statistics(const std::string& filename, TextureStatistics& stats, std::string& error);

/// Same, from the bytes of a file (for tests and fuzzing); `name` is used in messages.
bool parse_statistics(const std::string& bytes, const std::string& name, TextureStatistics& stats,
    std::string& error);

/// True if `filename` ends in ".tsa" (case-insensitive): the tool and recipes read such
/// files as analyses, not images.
bool is_analysis_filename(const std::string& filename);

} // namespace texsyn
#pragma GCC visibility pop
