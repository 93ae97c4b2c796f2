// SPDX-License-Identifier: Apache-2.0
// The pieces of the cascade (cascade.h): maps, kernels, the convolution.
#pragma once

#include <string>
#include <vector>

#include <texsyn/cascade.h>
#include <texsyn/image.h>

namespace texsyn::detail {

/// p(x) for one map, clamped to [0, 1] (x is clamped first). `curve` is the map=curve points.
float cascade_map_value(CascadeMap map, float r, const std::vector<float>& curve, float x);

/// Applies cascade_map_value to every value of `plane`.
void apply_cascade_map(
    Plane& plane, CascadeMap map, float r, const std::vector<float>& curve, int nthreads);

/// A square kernel: size x size weights, row by row, summing to 1.
struct CascadeKernelWeights {
    int size = 1;
    std::vector<float> weights;
    float at(int i, int j) const { return weights[size_t(j) * size_t(size) + size_t(i)]; }
};

/// The kernel the options name for cascade level `level` (presets, or kernel=custom's
/// normalised weights).
CascadeKernelWeights cascade_kernel(const CascadeOptions& opt, int level);

/// out = N(in), circular: out(x, y) = sum_ij w(i, j) in(x + i - h, y + j - h), h = size / 2.
/// Each row is a sum of shifted rows, so it vectorises; parallel over rows.
void convolve_circular(const Plane& in, const CascadeKernelWeights& k, Plane& out, int nthreads);

/// The warped convolution: tap (i, j) of pixel (x, y) is read at (x, y) + d R(a) (i - h,
/// j - h), bilinearly and circularly, with d = dilation(x, y) (1 if `dilation` is empty)
/// and R(a) the rotation by a = angle(x, y) radians (0 if `angle` is empty). d = 1 and
/// a = 0 everywhere give exactly convolve_circular's result.
void convolve_warped(const Plane& in, const CascadeKernelWeights& k, const Plane& dilation,
    const Plane& angle, Plane& out, int nthreads);

/// `in` resampled to width x height, circularly (so a tile stays a tile): separable
/// Catmull-Rom, widened by the ratio when minifying. The same size returns `in` exactly.
Plane resample_circular(const Plane& in, int width, int height, int nthreads);

/// The tool's shorthands, rewritten into options: `map=curve:x0,y0,…` (a piece without '='
/// after map=…curve) becomes curve=x0,y0,…; `kernel=w0,w1,…` (numbers) becomes
/// kernel=custom:weights=… with ksize the square root of their count unless given;
/// `ramp=FILE` (a name with a letter extension, e.g. rust.png) becomes palette=FILE.
std::string cascade_shorthands(const std::string& modifiers);

} // namespace texsyn::detail
