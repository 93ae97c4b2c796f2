// SPDX-License-Identifier: Apache-2.0
// Castellanos & Williams choosy sampling on the pixel grid ("Automatic Synthesis of
// Isotropic Textures on Surfaces from Sample Images", §3.2–3.3, §3.11–3.13, §4, §6).
//
// Same conventions as synthesis.h: ImageBufAlgo-style two forms, errors in dst, scene-linear
// float in and out, bit-identical for a seed whatever nthreads is.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include <texsyn/options.h>
#include <texsyn/run_controls.h>
#include <texsyn/source_map.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// How choosy sampling finds the best-scoring sample neighbourhood.
enum class ChoosySearch {
    /// Every sample neighbourhood in every orientation, in full dimension, exactly: the
    /// paper's O(MNd) loop (§6.1), the oracle for the other.
    Exhaustive,
    /// §6.2–6.4: neighbourhoods (weighted, then projected on their `dims` leading principal
    /// components) in a set of dynamic kd-trees, one per use count; each tree's nearest is
    /// scaled by its penalty and the smallest wins.
    KdTree,
};

/// Options of choosy sampling. Defaults are the paper's (§5: four levels, one iteration
/// per level, the 2-distant neighbourhood; §6.2: 20 dimensions) except `isotropic`, which
/// is 0 on images.
struct ChoosyOptions : RunControls {
    int width = 0; ///< output size; 0x0 = the sample's size (after the crop, see below)
    int height = 0;
    int levels = 4; ///< Gaussian/Laplacian pyramid levels
    /// Choosy passes per level, finest first; one value = every level; coarser levels
    /// missing from the list repeat the last (the paper's Fig. 10(c) is 1,8).
    std::vector<int> iterations = { 1 };
    /// A sample neighbourhood used c times scores distance x 2^(penalty x (c - c_min)):
    /// 1 is the paper's choosy sampling, 0 the greedy best match (Wei & Levoy's selection).
    float penalty = 1.0f;
    /// 1: compare with the sample's neighbourhoods in all 8 rotations and reflections of the
    /// grid (isotropic variants of anisotropic samples, §5); 0 (the default, unlike the
    /// paper's): the sample's orientation, so that wood grain or bricks keep their direction.
    int isotropic = 0;
    /// 1: the sample's low-order lighting is divided out first (flatten_illumination,
    /// homogeneity.h); the result copies the flattened sample's pixels.
    int flatten = 0;
    /// The result's features this many times as large as the sample's, 0.25..4: the sample
    /// is resampled by it first (its source map then refers to the resampled sample).
    float scale = 1.0f;
    ChoosySearch search = ChoosySearch::KdTree;
    int dims = 20; ///< kdtree: principal components kept (>= the vector size: all, exact)
    /// kdtree: nanoflann's approximation factor (0 = exact in PCA space). 30 was measured
    /// 4x faster than 0 with the same histogram match and look (docs/choosy.md).
    float eps = 30.0f;

    /// The table behind `--choosy:name=value`, recipes, synth:options and the docs.
    static const OptionTable<ChoosyOptions>& table();

    /// Checks the options alone (ranges, list lengths). False with a message.
    bool validate(std::string& error) const;

    /// Iterations at level `level` (0 finest).
    int iterations_at(int level) const;
};

/// Bytes of memory a synthesis needs (the estimate the size check uses): the finest level's
/// sample neighbourhoods (in every orientation) and their search structure dominate.
size_t choosy_memory_estimate(int sample_width, int sample_height, int nchannels, int out_width,
    int out_height, const ChoosyOptions& opt);

/// Castellanos & Williams' synthesis (Algorithms 1 and 2) on the pixel grid.
///
/// Analysis: the sample is cropped to a multiple of 2^(levels-1) on each side (its
/// top-left part) and decomposed into Gaussian levels G_k and Laplacian levels
/// L_k = G_k - project(G_{k-1}) (the (1,4,6,4,1)/16 kernel, reflected at the edges).
///
/// Synthesis: the coarsest output level starts as random sample pixels of the coarsest
/// sample level. Every pass of a level visits every output pixel in a seeded random order
/// and replaces it with the sample pixel whose neighbourhood scores best, and the pixel's
/// four children at the next finer level with that sample pixel's four Laplacian children
/// (turned with the orientation that matched). The neighbourhood is the 24 pixels within
/// Chebyshev distance 2 (the 5x5 square but its centre: the grid's 2-distant neighbours
/// under 8-adjacency), every channel, each pixel weighted by
/// beta = exp(-1/2 (d / 1.3)^2) with d its Euclidean distance to the centre in the level's
/// pixels (eq. 7, sigma_k = 1 pixel, the kernel's). The score is the weighted Euclidean
/// distance times 2^(penalty (c - c_min)), c counting the uses of that sample pixel in the
/// pass. Sample neighbourhoods must lie inside the sample; output ones wrap around (the
/// output tiles). The next level starts as its synthesized Laplacian plus the projected
/// (circularly) level above. Rounds of up to 256 visits are searched in parallel against
/// the state at the round's start and applied in order; a visit whose neighbours or choice
/// an earlier visit of the round changed is searched again, so the result never depends on
/// nthreads.
///
/// `dst` receives opt.width x opt.height (each a multiple of 2^(levels-1)) with the
/// sample's channels; every output pixel is a copy of a sample pixel. If `source_map` is not
/// null it receives the 2-channel float "x", "y" map of those pixels (see
/// neighborhood_synthesize). Fails (false, message in dst) on invalid options, a sample
/// with an error or NaN/Inf pixels, levels the sample or the output cannot hold (each
/// level needs at least 5x5 pixels; the message gives the most allowed), an output side
/// not a multiple of 2^(levels-1), or an output needing more memory than the machine has
/// (checked before allocating).
bool choosy_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample, const ChoosyOptions& opt,
    OIIO::ImageBuf* source_map = nullptr);
OIIO::ImageBuf choosy_synthesize(
    const OIIO::ImageBuf& sample, const ChoosyOptions& opt, OIIO::ImageBuf* source_map = nullptr);

} // namespace texsyn
#pragma GCC visibility pop
