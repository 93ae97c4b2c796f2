// SPDX-License-Identifier: Apache-2.0
// Burt & Adelson Laplacian pyramid with the separable (1,4,6,4,1)/16 kernel.
#include <texsyn/pyramid.h>

#include <algorithm>
#include <cassert>
#include <new>

#include <OpenImageIO/parallel.h>

namespace texsyn {
namespace {

constexpr float kernel[5] = { 1.0f, 4.0f, 6.0f, 4.0f, 1.0f };

// A 1-D resampling along one axis: out[i] = sum_t weight[i][t] * in[index[i][t]] / divisor[i],
// five taps per output. Integer weights and one division keep constants exact.
struct Taps {
    static constexpr int ntaps = 5;
    std::vector<int> index;
    std::vector<float> weight;
    std::vector<float> divisor;
    int size() const { return int(divisor.size()); }
};

// Blur then keep the even samples: ceil(n/2) outputs.
Taps reduce_taps(int n, Boundary b)
{
    Taps t;
    for (int i = 0; i < (n + 1) / 2; ++i) {
        for (int k = 0; k < Taps::ntaps; ++k) {
            t.index.push_back(wrap_coordinate(2 * i + k - 2, n, b));
            t.weight.push_back(kernel[k]);
        }
        t.divisor.push_back(16.0f);
    }
    return t;
}

// Insert zeros up to n samples, blur, and scale by the kernel weight that fell on the
// inserted samples. That weight is 8/16 everywhere (the usual x2 per axis) except where a
// circular odd size puts two coarse samples side by side across the seam; normalising
// there too keeps constants constant. Reconstruction is exact either way, since bands are
// differences.
Taps expand_taps(int n, Boundary b)
{
    Taps t;
    for (int x = 0; x < n; ++x) {
        float sum = 0.0f;
        for (int k = 0; k < Taps::ntaps; ++k) {
            const int j = wrap_coordinate(x + k - 2, n, b);
            const bool hit = j % 2 == 0;
            t.index.push_back(hit ? j / 2 : 0);
            t.weight.push_back(hit ? kernel[k] : 0.0f);
            sum += hit ? kernel[k] : 0.0f;
        }
        t.divisor.push_back(sum);
    }
    return t;
}

// Resamples rows (x) with tx and columns (y) with ty: out is tx.size() x ty.size().
void resample(const Plane& in, const Taps& tx, const Taps& ty, Plane& out, int nthreads)
{
    const int w = tx.size(), h = ty.size();
    Plane tmp(w, in.height());
    OIIO::parallel_for_range(
        int64_t(0), int64_t(in.height()),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y) {
                const float* src = in.row(int(y));
                float* dst = tmp.row(int(y));
                for (int x = 0; x < w; ++x) {
                    const int* idx = &tx.index[size_t(x) * Taps::ntaps];
                    const float* wt = &tx.weight[size_t(x) * Taps::ntaps];
                    float s = 0.0f;
                    for (int k = 0; k < Taps::ntaps; ++k)
                        s += wt[k] * src[idx[k]];
                    dst[x] = s / tx.divisor[size_t(x)];
                }
            }
        },
        OIIO::paropt(nthreads));
    if (out.width() != w || out.height() != h)
        out = Plane(w, h);
    OIIO::parallel_for_range(
        int64_t(0), int64_t(h),
        [&](int64_t begin, int64_t end) {
            for (int64_t y = begin; y < end; ++y) {
                const int* idx = &ty.index[size_t(y) * Taps::ntaps];
                const float* wt = &ty.weight[size_t(y) * Taps::ntaps];
                float* dst = out.row(int(y));
                std::fill(dst, dst + w, 0.0f);
                for (int k = 0; k < Taps::ntaps; ++k) {
                    const float* src = tmp.row(idx[k]);
                    for (int x = 0; x < w; ++x)
                        dst[x] += wt[k] * src[x];
                }
                const float d = ty.divisor[size_t(y)];
                for (int x = 0; x < w; ++x)
                    dst[x] /= d;
            }
        },
        OIIO::paropt(nthreads));
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
        bands.resize(m_names.size());
        Plane g = image, next, up;
        for (size_t s = 0; s < m_levels.size(); ++s) {
            const Level& lv = m_levels[s];
            resample(g, lv.reduce_x, lv.reduce_y, next, nthreads);
            resample(next, lv.expand_x, lv.expand_y, up, nthreads);
            for (size_t i = 0; i < g.size(); ++i)
                g.data()[i] -= up.data()[i];
            bands[s] = std::move(g);
            g = std::move(next);
            next = Plane();
        }
        bands.back() = std::move(g);
    }

    void collapse(const std::vector<Plane>& bands, Plane& image, int nthreads) const override
    {
        assert(bands.size() == m_names.size());
        Plane g = bands.back(), up;
        for (size_t s = m_levels.size(); s-- > 0;) {
            const Level& lv = m_levels[s];
            resample(g, lv.expand_x, lv.expand_y, up, nthreads);
            const Plane& band = bands[s];
            assert(band.width() == up.width() && band.height() == up.height());
            for (size_t i = 0; i < up.size(); ++i)
                up.data()[i] += band.data()[i];
            std::swap(g, up);
        }
        image = std::move(g);
    }

private:
    struct Level {
        Taps reduce_x, reduce_y; // this level -> the next (coarser) one
        Taps expand_x, expand_y; // the next level -> this one
    };
    std::vector<Level> m_levels;
};

} // namespace

std::unique_ptr<Pyramid> make_laplacian_pyramid(
    int width, int height, int scales, Boundary boundary)
{
    if (scales < 1 || scales > 30 || width < (1 << scales) || height < (1 << scales))
        return nullptr;
    try {
        return std::make_unique<LaplacianPyramid>(width, height, scales, boundary);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}

} // namespace texsyn
