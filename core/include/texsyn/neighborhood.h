// SPDX-License-Identifier: Apache-2.0
// The neighbourhood method: Wei & Levoy 2000 "Fast Texture Synthesis using Tree-structured
// Vector Quantization" (and its implementation report), with the search back-ends of
// search.h and source maps (source_map.h).
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
#include <texsyn/search.h>
#include <texsyn/source_map.h>

#pragma GCC visibility push(default) // exported: what this header declares
namespace texsyn {

/// Which output pixels a neighbourhood holds (the report's Figure 2 and Figure 3).
enum class NeighborhoodShape {
    /// The causal L: the (n-1)/2 rows above and the (n-1)/2 pixels to the left, n wide —
    /// pixels already synthesized in scanline order (Wei & Levoy's).
    Causal,
    /// The whole n x n square but its centre, unsynthesized noise included: the report's
    /// Figure 3(c), kept as a debug option to show why the L is used.
    Square,
};

/// Options of the neighbourhood method. Defaults are Wei & Levoy's where they give one.
struct NeighborhoodOptions : RunControls {
    int width = 0; ///< output size; 0x0 = the sample's size
    int height = 0;
    int levels = 4; ///< Gaussian pyramid levels (1 = single resolution)
    /// Neighbourhood width n (odd) per level, finest first; one value = every level;
    /// missing coarser levels repeat the last value.
    std::vector<int> n = { 9 };
    int coarse = 5; ///< side (odd) of the square at the next coarser level
    NeighborhoodShape shape = NeighborhoodShape::Causal;
    /// Coherent by default: it keeps edges and corners (grass blades, mortar lines) that the
    /// nearest-neighbour back-ends blur (the report's §3.3), matches the sample's histogram
    /// best, and is the fastest (bench/README.md).
    SearchMethod search = SearchMethod::Coherent;
    // Search defaults chosen by measurement (N3: 256x256 -> 512x512, 4 levels, n=9,7,5,5; about
    // 350,000 scanline-sequential queries, so a few microseconds each): 95% of the variance
    // takes 40-60 PCA components on real neighbourhoods, where a kd-tree is no faster than
    // a scan (2 ms a query); 8 components, the 4 best of an approximate (eps=30) reduced
    // search re-ranked in full, answer in ~3 us within ~19% of the exhaustive mean distance
    // (eps from 0 to 50 changes it by under 3%). k=1 (Ashikhmin's) keeps stones, flowers and
    // grass blades whole and is twice as fast as k=2, which blurs them. tsvq: 4 leaves is the
    // fewest that looked like the exhaustive result on N1.
    int candidates = 4; ///< tsvq: leaves visited; kdtree: matches re-ranked (see search.h)
    int dims = 8;       ///< kdtree: PCA components kept; 0 = 95% of the variance
    float eps = 30.0f;  ///< kdtree: approximation factor
    int coherence = 1;  ///< coherent: k of k-coherence
    int merge = 0;      ///< coherent: 1 = also ask the kd-tree
    /// 1: after each level's scanline pass, re-synthesize the pixels within n/2 of the
    /// wrap-around seams with full square neighbourhoods (which see both sides), so the
    /// output tiles; 0: Wei & Levoy's single pass (its first rows and columns matched noise).
    int tile = 1;
    /// 1: the sample's low-order lighting is divided out first (flatten_illumination,
    /// homogeneity.h); the result copies the flattened sample's pixels.
    int flatten = 0;
    /// The result's features this many times as large as the sample's, 0.25..4: the sample
    /// is resampled by it first (its source map then refers to the resampled sample).
    float scale = 1.0f;

    /// The table behind `--neighborhood:name=value`, recipes, synth:options and the docs.
    static const OptionTable<NeighborhoodOptions>& table();

    /// Checks the options alone (ranges, odd sizes). False with a message.
    bool validate(std::string& error) const;

    /// n at level `level` (0 finest).
    int n_at(int level) const;
};

/// Bytes of memory a synthesis needs (the estimate the size check uses): the sample's
/// neighbourhood vectors of the finest level and the searcher built over them dominate.
size_t neighborhood_memory_estimate(int sample_width, int sample_height, int nchannels,
    int out_width, int out_height, const NeighborhoodOptions& opt);

/// Wei & Levoy's synthesis. Gaussian pyramids (the (1,4,6,4,1)/16 kernel) of the sample
/// (`levels` levels) and of the output; the output's levels start as noise drawn from the
/// sample (each pixel a seeded random sample pixel of that level) and are synthesized
/// coarsest first, each in scanline order: the neighbourhood of an output pixel is the
/// causal L of width n at its level (toroidal: it reaches across the output's edges) plus,
/// below the coarsest level, the coarse x coarse square around its parent at the next
/// coarser (already synthesized) level; it is compared with every sample neighbourhood
/// that lies inside the sample (coarse squares reflect at the sample's edges) through
/// the chosen search back-end, and the best match's pixel is copied. Every channel (colour,
/// alpha, extra channels) is part of the neighbourhood and copied.
///
/// `dst` receives opt.width x opt.height (any size) with the sample's channels; if
/// `source_map` is not null it receives a 2-channel float image ("x", "y") of the same size
/// holding, per output pixel, the integer sample coordinate it was copied from, with
/// "synth:sample_size" = "WxH" (apply_source_map takes it).
/// Fails (false, message in dst) on invalid options, a sample with an error or NaN/Inf
/// pixels, a sample (at any level) smaller than that level's neighbourhood (the message
/// gives the most levels it allows), an output level smaller than its neighbourhood, or an
/// output that would need more memory than the machine has (checked before allocating).
bool neighborhood_synthesize(OIIO::ImageBuf& dst, const OIIO::ImageBuf& sample,
    const NeighborhoodOptions& opt, OIIO::ImageBuf* source_map = nullptr);
OIIO::ImageBuf neighborhood_synthesize(const OIIO::ImageBuf& sample, const NeighborhoodOptions& opt,
    OIIO::ImageBuf* source_map = nullptr);

} // namespace texsyn
#pragma GCC visibility pop
