// SPDX-License-Identifier: Apache-2.0
// FFTW backend (only built with -DTEXSYN_WITH_FFTW=ON). Plans are made once with
// FFTW_ESTIMATE (deterministic) under one mutex, since FFTW's planner is not thread-safe,
// and run with the new-array execute functions, which are. FFTW_UNALIGNED lets them run on
// any caller buffer. Each call is single-threaded: `nthreads` does not change the result.
#include "fft/fft_pvt.h"

#include <mutex>
#include <new>
#include <vector>

#include <fftw3.h>

namespace texsyn {
namespace {

using Cpx = std::complex<float>;

std::mutex& planner_mutex()
{
    static std::mutex m;
    return m;
}

class FftwFft2D final : public RealFft2D {
public:
    FftwFft2D(int width, int height)
        : RealFft2D(width, height)
    {
        std::lock_guard<std::mutex> lock(planner_mutex());
        float* real = fftwf_alloc_real(size_t(width) * size_t(height));
        fftwf_complex* spec = fftwf_alloc_complex(spectrum_size());
        const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
        if (real && spec) {
            m_r2c = fftwf_plan_dft_r2c_2d(height, width, real, spec, flags);
            m_c2r = fftwf_plan_dft_c2r_2d(height, width, spec, real, flags);
        }
        fftwf_free(real);
        fftwf_free(spec);
        if (!m_r2c || !m_c2r) {
            destroy();
            throw std::bad_alloc();
        }
    }
    ~FftwFft2D() override
    {
        std::lock_guard<std::mutex> lock(planner_mutex());
        destroy();
    }

    void forward(const float* in, Cpx* out, int) const override
    {
        // An out-of-place r2c plan preserves its input, so the const_cast is safe.
        fftwf_execute_dft_r2c(m_r2c, const_cast<float*>(in), reinterpret_cast<fftwf_complex*>(out));
    }

    void inverse(const Cpx* in, float* out, int) const override
    {
        // c2r overwrites its input: work on a per-thread copy.
        thread_local std::vector<Cpx> copy;
        copy.assign(in, in + spectrum_size());
        fftwf_execute_dft_c2r(m_c2r, reinterpret_cast<fftwf_complex*>(copy.data()), out);
        const float scale = float(1.0 / (double(m_width) * double(m_height)));
        const size_t n = size_t(m_width) * size_t(m_height);
        for (size_t i = 0; i < n; ++i)
            out[i] *= scale;
    }

private:
    void destroy()
    {
        if (m_r2c)
            fftwf_destroy_plan(m_r2c);
        if (m_c2r)
            fftwf_destroy_plan(m_c2r);
        m_r2c = m_c2r = nullptr;
    }

    fftwf_plan m_r2c = nullptr;
    fftwf_plan m_c2r = nullptr;
};

} // namespace

std::unique_ptr<RealFft2D> make_fftw_fft(int width, int height)
{
    return std::make_unique<FftwFft2D>(width, height);
}

} // namespace texsyn
