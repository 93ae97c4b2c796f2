// SPDX-License-Identifier: Apache-2.0
// KissFFT backend. Only the complex kiss_fft is used: with distinct input and output its
// cfg is read-only, so one plan serves concurrent calls (kiss_fftr keeps a scratch buffer
// in its cfg, and kiss_fftndr crashes). Real rows are transformed in pairs as one complex
// FFT of x = a + i b; columns of the half spectrum are gathered in blocks so that each
// complex FFT runs on contiguous memory.
#include "fft/fft_pvt.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include <OpenImageIO/parallel.h>
#include <dlfcn.h>
#include <kiss_fft.h>

#include "image/parallel_pvt.h"

namespace texsyn {
namespace {

using Cpx = std::complex<float>;
static_assert(sizeof(kiss_fft_cpx) == sizeof(Cpx), "kiss_fft_cpx must be two floats");

// Columns per gather block: 16 complex values are two cache lines of each row.
constexpr int64_t column_block = 16;

// KissFFT's entry points. texsyn does not link libkissfft but loads it here with
// RTLD_DEEPBIND, so that its own internal calls (kiss_fft -> kiss_fft_stride, ...) bind to
// itself: libcodec2, which ffmpeg and so OIIO load, bundles another kissfft, and where
// texsyn is loaded late — as a plugin of stock oiiotool — every kiss_* symbol would
// otherwise resolve to that copy, whose different rounding broke bit-identical results.
struct KissApi {
    decltype(&kiss_fft_alloc) alloc = nullptr;
    decltype(&kiss_fft) fft = nullptr;
};

// Sanitizer runtimes refuse RTLD_DEEPBIND (google/sanitizers#611): sanitizer builds
// (scripts/sanitize.sh) load KissFFT without it, and so do not guard against the clash.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TEXSYN_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define TEXSYN_SANITIZED 1
#endif
#endif
#ifdef TEXSYN_SANITIZED
constexpr int deep_bind = 0;
#else
constexpr int deep_bind = RTLD_DEEPBIND;
#endif

const KissApi& kiss_api()
{
    static const KissApi api = [] {
        KissApi a;
        const int flags = RTLD_NOW | RTLD_LOCAL | deep_bind;
        void* lib = dlopen(TEXSYN_KISSFFT_SONAME, flags);
        if (!lib)
            lib = dlopen(TEXSYN_KISSFFT_FILE, flags);
        if (lib) {
            a.alloc = reinterpret_cast<decltype(&kiss_fft_alloc)>(dlsym(lib, "kiss_fft_alloc"));
            a.fft = reinterpret_cast<decltype(&kiss_fft)>(dlsym(lib, "kiss_fft"));
        }
        return a;
    }();
    if (!api.alloc || !api.fft)
        throw std::runtime_error(
            std::string("cannot load KissFFT (") + TEXSYN_KISSFFT_SONAME + ")");
    return api;
}

// A complex FFT of length n (unnormalised, either direction). KissFFT handles the factors
// 2, 3, 4 and 5 with fast butterflies but any other prime factor p with an O(p) generic
// one, so a prime length costs O(n^2): a 1009-wide row took 10x as long as a 1024-wide
// one. Such lengths go through Bluestein's chirp-z algorithm instead: the transform
// becomes a circular convolution of a 5-smooth length m >= 2n - 1, done with two KissFFTs
// of length m.
class KissCfg {
public:
    KissCfg(int n, bool inverse)
        : m_n(n)
    {
        if (!use_bluestein(n)) {
            m_direct = make_cfg(n, inverse);
            return;
        }
        m_m = bluestein_length(n);
        m_forward_m = make_cfg(m_m, false);
        m_inverse_m = make_cfg(m_m, true);
        // Chirp w_k = exp(-+ i pi k^2 / n); k^2 is reduced mod 2n so the angle stays exact.
        const double sign = inverse ? 1.0 : -1.0;
        m_chirp.resize(size_t(n));
        for (int64_t k = 0; k < n; ++k) {
            const double angle = sign * M_PI * double((k * k) % (2 * int64_t(n))) / n;
            m_chirp[size_t(k)] = Cpx(float(std::cos(angle)), float(std::sin(angle)));
        }
        // The convolution kernel conj(w_k) at k and m - k, transformed once; 1/m folded in.
        std::vector<Cpx> b(size_t(m_m), Cpx(0.0f));
        for (int k = 0; k < n; ++k) {
            b[size_t(k)] = std::conj(m_chirp[size_t(k)]) / float(m_m);
            if (k > 0)
                b[size_t(m_m - k)] = b[size_t(k)];
        }
        m_kernel.resize(size_t(m_m));
        kiss_api().fft(m_forward_m.get(), as_kiss(b.data()), as_kiss(m_kernel.data()));
    }

    void run(const Cpx* in, Cpx* out) const
    {
        if (m_n == 1) { // kiss_fft's generic radix path is not meant for n = 1
            out[0] = in[0];
            return;
        }
        if (m_direct) {
            kiss_api().fft(m_direct.get(), as_kiss(in), as_kiss(out));
            return;
        }
        thread_local std::vector<Cpx> scratch;
        if (scratch.size() < 2 * size_t(m_m))
            scratch.resize(2 * size_t(m_m));
        Cpx* a = scratch.data();
        Cpx* fa = a + m_m;
        for (int k = 0; k < m_n; ++k)
            a[k] = in[k] * m_chirp[size_t(k)];
        std::fill(a + m_n, a + m_m, Cpx(0.0f));
        kiss_api().fft(m_forward_m.get(), as_kiss(a), as_kiss(fa));
        for (int k = 0; k < m_m; ++k)
            fa[k] *= m_kernel[size_t(k)];
        kiss_api().fft(m_inverse_m.get(), as_kiss(fa), as_kiss(a));
        for (int k = 0; k < m_n; ++k)
            out[k] = a[k] * m_chirp[size_t(k)];
    }

private:
    struct CfgFree {
        void operator()(kiss_fft_cfg cfg) const { kiss_fft_free(cfg); }
    };
    using Cfg = std::unique_ptr<std::remove_pointer_t<kiss_fft_cfg>, CfgFree>;

    static Cfg make_cfg(int n, bool inverse)
    {
        Cfg cfg(kiss_api().alloc(n, inverse ? 1 : 0, nullptr, nullptr));
        if (!cfg)
            throw std::bad_alloc();
        return cfg;
    }
    static kiss_fft_cpx* as_kiss(Cpx* p) { return reinterpret_cast<kiss_fft_cpx*>(p); }
    static const kiss_fft_cpx* as_kiss(const Cpx* p)
    {
        return reinterpret_cast<const kiss_fft_cpx*>(p);
    }

    // Sum of the prime factors of n, with multiplicity: KissFFT's cost is ~n times this.
    static int64_t prime_factor_sum(int64_t n)
    {
        int64_t sum = 0;
        for (int64_t p = 2; p * p <= n; ++p)
            while (n % p == 0) {
                sum += p;
                n /= p;
            }
        return n > 1 ? sum + n : sum;
    }

    // The convolution length: the smallest m >= 2n - 1 whose factors are 2, 3 and 5, which
    // KissFFT has fast butterflies for.
    static int bluestein_length(int n)
    {
        for (int64_t m = 2 * int64_t(n) - 1;; ++m) {
            int64_t r = m;
            for (int64_t p : { 2, 3, 5 })
                while (r % p == 0)
                    r /= p;
            if (r == 1)
                return int(m);
        }
    }

    // Bluestein when KissFFT's direct cost exceeds that of the two length-m transforms.
    static bool use_bluestein(int n)
    {
        if (n < 2)
            return false;
        const int64_t m = bluestein_length(n);
        return int64_t(n) * prime_factor_sum(n) > 2 * m * prime_factor_sum(m);
    }

    int m_n;
    Cfg m_direct;
    int m_m = 0;
    Cfg m_forward_m, m_inverse_m;
    std::vector<Cpx> m_chirp, m_kernel;
};

// Per-thread task scratch, grown on demand. Tasks never wait on other tasks while they
// hold it, so it cannot be re-entered.
Cpx* task_scratch(size_t n)
{
    thread_local std::vector<Cpx> buffer;
    if (buffer.size() < n)
        buffer.resize(n);
    return buffer.data();
}

// The inverse's intermediate spectrum, held across parallel loops: a thread that runs
// another call's tasks while it waits must not reuse it, hence the busy flag.
class SpectrumScratch {
public:
    explicit SpectrumScratch(size_t n)
        : m_shared(shared())
    {
        if (m_shared.busy) {
            m_own.resize(n);
            m_data = m_own.data();
            return;
        }
        m_shared.busy = true;
        m_owner = true;
        if (m_shared.data.size() < n)
            m_shared.data.resize(n);
        m_data = m_shared.data.data();
    }
    ~SpectrumScratch()
    {
        if (m_owner)
            m_shared.busy = false;
    }
    SpectrumScratch(const SpectrumScratch&) = delete;
    SpectrumScratch& operator=(const SpectrumScratch&) = delete;
    Cpx* data() { return m_data; }

private:
    struct Shared {
        std::vector<Cpx> data;
        bool busy = false;
    };
    static Shared& shared()
    {
        thread_local Shared s;
        return s;
    }
    Shared& m_shared;
    std::vector<Cpx> m_own;
    Cpx* m_data = nullptr;
    bool m_owner = false;
};

class KissFft2D final : public RealFft2D {
public:
    KissFft2D(int width, int height)
        : RealFft2D(width, height)
        , m_row_fwd(width, false)
        , m_row_inv(width, true)
        , m_col_fwd(height, false)
        , m_col_inv(height, true)
    { }

    void forward(const float* in, Cpx* out, int nthreads) const override
    {
        const int64_t w = m_width, wc = w / 2 + 1;
        for_row_pairs(nthreads, [&](int64_t y0, bool pair, Cpx* z, Cpx* zf) {
            const float* a = in + y0 * w;
            const float* b = a + w;
            for (int64_t x = 0; x < w; ++x)
                z[x] = Cpx(a[x], pair ? b[x] : 0.0f);
            m_row_fwd.run(z, zf);
            // Split Z = A + iB using A(k) = (Z(k) + conj Z(-k))/2, B(k) = (Z(k) - conj
            // Z(-k))/2i.
            Cpx* oa = out + y0 * wc;
            Cpx* ob = oa + wc;
            for (int64_t k = 0; k < wc; ++k) {
                const Cpx zk = zf[k];
                const Cpx zc = std::conj(zf[k == 0 ? 0 : w - k]);
                oa[k] = 0.5f * (zk + zc);
                if (pair)
                    ob[k] = Cpx(0.5f * (zk.imag() - zc.imag()), -0.5f * (zk.real() - zc.real()));
            }
        });
        columns(out, out, m_col_fwd, nthreads);
    }

    void inverse(const Cpx* in, float* out, int nthreads) const override
    {
        const int64_t w = m_width, h = m_height, wc = w / 2 + 1;
        SpectrumScratch work(spectrum_size());
        Cpx* spec = work.data();
        columns(in, spec, m_col_inv, nthreads);
        const float scale = float(1.0 / (double(w) * double(h)));
        for_row_pairs(nthreads, [&](int64_t y0, bool pair, Cpx* z, Cpx* zf) {
            const Cpx* a = spec + y0 * wc;
            const Cpx* b = a + wc;
            // Z = A + iB over the full row from the Hermitian halves; the imaginary
            // parts of the self-conjugate bins (DC, even-width Nyquist) are dropped,
            // as a c2r transform does.
            z[0] = Cpx(a[0].real(), pair ? b[0].real() : 0.0f);
            for (int64_t k = 1; k < wc; ++k) {
                const Cpx ak = a[k];
                const Cpx bk = pair ? b[k] : Cpx(0.0f);
                if (2 * k == w) {
                    z[k] = Cpx(ak.real(), bk.real());
                    continue;
                }
                z[k] = Cpx(ak.real() - bk.imag(), ak.imag() + bk.real());
                z[w - k] = Cpx(ak.real() + bk.imag(), bk.real() - ak.imag());
            }
            m_row_inv.run(z, zf);
            float* oa = out + y0 * w;
            float* ob = oa + w;
            for (int64_t x = 0; x < w; ++x)
                oa[x] = zf[x].real() * scale;
            if (pair)
                for (int64_t x = 0; x < w; ++x)
                    ob[x] = zf[x].imag() * scale;
        });
    }

private:
    // Calls f(y0, pair, z, zf) for rows y0 = 0, 2, 4, …, in parallel: rows y0 and y0 + 1 (if
    // pair) share one complex FFT of length width; z and zf are per-task scratch of that
    // length.
    template <class F>
    void for_row_pairs(int nthreads, F&& f) const
    {
        const int64_t w = m_width, h = m_height;
        OIIO::parallel_for_range(
            int64_t(0), (h + 1) / 2,
            [&](int64_t begin, int64_t end) {
                Cpx* z = task_scratch(2 * size_t(w));
                for (int64_t p = begin; p < end; ++p)
                    f(2 * p, 2 * p + 1 < h, z, z + w);
            },
            detail::split_every_item(nthreads));
    }

    // Complex FFT of every column of a half spectrum; src may equal dst (each block reads
    // all of its columns before writing them).
    void columns(const Cpx* src, Cpx* dst, const KissCfg& cfg, int nthreads) const
    {
        const int64_t h = m_height, wc = m_width / 2 + 1;
        const int64_t nblocks = (wc + column_block - 1) / column_block;
        OIIO::parallel_for_range(
            int64_t(0), nblocks,
            [&](int64_t begin, int64_t end) {
                Cpx* gathered = task_scratch(2 * size_t(column_block * h));
                Cpx* result = gathered + column_block * h;
                for (int64_t blk = begin; blk < end; ++blk) {
                    const int64_t c0 = blk * column_block;
                    const int64_t nc = std::min(column_block, wc - c0);
                    for (int64_t y = 0; y < h; ++y) {
                        const Cpx* s = src + y * wc + c0;
                        for (int64_t c = 0; c < nc; ++c)
                            gathered[c * h + y] = s[c];
                    }
                    for (int64_t c = 0; c < nc; ++c)
                        cfg.run(gathered + c * h, result + c * h);
                    for (int64_t y = 0; y < h; ++y) {
                        Cpx* d = dst + y * wc + c0;
                        for (int64_t c = 0; c < nc; ++c)
                            d[c] = result[c * h + y];
                    }
                }
            },
            detail::split_every_item(nthreads));
    }

    KissCfg m_row_fwd, m_row_inv, m_col_fwd, m_col_inv;
};

} // namespace

std::unique_ptr<RealFft2D> make_kiss_fft(int width, int height)
{
    return std::make_unique<KissFft2D>(width, height);
}

} // namespace texsyn
