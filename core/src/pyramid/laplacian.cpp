// SPDX-License-Identifier: Apache-2.0
// Burt & Adelson Laplacian pyramid with the separable (1,4,6,4,1)/16 kernel.
#include <texsyn/pyramid.h>

#include <algorithm>
#include <cassert>
#include <new>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "laplacian_taps_pvt.h"

namespace texsyn {
namespace {

using detail::expand_taps;
using detail::reduce_taps;
using detail::Taps;

// Resamples rows (x) with tx and columns (y) with ty: out is tx.size() x ty.size().
void resample(const Plane& in, const Taps& tx, const Taps& ty, Plane& out, int nthreads)
{
    const int w = tx.size(), h = ty.size();
    Plane tmp(w, in.height());
    OIIO::parallel_for_range(
        int64_t(0), int64_t(in.height()),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y)
                detail::filter_row(in.row(int(y)), tx, tmp.row(int(y)));
        },
        detail::split_every_item(nthreads));
    if (out.width() != w || out.height() != h)
        out = Plane(w, h);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(h),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y)
                detail::filter_rows(tmp.data(), size_t(w), ty, int(y), out.row(int(y)));
        },
        detail::split_every_item(nthreads));
}

class LaplacianPyramid final : public Pyramid {
public:
    LaplacianPyramid(int width, int height, int scales, Boundary boundary)
        : Pyramid(width, height)
    {
        int w = width, h = height;
        for (int s = 0; s < scales; ++s) {
            m_levels.push_back({ reduce_taps(w, boundary), reduce_taps(h, boundary),
                expand_taps(w, boundary), expand_taps(h, boundary) });
            m_names.push_back("L" + std::to_string(s));
            w = (w + 1) / 2;
            h = (h + 1) / 2;
        }
        m_names.push_back("lowpass");
    }

    void build(const Plane& image, std::vector<Plane>& bands, int nthreads) const override
    {
        assert(image.width() == m_width && image.height() == m_height);
        detail::laplacian_build(
            image, m_levels.size(), bands,
            [&](size_t s, const Plane& in, Plane& out) {
                resample(in, m_levels[s].reduce_x, m_levels[s].reduce_y, out, nthreads);
            },
            [&](size_t s, const Plane& in, Plane& out) { expand(s, in, out, nthreads); });
    }

    void collapse(const std::vector<Plane>& bands, Plane& image, int nthreads) const override
    {
        assert(bands.size() == m_names.size());
        detail::laplacian_collapse(bands, m_levels.size(), image,
            [&](size_t s, const Plane& in, Plane& out) { expand(s, in, out, nthreads); });
    }

private:
    struct Level {
        Taps reduce_x, reduce_y; // this level -> the next (coarser) one
        Taps expand_x, expand_y; // the next level -> this one
    };
    std::vector<Level> m_levels;

    void expand(size_t s, const Plane& in, Plane& out, int nthreads) const
    {
        resample(in, m_levels[s].expand_x, m_levels[s].expand_y, out, nthreads);
    }
};

} // namespace

Plane reduce_plane(const Plane& image, Boundary boundary, int nthreads)
{
    Plane out;
    resample(image, reduce_taps(image.width(), boundary), reduce_taps(image.height(), boundary),
        out, nthreads);
    return out;
}

Plane expand_plane(const Plane& coarse, int width, int height, Boundary boundary, int nthreads)
{
    Plane out;
    resample(coarse, expand_taps(width, boundary), expand_taps(height, boundary), out, nthreads);
    return out;
}

std::vector<std::vector<Plane>> gaussian_pyramid(
    const std::vector<Plane>& channels, int nlevels, Boundary boundary, int nthreads)
{
    std::vector<std::vector<Plane>> levels(size_t(std::max(nlevels, 1)));
    levels[0] = channels;
    for (size_t l = 1; l < levels.size(); ++l)
        for (const Plane& p : levels[l - 1])
            levels[l].push_back(reduce_plane(p, boundary, nthreads));
    return levels;
}

std::unique_ptr<Pyramid> make_laplacian_pyramid(
    int width, int height, int scales, Boundary boundary, std::string& error)
{
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (scales < 1 || scales > 30 || width < (1 << scales) || height < (1 << scales)) {
        error = "Laplacian pyramid: scales=" + std::to_string(scales) + " does not fit a " + size
            + " image (need scales >= 1 and width, height >= 2^scales)";
        return nullptr;
    }
    try {
        return std::make_unique<LaplacianPyramid>(width, height, scales, boundary);
    } catch (const std::bad_alloc&) {
        error = "Laplacian pyramid: out of memory for a " + size + " image";
        return nullptr;
    }
}

} // namespace texsyn
