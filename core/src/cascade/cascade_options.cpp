// SPDX-License-Identifier: Apache-2.0
// The cascade's options: table and validation.
#include <texsyn/cascade.h>

#include "methods/common_options_pvt.h"

#include <algorithm>
#include <cmath>

namespace texsyn {

const OptionTable<CascadeOptions>& CascadeOptions::table()
{
    return declared_table<CascadeOptions>([](OptionTable<CascadeOptions>& t) {
        using O = CascadeOptions;
        using K = CascadeKernel;
        constexpr size_t max_levels = 12;
        // Looks found by trying; each sets every option that matters to it, and options
        // after it override (docs/cascade.md shows them).
        t.preset("preset",
            { { "cells",
                  "reference=256:levels=1:kernel=dog7:map=logistic:r=3.9:iterations=5:"
                  "ramp=0.05,0.03,0.02,0.6,0.45,0.3" },
                { "blotches",
                    "reference=256:levels=4:kernel=gauss5:map=sine:r=3.9,3.8,3.6,3.4:noise=0,0.1:"
                    "iterations=4:ramp=0.1,0.12,0.1,0.9,0.88,0.85" },
                { "fibres",
                    "reference=256:levels=3:kernel=aniso7:angle=25:map=logistic:r=3.7:iterations=5:"
                    "ramp=0.15,0.07,0.03,0.55,0.33,0.16" },
                { "bands",
                    "reference=256:levels=5:kernel=gauss7:map=tent:r=3.2:iterations=3:noise=0,0.15:"
                    "ramp=0.05,0.1,0.03,0.3,0.4,0.15" },
                { "caustics",
                    "reference=256:levels=2:kernel=dog5:map=sine:r=4:iterations=8:"
                    "ramp=0.01,0.05,0.15,0.6,0.8,0.9" },
                { "stone",
                    "reference=256:levels=3:kernel=box3:map=curve:curve=0,0,0.45,1,0.55,1,1,0:"
                    "iterations=6:ramp=0.2,0.1,0.05,0.7,0.5,0.35" } },
            "a named look (cells, blotches, fibres, bands, caustics, stone) setting the "
            "options below; options after it override it");
        t.size("size", &O::width, &O::height, detail::max_image_side,
            "512x512, or the input image's size",
            "output size WxH (default: 512x512 for a generator, the input image's size for a "
            "transfer)");
        t.integer("levels", &O::levels, 1, int(max_levels),
            "cascade levels, coarsest first; each doubles the size (1 = a single level)");
        t.integers("iterations", &O::iterations, 1, 100, max_levels,
            "iterations of A <- p(N(A)) per level, coarsest first (a missing level repeats the "
            "last value)");
        t.choices("map", &O::map,
            { { "logistic", CascadeMap::Logistic }, { "sine", CascadeMap::Sine },
                { "tent", CascadeMap::Tent }, { "cubic", CascadeMap::Cubic },
                { "curve", CascadeMap::Curve } },
            max_levels,
            "the pointwise map p per level, coarsest first: logistic r x(1-x), sine r/4 sin(pi x), "
            "tent r/4 (1-|2x-1|), "
            "cubic (peak r/4), or curve (piecewise linear through `curve`)");
        t.numbers("r", &O::r, 0.0f, 4.0f, max_levels, "none",
            "the map's parameter per level, coarsest first: its peak value is r/4");
        t.numbers("curve", &O::curve, 0.0f, 1.0f, 64, "none",
            "map=curve: x0,y0,x1,y1,... with x increasing (at least 2 points)");
        t.choices("kernel", &O::kernel,
            { { "box3", K::Box3 }, { "box5", K::Box5 }, { "box7", K::Box7 },
                { "gauss3", K::Gauss3 }, { "gauss5", K::Gauss5 }, { "gauss7", K::Gauss7 },
                { "dog5", K::Dog5 }, { "dog7", K::Dog7 }, { "aniso5", K::Aniso5 },
                { "aniso7", K::Aniso7 }, { "custom", K::Custom } },
            max_levels,
            "the convolution N per level, coarsest first: box, Gaussian (sigma size/4), dog "
            "(Mexican hat), aniso "
            "(Gaussian stretched along `angle`) of side 3, 5 or 7, or custom (`weights`)");
        t.numbers("angle", &O::angle, -360.0f, 360.0f, max_levels, "none",
            "aniso kernels: direction in degrees, per level, coarsest first");
        t.odd_integer("ksize", &O::ksize, 1, 7, "kernel=custom: side of the kernel");
        t.numbers("weights", &O::weights, -100.0f, 100.0f, 49, "none",
            "kernel=custom: ksize x ksize weights, row by row (normalised to sum 1)");
        t.numbers("noise", &O::noise, 0.0f, 1.0f, max_levels, "none",
            "per level after the first, coarsest first: weight of fresh noise mixed into the "
            "upsampled previous level");
        t.real("dmin", &O::dmin, 0.0f, 16.0f, "kernel dilation where the control image is 0");
        t.real("dmax", &O::dmax, 0.0f, 16.0f, "kernel dilation where the control image is 1");
        t.choice("transfer", &O::transfer,
            { { "luminance", CascadeTransfer::Luminance },
                { "channels", CascadeTransfer::Channels } },
            "with an input image: its luminance or each of its channels is the initial "
            "lattice");
        t.real("scale", &O::scale, 0.25f, 16.0f,
            "feature size multiplier: the lattice runs at the output's size divided by it (and "
            "by size/reference), then is resampled to the output");
        t.integer("reference", &O::reference, 0, detail::max_image_side,
            "the shorter side at which features have the kernel's size in pixels; other sizes "
            "scale them with the image (0 = fixed in pixels; every preset sets 256)");
        t.numbers("ramp", &O::ramp, 0.0f, 1000.0f, 3 * 64, "none",
            "colour ramp: r,g,b triples (scene-linear), evenly spaced from value 0 to 1 "
            "(default: the grey lattice, one channel)");
    });
}

bool CascadeOptions::validate(std::string& error) const
{
    if (!table().check(*this, error))
        return false;
    const auto& t = table();
    for (const char* name : { "iterations", "map", "r", "kernel", "angle", "noise" }) {
        const OptionField& f = *t.find(name);
        const std::string shown = f.format(this);
        const size_t count = size_t(std::count(shown.begin(), shown.end(), ',')) + 1;
        if (!check_level_list(name, shown, shown == f.none ? 0 : count, levels, error))
            return false;
    }
    if (std::find(map.begin(), map.end(), CascadeMap::Curve) != map.end()) {
        if (curve.size() < 4 || curve.size() % 2 != 0) {
            error = option_error("curve", format_number_list(curve),
                "map=curve needs x0,y0,x1,y1,... with at least 2 points (got "
                    + std::to_string(curve.size()) + " values)");
            return false;
        }
        for (size_t k = 2; k < curve.size(); k += 2)
            if (!(curve[k] > curve[k - 2])) {
                error = option_error("curve", format_number_list(curve), "x must increase");
                return false;
            }
    }
    if (std::find(kernel.begin(), kernel.end(), CascadeKernel::Custom) != kernel.end()) {
        if (weights.size() != size_t(ksize * ksize)) {
            error = option_error("weights", format_number_list(weights),
                "kernel=custom with ksize=" + std::to_string(ksize) + " needs "
                    + std::to_string(ksize * ksize) + " weights (got "
                    + std::to_string(weights.size()) + ")");
            return false;
        }
        double sum = 0;
        for (float w : weights)
            sum += w;
        if (std::abs(sum) < 1e-6) {
            error = option_error(
                "weights", format_number_list(weights), "sum to 0 (they are normalised to sum 1)");
            return false;
        }
    }
    if (!ramp.empty() && (ramp.size() % 3 != 0 || ramp.size() < 6)) {
        error = option_error("ramp", format_number_list(ramp),
            "needs r,g,b triples, at least two colours (got " + std::to_string(ramp.size())
                + " values)");
        return false;
    }
    return true;
}

} // namespace texsyn
