// SPDX-License-Identifier: Apache-2.0
// The whole public API: this header includes every header of include/texsyn (each
// method's entry points, in the ImageBufAlgo style, and what they share; a test checks
// that none is left out).
//
// Rules for every method's functions:
//  - Two forms: `bool f(ImageBuf& dst, …)` does the work; `ImageBuf f(…)` wraps it and
//    returns an ImageBuf whose has_error() is true on failure. Errors go to
//    dst.errorfmt(); nothing throws across this API and nothing exits.
//  - The sample is read as float (any pixel type, any channel count 1..n; the channel
//    named by spec.alpha_channel is alpha). Its pixels must already be scene-linear:
//    ColorConfig::convert (color.h) does that; the `texsyn` tool does it for you.
//  - The result is a float image with the sample's channels and channel names, its
//    pixels scene-linear, origin (0,0), carrying synth:version, synth:method, synth:seed
//    and synth:options metadata. Colour is associated with alpha as in the sample: a
//    sample flagged "oiio:UnassociatedAlpha" gives an un-associated result, so flagged.
//  - Deterministic: a seed gives bit-identical output whatever opt.nthreads is.
#pragma once

#include <texsyn/cascade.h>
#include <texsyn/choosy.h>
#include <texsyn/color.h>
#include <texsyn/error_text.h>
#include <texsyn/feature_scale.h>
#include <texsyn/fft.h>
#include <texsyn/fill.h>
#include <texsyn/histogram.h>
#include <texsyn/homogeneity.h>
#include <texsyn/image.h>
#include <texsyn/inputs.h>
#include <texsyn/io.h>
#include <texsyn/material.h>
#include <texsyn/memory.h>
#include <texsyn/methods.h>
#include <texsyn/mix.h>
#include <texsyn/neighborhood.h>
#include <texsyn/options.h>
#include <texsyn/patch.h>
#include <texsyn/pyramid.h>
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/random.h>
#include <texsyn/recipe.h>
#include <texsyn/run_controls.h>
#include <texsyn/search.h>
#include <texsyn/solid.h>
#include <texsyn/source_map.h>
#include <texsyn/stats.h>
#include <texsyn/stop.h>
#include <texsyn/subbands.h>
#include <texsyn/surface.h>
#include <texsyn/transfer.h>
#include <texsyn/version.h>
#include <texsyn/volume.h>
