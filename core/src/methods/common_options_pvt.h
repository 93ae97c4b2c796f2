// SPDX-License-Identifier: Apache-2.0
// Options several methods take, declared once (the same name, range and help everywhere).
#pragma once

#include <string>

#include <texsyn/options.h>

namespace texsyn::detail {

/// The largest side of an output image (memory refuses far less anyway).
constexpr int max_image_side = 65536;

/// "size": the output's WxH, 1..max_side each, 0x0 = the sample's size. T has int members
/// width and height.
template <class T>
void add_output_size(OptionTable<T>& t,
    const char* help = "output size WxH (default: the sample's size)",
    int max_side = max_image_side)
{
    t.size("size", &T::width, &T::height, max_side, "the sample's size", help).shared();
}

/// "levels": the pyramid levels a coarse-to-fine method synthesizes, 1..max_levels. T has
/// an int member levels.
template <class T>
void add_levels(OptionTable<T>& t, int max_levels, const char* help)
{
    t.integer("levels", &T::levels, 1, max_levels, help).shared();
}

/// "flatten": 1 = the sample's low-order lighting divided out before the method reads it
/// (flatten_illumination, homogeneity.h). T has an int member flatten.
template <class T>
void add_flatten(OptionTable<T>& t, const char* what = "before it is read")
{
    t.integer("flatten", &T::flatten, 0, 1,
         (std::string("1 = divide the sample by its fitted lighting gradient ") + what
             + " (see texsyn --check and docs/homogeneity.md)")
             .c_str())
        .shared();
}

/// "scale": the copying methods' features k times larger (or smaller) than in the sample:
/// the sample is resampled by k first (scale_sample). T has a float member scale.
template <class T>
void add_scale(OptionTable<T>& t)
{
    t.real("scale", &T::scale, 0.25f, 4.0f,
         "the result's features this many times as large as the sample's (the sample is "
         "resampled first: a texture at another texel density than the scan); the source "
         "map then refers to the resampled sample, and --apply-map resamples a map of the "
         "sample's size to match")
        .shared();
}

/// "eps": the approximation factor of a kd-tree search, 0..100. T has a float member eps.
template <class T>
void add_kdtree_eps(OptionTable<T>& t)
{
    t.real("eps", &T::eps, 0.0f, 100.0f,
         "kdtree: approximation factor (a match's squared distance in PCA space may be "
         "(1+eps) times the nearest's; 0 = exact)")
        .shared();
}

} // namespace texsyn::detail
