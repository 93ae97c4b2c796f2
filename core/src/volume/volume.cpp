// SPDX-License-Identifier: Apache-2.0
#include <texsyn/volume.h>

#include <algorithm>
#include <cassert>
#include <cstdio>

namespace texsyn {

Volume::Volume(int width, int height, int depth, float value)
    : m_voxels(width, height * depth, value)
    , m_height(height)
    , m_depth(depth)
{ }

Volume::Volume(Plane voxels, int height, int depth)
    : m_voxels(std::move(voxels))
    , m_height(height)
    , m_depth(depth)
{
    assert(m_voxels.height() == height * depth);
}

const char* slice_axis_name(SliceAxis axis)
{
    return axis == SliceAxis::X ? "x" : axis == SliceAxis::Y ? "y" : "z";
}

int slice_count(const Volume& v, SliceAxis axis)
{
    return axis == SliceAxis::X ? v.width() : axis == SliceAxis::Y ? v.height() : v.depth();
}

namespace {

// Calls f(slice row, volume offset of the row's first voxel, stride between the row's
// voxels) for every row of slice `index`.
template <class F>
void for_slice_rows(const Volume& v, SliceAxis axis, int index, F&& f)
{
    const size_t w = size_t(v.width()), h = size_t(v.height());
    for (int r = 0; r < (axis == SliceAxis::Z ? v.height() : v.depth()); ++r) {
        if (axis == SliceAxis::Z)
            f(r, (size_t(index) * h + size_t(r)) * w, size_t(1));
        else if (axis == SliceAxis::Y)
            f(r, (size_t(r) * h + size_t(index)) * w, size_t(1));
        else
            f(r, size_t(r) * h * w + size_t(index), w);
    }
}

} // namespace

void extract_slice(const Volume& v, SliceAxis axis, int index, Plane& out)
{
    assert(index >= 0 && index < slice_count(v, axis));
    const int sw = axis == SliceAxis::X ? v.height() : v.width();
    const int sh = axis == SliceAxis::Z ? v.height() : v.depth();
    if (out.width() != sw || out.height() != sh)
        out = Plane(sw, sh);
    const float* src = v.data();
    for_slice_rows(v, axis, index, [&](int r, size_t offset, size_t stride) {
        float* dst = out.row(r);
        for (int i = 0; i < sw; ++i)
            dst[i] = src[offset + size_t(i) * stride];
    });
}

void add_slice(const Plane& slice, SliceAxis axis, int index, Volume& v)
{
    assert(index >= 0 && index < slice_count(v, axis));
    float* dst = v.data();
    for_slice_rows(v, axis, index, [&](int r, size_t offset, size_t stride) {
        const float* src = slice.row(r);
        for (int i = 0; i < slice.width(); ++i)
            dst[offset + size_t(i) * stride] += src[i];
    });
}

void swap_voxel_planes(PlanarVolume& v, PlanarImage& img)
{
    img.channels.resize(v.channels.size());
    for (size_t c = 0; c < v.channels.size(); ++c)
        std::swap(img.channels[c], v.channels[c].voxels());
}

std::string volume_exr_part_name(int z, int depth)
{
    int digits = 4;
    for (int d = std::max(depth - 1, 0); d >= 10000; d /= 10)
        ++digits;
    char buf[32];
    std::snprintf(buf, sizeof(buf), "z%0*d", digits, z);
    return buf;
}

} // namespace texsyn
