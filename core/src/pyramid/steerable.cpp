// SPDX-License-Identifier: Apache-2.0
// Fourier-domain steerable pyramid (Simoncelli & Freeman 1995; notes/pyramid-math.md).
// Level s is ceil(w/2^s) x ceil(h/2^s). A spectrum index k means k cycles per image at
// every level, so level s evaluates its masks at the true frequencies w = 2 pi k 2^s / size0,
// and the crop to level s+1 keeps exactly the signed indices |k| < size_{s+1}/2, which hold
// all of L(r) Y (L vanishes for r >= pi/2). That makes cropping exact for any size, and
// zero-padding its inverse.
#include <texsyn/pyramid.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <new>

#include <OpenImageIO/parallel.h>

#include "image/parallel_pvt.h"

namespace texsyn {
namespace {

using Cpx = std::complex<float>;
constexpr double pi = 3.14159265358979323846;

// L(r): one-octave raised-cosine transition in log2 r between pi/4 and pi/2.
double lowpass_profile(double r)
{
    if (r <= pi / 4)
        return 1.0;
    if (r >= pi / 2)
        return 0.0;
    return std::cos(pi / 2 * std::log2(4 * r / pi));
}

// H(r) = sqrt(1 - L(r)^2), so that L^2 + H^2 = 1.
double highpass_profile(double r)
{
    const double l = lowpass_profile(r);
    return std::sqrt(std::max(0.0, 1.0 - l * l));
}

// alpha_K = 2^(K-1) (K-1)! / sqrt(K (2(K-1))!), which makes sum_k |G_k|^2 = 1.
double orientation_gain(int K)
{
    auto factorial = [](int n) {
        double f = 1.0;
        for (int i = 2; i <= n; ++i)
            f *= i;
        return f;
    };
    return std::ldexp(factorial(K - 1), K - 1) / std::sqrt(K * factorial(2 * (K - 1)));
}

// i - n when i is past the middle: the signed frequency of DFT index i.
int signed_index(int i, int n)
{
    return 2 * i <= n ? i : i - n;
}

// Runs f(begin, end) over [0, n) in parallel; each index is written by one task only.
template <class F>
void for_ranges(size_t n, int nthreads, F&& f)
{
    OIIO::parallel_for_range(
        int64_t(0), int64_t(n), [&](int64_t b, int64_t e) { f(size_t(b), size_t(e)); },
        detail::split_every_item(nthreads));
}

class SteerablePyramid final : public Pyramid {
public:
    SteerablePyramid(int width, int height, int scales, int orientations, FftBackend fft)
        : Pyramid(width, height)
        , m_norient(orientations)
    {
        // (-i)^(K-1): makes every oriented band real in space.
        const Cpx phases[4] = { { 1, 0 }, { 0, -1 }, { -1, 0 }, { 0, 1 } };
        m_phase = phases[(orientations - 1) % 4];
        std::string error;
        int w = width, h = height;
        for (int s = 0; s <= scales; ++s) {
            Level lv;
            lv.w = w;
            lv.h = h;
            lv.fft = RealFft2D::create(w, h, fft, error);
            if (!lv.fft)
                throw std::bad_alloc(); // the backend was checked by the factory
            if (s < scales)
                make_masks(lv, s);
            m_levels.push_back(std::move(lv));
            w = (w + 1) / 2;
            h = (h + 1) / 2;
        }
        for (int s = 0; s < scales; ++s)
            make_crop(s);
        m_names.push_back("highpass");
        for (int s = 0; s < scales; ++s)
            for (int k = 0; k < orientations; ++k)
                m_names.push_back("s" + std::to_string(s) + ".o" + std::to_string(k));
        m_names.push_back("lowpass");
    }

    void build(const Plane& image, std::vector<Plane>& bands, int nthreads) const override
    {
        assert(image.width() == m_width && image.height() == m_height);
        bands.resize(m_names.size());
        const size_t n0 = m_levels[0].fft->spectrum_size();
        std::vector<Cpx> y(n0), t(n0), next(n0);
        m_levels[0].fft->forward(image.data(), y.data(), nthreads);
        for_ranges(n0, nthreads, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i) {
                t[i] = m_hi0[i] * y[i];
                y[i] *= m_lo0[i];
            }
        });
        inverse(0, t, bands[0], nthreads);
        size_t band = 1;
        const int scales = int(m_levels.size()) - 1;
        for (int s = 0; s < scales; ++s) {
            const Level& lv = m_levels[s];
            const size_t n = lv.fft->spectrum_size();
            for (int k = 0; k < m_norient; ++k) {
                const float* g = lv.oriented[size_t(k)].data();
                for_ranges(n, nthreads, [&](size_t b, size_t e) {
                    for (size_t i = b; i < e; ++i)
                        t[i] = (m_phase * g[i]) * y[i];
                });
                inverse(s, t, bands[band++], nthreads);
            }
            const Crop& c = m_crops[size_t(s)];
            std::fill_n(next.begin(), m_levels[s + 1].fft->spectrum_size(), Cpx(0.0f));
            for_ranges(c.src.size(), nthreads, [&](size_t b, size_t e) {
                for (size_t p = b; p < e; ++p)
                    next[c.dst[p]] = c.down[p] * y[c.src[p]];
            });
            std::swap(y, next);
        }
        inverse(scales, y, bands[band], nthreads);
    }

    void collapse(const std::vector<Plane>& bands, Plane& image, int nthreads) const override
    {
        assert(bands.size() == m_names.size());
        const int scales = int(m_levels.size()) - 1;
        const size_t n0 = m_levels[0].fft->spectrum_size();
        std::vector<Cpx> y(n0), t(n0), acc(n0);
        forward(scales, bands.back(), y, nthreads);
        const Cpx conj_phase = std::conj(m_phase);
        for (int s = scales - 1; s >= 0; --s) {
            const Level& lv = m_levels[s];
            const size_t n = lv.fft->spectrum_size();
            const Crop& c = m_crops[size_t(s)];
            std::fill_n(acc.begin(), n, Cpx(0.0f));
            for_ranges(c.src.size(), nthreads, [&](size_t b, size_t e) {
                for (size_t p = b; p < e; ++p)
                    acc[c.src[p]] = c.up[p] * y[c.dst[p]];
            });
            for (int k = 0; k < m_norient; ++k) {
                forward(s, bands[1 + size_t(s) * m_norient + k], t, nthreads);
                const float* g = lv.oriented[size_t(k)].data();
                for_ranges(n, nthreads, [&](size_t b, size_t e) {
                    for (size_t i = b; i < e; ++i)
                        acc[i] += (conj_phase * g[i]) * t[i];
                });
            }
            std::swap(y, acc);
        }
        forward(0, bands[0], t, nthreads);
        for_ranges(n0, nthreads, [&](size_t b, size_t e) {
            for (size_t i = b; i < e; ++i)
                y[i] = m_lo0[i] * y[i] + m_hi0[i] * t[i];
        });
        if (image.width() != m_width || image.height() != m_height)
            image = Plane(m_width, m_height);
        m_levels[0].fft->inverse(y.data(), image.data(), nthreads);
    }

    void transform_bands(Plane& image, std::vector<Plane>& bands, const BandFunction& modify,
        int nthreads, const StopFlag* stop) const override
    {
        assert(image.width() == m_width && image.height() == m_height);
        const int scales = int(m_levels.size()) - 1;
        const int nbands = int(m_names.size());
        bands.resize(size_t(nbands));

        WorkspaceLease lease(*this);
        Workspace& ws = lease.get();

        // The low-pass spectrum of every level (cheap: one transform, then crops).
        std::vector<std::vector<Cpx>>& lows = ws.lows;
        lows.resize(size_t(scales) + 1);
        std::vector<Cpx>& x = ws.x;
        x.resize(m_levels[0].fft->spectrum_size());
        m_levels[0].fft->forward(image.data(), x.data(), nthreads);
        lows[0].resize(x.size());
        for (size_t i = 0; i < x.size(); ++i)
            lows[0][i] = m_lo0[i] * x[i];
        for (int s = 0; s < scales; ++s) {
            const Crop& c = m_crops[size_t(s)];
            lows[size_t(s) + 1].assign(m_levels[size_t(s) + 1].fft->spectrum_size(), Cpx(0.0f));
            for (size_t p = 0; p < c.src.size(); ++p)
                lows[size_t(s) + 1][c.dst[p]] = c.down[p] * lows[size_t(s)][c.src[p]];
        }

        // Per band, on one thread: mask, inverse transform, modify, forward transform, adjoint
        // mask. Each band's contribution is kept apart so the sum below has a fixed order.
        const Cpx conj_phase = std::conj(m_phase);
        std::vector<std::vector<Cpx>>& contrib = ws.contrib;
        contrib.resize(size_t(nbands));
        auto process = [&](int b) {
            const int s = band_level(b, scales);
            const Level& lv = m_levels[size_t(s)];
            const size_t n = lv.fft->spectrum_size();
            std::vector<Cpx>& t = contrib[size_t(b)];
            t.resize(n);
            if (b == 0) {
                for (size_t i = 0; i < n; ++i)
                    t[i] = m_hi0[i] * x[i];
            } else if (b == nbands - 1) {
                t = lows[size_t(scales)];
            } else {
                const float* g = lv.oriented[size_t((b - 1) % m_norient)].data();
                for (size_t i = 0; i < n; ++i)
                    t[i] = (m_phase * g[i]) * lows[size_t(s)][i];
            }
            inverse(s, t, bands[size_t(b)], 1);
            modify(b, bands[size_t(b)]);
            forward(s, bands[size_t(b)], t, 1);
            if (b > 0 && b < nbands - 1) {
                const float* g = lv.oriented[size_t((b - 1) % m_norient)].data();
                for (size_t i = 0; i < n; ++i)
                    t[i] = (conj_phase * g[i]) * t[i];
            }
        };
        // One task per band (chunk size 1), largest first, taken by whichever thread is free:
        // bands differ 4x in size per level, so equal static chunks would not balance.
        OIIO::parallel_for_chunked(
            int64_t(0), int64_t(nbands), int64_t(1),
            [&](int64_t b, int64_t) {
                if (!stop_requested(stop))
                    process(int(b));
            },
            detail::split_every_item(nthreads));
        if (stop_requested(stop))
            return;

        // Collapse, adding the contributions in the order collapse() does.
        std::vector<Cpx>& y = ws.y;
        std::vector<Cpx>& acc = ws.acc;
        y.swap(contrib[size_t(nbands) - 1]);
        for (int s = scales - 1; s >= 0; --s) {
            const Crop& c = m_crops[size_t(s)];
            acc.assign(m_levels[size_t(s)].fft->spectrum_size(), Cpx(0.0f));
            for (size_t p = 0; p < c.src.size(); ++p)
                acc[c.src[p]] = c.up[p] * y[c.dst[p]];
            for (int k = 0; k < m_norient; ++k) {
                const std::vector<Cpx>& t = contrib[1 + size_t(s) * m_norient + size_t(k)];
                for (size_t i = 0; i < acc.size(); ++i)
                    acc[i] += t[i];
            }
            std::swap(y, acc);
        }
        const std::vector<Cpx>& hi = contrib[0];
        for (size_t i = 0; i < y.size(); ++i)
            y[i] = m_lo0[i] * y[i] + m_hi0[i] * hi[i];
        m_levels[0].fft->inverse(y.data(), image.data(), nthreads);
    }

private:
    // Spectra that transform_bands needs per call (tens of MB at 1024^2). Reusing them
    // avoids page-faulting fresh memory on every iteration; concurrent calls each lease
    // their own.
    struct Workspace {
        std::vector<std::vector<Cpx>> lows, contrib;
        std::vector<Cpx> x, y, acc;
    };
    class WorkspaceLease {
    public:
        explicit WorkspaceLease(const SteerablePyramid& pyr)
            : m_pyr(pyr)
        {
            std::lock_guard<std::mutex> lock(pyr.m_workspace_mutex);
            if (pyr.m_workspaces.empty()) {
                m_ws = std::make_unique<Workspace>();
            } else {
                m_ws = std::move(pyr.m_workspaces.back());
                pyr.m_workspaces.pop_back();
            }
        }
        ~WorkspaceLease()
        {
            std::lock_guard<std::mutex> lock(m_pyr.m_workspace_mutex);
            m_pyr.m_workspaces.push_back(std::move(m_ws));
        }
        WorkspaceLease(const WorkspaceLease&) = delete;
        WorkspaceLease& operator=(const WorkspaceLease&) = delete;
        Workspace& get() { return *m_ws; }

    private:
        const SteerablePyramid& m_pyr;
        std::unique_ptr<Workspace> m_ws;
    };

    // The pyramid level whose size band b has.
    int band_level(int b, int scales) const
    {
        if (b == 0)
            return 0;
        if (b == 1 + scales * m_norient)
            return scales;
        return (b - 1) / m_norient;
    }

    struct Level {
        int w = 0, h = 0;
        std::unique_ptr<RealFft2D> fft;
        std::vector<std::vector<float>> oriented; // H(r) alpha cos(theta - pi k/K)^(K-1)
    };
    // Level s -> s+1: spectrum index pairs of the kept window, with L(r) and the DFT
    // normalisation folded in (down = L N_{s+1}/N_s, up = L N_s/N_{s+1}).
    struct Crop {
        std::vector<uint32_t> src, dst;
        std::vector<float> down, up;
    };

    void inverse(int s, const std::vector<Cpx>& spectrum, Plane& out, int nthreads) const
    {
        const Level& lv = m_levels[size_t(s)];
        if (out.width() != lv.w || out.height() != lv.h)
            out = Plane(lv.w, lv.h);
        lv.fft->inverse(spectrum.data(), out.data(), nthreads);
    }

    void forward(int s, const Plane& in, std::vector<Cpx>& spectrum, int nthreads) const
    {
        assert(in.width() == m_levels[size_t(s)].w && in.height() == m_levels[size_t(s)].h);
        m_levels[size_t(s)].fft->forward(in.data(), spectrum.data(), nthreads);
    }

    // Radian frequency of half-spectrum index (kx, row) at level s (height h), from the
    // level-0 size.
    void frequency(int s, int h, int kx, int row, double& wx, double& wy) const
    {
        const double scale = 2 * pi * std::ldexp(1.0, s);
        wx = scale * kx / m_width;
        wy = scale * signed_index(row, h) / m_height;
    }

    void make_masks(Level& lv, int s)
    {
        const int wc = lv.w / 2 + 1;
        const size_t n = size_t(wc) * size_t(lv.h);
        const double alpha = orientation_gain(m_norient);
        const bool odd = (m_norient - 1) % 2 == 1;
        std::vector<double> cos_k(static_cast<size_t>(m_norient)), sin_k(cos_k.size());
        for (int k = 0; k < m_norient; ++k) {
            cos_k[size_t(k)] = std::cos(pi * k / m_norient);
            sin_k[size_t(k)] = std::sin(pi * k / m_norient);
        }
        lv.oriented.assign(size_t(m_norient), std::vector<float>(n));
        if (s == 0) {
            m_hi0.resize(n);
            m_lo0.resize(n);
        }
        // Serial: make_steerable_pyramid is given no thread count.
        for (int row = 0; row < lv.h; ++row) {
            for (int kx = 0; kx < wc; ++kx) {
                double wx, wy;
                frequency(s, lv.h, kx, row, wx, wy);
                const double r = std::hypot(wx, wy);
                const double hi = highpass_profile(r);
                // cos(theta - pi k/K) from the unit vector; theta = atan2(0, 0) = 0 at DC.
                const double ux = r > 0 ? wx / r : 1.0, uy = r > 0 ? wy / r : 0.0;
                const size_t i = size_t(row) * wc + kx;
                // A bin that is its own conjugate (DC, Nyquist) must get a real mask,
                // else c2r would drop half of it: the imaginary G_k is zeroed there
                // (L(r) Y already vanishes at every Nyquist bin).
                const bool self_conj = (kx == 0 || 2 * kx == lv.w) && (row == 0 || 2 * row == lv.h);
                for (int k = 0; k < m_norient; ++k) {
                    const double c = ux * cos_k[size_t(k)] + uy * sin_k[size_t(k)];
                    double g = alpha;
                    for (int e = 1; e < m_norient; ++e)
                        g *= c;
                    lv.oriented[size_t(k)][i] = (odd && self_conj) ? 0.0f : float(hi * g);
                }
                if (s == 0) {
                    m_hi0[i] = float(highpass_profile(r / 2));
                    m_lo0[i] = float(lowpass_profile(r / 2));
                }
            }
        }
    }

    void make_crop(int s)
    {
        const Level& a = m_levels[size_t(s)];
        const Level& b = m_levels[size_t(s) + 1];
        const int wca = a.w / 2 + 1, wcb = b.w / 2 + 1;
        const double ratio = (double(b.w) * b.h) / (double(a.w) * a.h);
        Crop c;
        // Signed indices |k| < size_{s+1}/2: symmetric about zero, so the crop commutes
        // with conjugation and every kept index is unique at both sizes.
        const int kx_max = (b.w - 1) / 2, ky_max = (b.h - 1) / 2;
        for (int ky = -ky_max; ky <= ky_max; ++ky) {
            const int ra = ky < 0 ? ky + a.h : ky, rb = ky < 0 ? ky + b.h : ky;
            for (int kx = 0; kx <= kx_max; ++kx) {
                double wx, wy;
                frequency(s, a.h, kx, ra, wx, wy);
                const double l = lowpass_profile(std::hypot(wx, wy));
                c.src.push_back(uint32_t(size_t(ra) * wca + kx));
                c.dst.push_back(uint32_t(size_t(rb) * wcb + kx));
                c.down.push_back(float(l * ratio));
                c.up.push_back(float(l / ratio));
            }
        }
        m_crops.push_back(std::move(c));
    }

    int m_norient;
    Cpx m_phase;
    std::vector<Level> m_levels;     // scales + 1: the last one only for the low-pass
    std::vector<Crop> m_crops;       // scales
    std::vector<float> m_hi0, m_lo0; // the first split, H(r/2) and L(r/2), at level 0
    mutable std::mutex m_workspace_mutex;
    mutable std::vector<std::unique_ptr<Workspace>> m_workspaces;
};

} // namespace

std::unique_ptr<Pyramid> make_steerable_pyramid(
    int width, int height, int scales, int orientations, FftBackend fft, std::string& error)
{
    if (!fft_backend_available(fft)) {
        error = std::string("steerable pyramid: FFT backend '") + fft_backend_name(fft)
            + "' is not built into this texsyn";
        return nullptr;
    }
    if (orientations < 1 || orientations > 8) {
        error = "steerable pyramid: orientations=" + std::to_string(orientations)
            + " is out of range (1 to 8)";
        return nullptr;
    }
    if (scales < 1 || scales > 30 || width < (1 << scales) || height < (1 << scales)) {
        error = "steerable pyramid: scales=" + std::to_string(scales) + " does not fit a "
            + std::to_string(width) + "x" + std::to_string(height)
            + " image (need scales >= 1 and width, height >= 2^scales)";
        return nullptr;
    }
    try {
        return std::make_unique<SteerablePyramid>(width, height, scales, orientations, fft);
    } catch (const std::bad_alloc&) {
        error = "steerable pyramid: out of memory for a " + std::to_string(width) + "x"
            + std::to_string(height) + " image";
        return nullptr;
    }
}

} // namespace texsyn
