// SPDX-License-Identifier: Apache-2.0
// nanoflann's dataset and distance concepts over row-major float points, for the kd-trees of
// the search back-ends (kdtree_index.cpp) and of choosy sampling (choosy/dynamic_kdtree.cpp).
// Include only from those .cpp files: nanoflann is a large header.
#pragma once

#include <cstddef>
#include <cstdint>

#include <nanoflann.hpp>

#include "distance_pvt.h"

namespace texsyn::detail {

/// Points per kd-tree leaf (nanoflann's default is 10).
constexpr size_t kLeafSize = 10;

/// nanoflann's dataset concept: `count` points of `dim` floats, row-major.
struct ReducedPoints {
    const float* data = nullptr;
    size_t count = 0;
    int dim = 0;

    size_t kdtree_get_point_count() const { return count; }
    float kdtree_get_pt(uint32_t i, int32_t d) const
    {
        return data[size_t(i) * size_t(dim) + size_t(d)];
    }
    template <class BoundingBox>
    bool kdtree_get_bbox(BoundingBox&) const
    {
        return false;
    }
};

/// nanoflann's distance concept: squared L2 with the kernel every back-end uses.
struct ReducedMetric {
    using ElementType = float;
    using DistanceType = float;

    const ReducedPoints& points;

    explicit ReducedMetric(const ReducedPoints& p)
        : points(p)
    { }

    float evalMetric(const float* a, uint32_t b, size_t size) const
    {
        return distance2(a, points.data + size_t(b) * size_t(points.dim), int(size));
    }
    template <typename U, typename V>
    float accum_dist(U a, V b, size_t) const
    {
        return (a - b) * (a - b);
    }
};

/// A static kd-tree over ReducedPoints (built by its constructor).
using NanoflannTree
    = nanoflann::KDTreeSingleIndexAdaptor<ReducedMetric, ReducedPoints, -1, uint32_t>;

} // namespace texsyn::detail
