// SPDX-License-Identifier: Apache-2.0
// The Burt & Adelson Laplacian pyramid in three dimensions, circular along every axis
// (Heeger & Bergen 1995 §4).
#include <texsyn/pyramid.h>

#include <cassert>
#include <new>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

#include "laplacian_taps_pvt.h"

namespace texsyn {
namespace {

using detail::Taps;

// Resamples along x with tx, y with ty and z with tz: out is tx.size() x ty.size() x
// tz.size(). Each pass runs over independent rows or slabs, so the split over threads never
// changes a value.
void resample(
    const Volume& in, const Taps& tx, const Taps& ty, const Taps& tz, Volume& out, int nthreads)
{
    const int w = tx.size(), h = ty.size(), d = tz.size();
    const int ih = in.height(), id = in.depth();
    Volume along_x(w, ih, id);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(ih) * id,
        [&](int64_t begin, int64_t end) {
            for (int64_t r = begin; r < end; ++r)
                detail::filter_row(in.data() + size_t(r) * size_t(in.width()), tx,
                    along_x.data() + size_t(r) * size_t(w));
        },
        detail::split_every_item(nthreads));
    Volume along_y(w, h, id);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(h) * id,
        [&](int64_t begin, int64_t end) {
            for (int64_t r = begin; r < end; ++r) {
                const int z = int(r / h), y = int(r % h);
                detail::filter_rows(
                    along_x.slab(z), size_t(w), ty, y, along_y.slab(z) + size_t(y) * size_t(w));
            }
        },
        detail::split_every_item(nthreads));
    if (out.width() != w || out.height() != h || out.depth() != d)
        out = Volume(w, h, d);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(d),
        [&](int64_t begin, int64_t end) {
            for (int64_t z = begin; z < end; ++z)
                detail::filter_rows(
                    along_y.data(), size_t(w) * size_t(h), tz, int(z), out.slab(int(z)));
        },
        detail::split_every_item(nthreads));
}

class LaplacianPyramid3D final : public VolumePyramid {
public:
    LaplacianPyramid3D(int width, int height, int depth, int scales)
        : VolumePyramid(width, height, depth)
    {
        const Boundary b = Boundary::Circular;
        int w = width, h = height, d = depth;
        for (int s = 0; s < scales; ++s) {
            m_levels.push_back({ { detail::reduce_taps(w, b), detail::reduce_taps(h, b),
                                     detail::reduce_taps(d, b) },
                { detail::expand_taps(w, b), detail::expand_taps(h, b),
                    detail::expand_taps(d, b) } });
            m_names.push_back("L" + std::to_string(s));
            w = (w + 1) / 2;
            h = (h + 1) / 2;
            d = (d + 1) / 2;
        }
        m_names.push_back("lowpass");
    }

    void build(const Volume& volume, std::vector<Volume>& bands, int nthreads) const override
    {
        assert(
            volume.width() == m_width && volume.height() == m_height && volume.depth() == m_depth);
        detail::laplacian_build(
            volume, m_levels.size(), bands,
            [&](size_t s, const Volume& in, Volume& out) {
                apply(m_levels[s].reduce, in, out, nthreads);
            },
            [&](size_t s, const Volume& in, Volume& out) {
                apply(m_levels[s].expand, in, out, nthreads);
            });
    }

    void collapse(const std::vector<Volume>& bands, Volume& volume, int nthreads) const override
    {
        assert(bands.size() == m_names.size());
        detail::laplacian_collapse(
            bands, m_levels.size(), volume, [&](size_t s, const Volume& in, Volume& out) {
                apply(m_levels[s].expand, in, out, nthreads);
            });
    }

private:
    struct Axes {
        Taps x, y, z;
    };
    struct Level {
        Axes reduce; // this level -> the next (coarser) one
        Axes expand; // the next level -> this one
    };
    std::vector<Level> m_levels;

    static void apply(const Axes& a, const Volume& in, Volume& out, int nthreads)
    {
        resample(in, a.x, a.y, a.z, out, nthreads);
    }
};

} // namespace

std::unique_ptr<VolumePyramid> make_laplacian_pyramid_3d(
    int width, int height, int depth, int scales, std::string& error)
{
    const std::string size
        = std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(depth);
    if (scales < 1 || scales > 30 || width < (1 << scales) || height < (1 << scales)
        || depth < (1 << scales)) {
        error = "3-D Laplacian pyramid: scales=" + std::to_string(scales) + " does not fit a "
            + size + " volume (need scales >= 1 and every side >= 2^scales)";
        return nullptr;
    }
    try {
        return std::make_unique<LaplacianPyramid3D>(width, height, depth, scales);
    } catch (const std::bad_alloc&) {
        error = "3-D Laplacian pyramid: out of memory for a " + size + " volume";
        return nullptr;
    }
}

} // namespace texsyn
