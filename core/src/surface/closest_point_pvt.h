// SPDX-License-Identifier: Apache-2.0
// The point of a triangle closest to a point, in the plane (UV bakes) or in space (closest
// points on a mesh).
#pragma once

#include <OpenImageIO/Imath.h>

namespace texsyn::detail {

/// Ericson, Real-Time Collision Detection §5.1.5: the point of triangle abc closest to p,
/// with its barycentric coordinates (for a, b, c) in `bary`. V is Imath::V2d or V3d; the
/// triangle must have non-zero area.
template <class V>
V closest_on_triangle(const V& p, const V& a, const V& b, const V& c, Imath::V3d& bary)
{
    const V ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab ^ ap, d2 = ac ^ ap;
    if (d1 <= 0 && d2 <= 0) {
        bary = Imath::V3d(1, 0, 0);
        return a;
    }
    const V bp = p - b;
    const double d3 = ab ^ bp, d4 = ac ^ bp;
    if (d3 >= 0 && d4 <= d3) {
        bary = Imath::V3d(0, 1, 0);
        return b;
    }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double v = d1 / (d1 - d3);
        bary = Imath::V3d(1 - v, v, 0);
        return a + v * ab;
    }
    const V cp = p - c;
    const double d5 = ab ^ cp, d6 = ac ^ cp;
    if (d6 >= 0 && d5 <= d6) {
        bary = Imath::V3d(0, 0, 1);
        return c;
    }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double w = d2 / (d2 - d6);
        bary = Imath::V3d(1 - w, 0, w);
        return a + w * ac;
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        bary = Imath::V3d(0, 1 - w, w);
        return b + w * (c - b);
    }
    const double denom = 1 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    bary = Imath::V3d(1 - v - w, v, w);
    return a + v * ab + w * ac;
}

} // namespace texsyn::detail
