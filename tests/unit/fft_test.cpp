// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <thread>
#include <vector>

#include <texsyn/fft.h>

using namespace texsyn;
using Cpx = std::complex<float>;

namespace {

std::vector<float> test_signal(int w, int h, unsigned seed)
{
    std::vector<float> v(size_t(w) * h);
    unsigned s = seed * 2654435761u + 1u;
    for (float& x : v) {
        s = s * 1664525u + 1013904223u;
        x = float(s >> 8) / float(1 << 24) * 2.0f - 1.0f;
    }
    return v;
}

std::unique_ptr<RealFft2D> plan(int w, int h, FftBackend b = FftBackend::Kiss)
{
    std::string error;
    auto p = RealFft2D::create(w, h, b, error);
    EXPECT_TRUE(p) << error;
    return p;
}

// The half spectrum by the definition, in double.
std::vector<std::complex<double>> naive_dft(const std::vector<float>& x, int w, int h)
{
    const int wc = w / 2 + 1;
    std::vector<std::complex<double>> out(size_t(h) * wc);
    for (int ky = 0; ky < h; ++ky)
        for (int kx = 0; kx < wc; ++kx) {
            std::complex<double> s = 0;
            for (int y = 0; y < h; ++y)
                for (int xx = 0; xx < w; ++xx) {
                    const double a = -2 * M_PI * (double(kx) * xx / w + double(ky) * y / h);
                    s += double(x[size_t(y) * w + xx])
                        * std::complex<double>(std::cos(a), std::sin(a));
                }
            out[size_t(ky) * wc + kx] = s;
        }
    return out;
}

const std::vector<std::pair<int, int>> small_sizes
    = { { 7, 5 }, { 8, 6 }, { 16, 16 }, { 5, 8 }, { 1, 4 }, { 4, 1 }, { 1, 1 }, { 3, 9 } };

std::vector<FftBackend> backends()
{
    std::vector<FftBackend> b = { FftBackend::Kiss };
    if (fft_backend_available(FftBackend::Fftw))
        b.push_back(FftBackend::Fftw);
    return b;
}

} // namespace

TEST(Fft, Names)
{
    EXPECT_STREQ(fft_backend_name(FftBackend::Kiss), "kiss");
    EXPECT_STREQ(fft_backend_name(FftBackend::Fftw), "fftw");
    EXPECT_TRUE(fft_backend_available(FftBackend::Kiss));
    std::string error;
    auto p = RealFft2D::create(8, 8, FftBackend::Fftw, error);
    EXPECT_EQ(bool(p), fft_backend_available(FftBackend::Fftw));
    if (!p) {
        EXPECT_NE(error.find("fftw"), std::string::npos) << error;
    }
}

TEST(Fft, RejectsBadSize)
{
    std::string error;
    EXPECT_FALSE(RealFft2D::create(0, 8, FftBackend::Kiss, error));
    EXPECT_NE(error.find("0x8"), std::string::npos);
}

TEST(Fft, MatchesNaiveDft)
{
    for (FftBackend b : backends())
        for (auto [w, h] : small_sizes) {
            auto p = plan(w, h, b);
            ASSERT_EQ(p->spectrum_size(), size_t(h) * (w / 2 + 1));
            const auto x = test_signal(w, h, unsigned(w * 31 + h));
            const auto ref = naive_dft(x, w, h);
            std::vector<Cpx> spec(p->spectrum_size());
            p->forward(x.data(), spec.data());
            for (size_t i = 0; i < spec.size(); ++i) {
                // Float FFT of a unit-range signal with <= 64 terms: rounding well under 1e-5.
                EXPECT_NEAR(spec[i].real(), ref[i].real(), 1e-5)
                    << fft_backend_name(b) << " " << w << "x" << h << " i=" << i;
                EXPECT_NEAR(spec[i].imag(), ref[i].imag(), 1e-5)
                    << fft_backend_name(b) << " " << w << "x" << h << " i=" << i;
            }
        }
}

TEST(Fft, RoundTrip)
{
    for (FftBackend b : backends())
        for (auto [w, h] : std::vector<std::pair<int, int>> {
                 { 7, 5 }, { 8, 6 }, { 16, 16 }, { 257, 131 }, { 640, 480 } }) {
            auto p = plan(w, h, b);
            const auto x = test_signal(w, h, 7);
            std::vector<Cpx> spec(p->spectrum_size());
            std::vector<float> y(x.size());
            p->forward(x.data(), spec.data());
            const std::vector<Cpx> kept = spec;
            p->inverse(spec.data(), y.data());
            EXPECT_EQ(spec, kept) << "inverse() must not modify its input";
            double err = 0;
            for (size_t i = 0; i < x.size(); ++i)
                err = std::max(err, double(std::abs(x[i] - y[i])));
            // Unit-range data through float FFTs: a few ulps times log2(size).
            EXPECT_LT(err, 2e-6) << fft_backend_name(b) << " " << w << "x" << h;
        }
}

TEST(Fft, Parseval)
{
    const int w = 37, h = 24;
    auto p = plan(w, h);
    const auto x = test_signal(w, h, 3);
    std::vector<Cpx> spec(p->spectrum_size());
    p->forward(x.data(), spec.data());
    double space = 0, freq = 0;
    for (float v : x)
        space += double(v) * v;
    const int wc = w / 2 + 1;
    for (int ky = 0; ky < h; ++ky)
        for (int kx = 0; kx < wc; ++kx) {
            // Columns 1..ceil(w/2)-1 stand for themselves and their mirror image.
            const bool mirrored = kx > 0 && 2 * kx != w;
            freq += (mirrored ? 2.0 : 1.0)
                * std::norm(std::complex<double>(spec[size_t(ky) * wc + kx]));
        }
    // Float rounding of ~900 terms.
    EXPECT_NEAR(freq / (double(w) * h), space, 1e-5 * space);
}

TEST(Fft, Linearity)
{
    const int w = 30, h = 17;
    auto p = plan(w, h);
    const auto a = test_signal(w, h, 1), b = test_signal(w, h, 2);
    std::vector<float> c(a.size());
    for (size_t i = 0; i < c.size(); ++i)
        c[i] = 2.0f * a[i] - 0.5f * b[i];
    std::vector<Cpx> sa(p->spectrum_size()), sb(sa.size()), sc(sa.size());
    p->forward(a.data(), sa.data());
    p->forward(b.data(), sb.data());
    p->forward(c.data(), sc.data());
    for (size_t i = 0; i < sc.size(); ++i)
        // Float rounding of spectra of magnitude up to ~sqrt(510).
        EXPECT_LT(std::abs(sc[i] - (2.0f * sa[i] - 0.5f * sb[i])), 2e-4f) << i;
}

TEST(Fft, ThreadCountIndependent)
{
    for (FftBackend b : backends())
        for (auto [w, h] : std::vector<std::pair<int, int>> { { 255, 97 }, { 256, 256 } }) {
            auto p = plan(w, h, b);
            const auto x = test_signal(w, h, 11);
            std::vector<Cpx> s1(p->spectrum_size()), s2(s1.size());
            std::vector<float> y1(x.size()), y2(x.size());
            p->forward(x.data(), s1.data(), 1);
            p->forward(x.data(), s2.data(), 2);
            EXPECT_EQ(s1, s2);
            p->inverse(s1.data(), y1.data(), 1);
            p->inverse(s1.data(), y2.data(), 2);
            EXPECT_EQ(y1, y2);
        }
}

TEST(Fft, ConcurrentCallsOnOnePlan)
{
    // Plans are immutable: calls from several threads at once give the serial result.
    for (FftBackend b : backends()) {
        const int w = 96, h = 75;
        auto p = plan(w, h, b);
        std::vector<std::vector<float>> in, out(4, std::vector<float>(size_t(w) * h));
        std::vector<std::vector<Cpx>> spec(4, std::vector<Cpx>(p->spectrum_size())), ref = spec;
        for (unsigned i = 0; i < 4; ++i) {
            in.push_back(test_signal(w, h, 100 + i));
            p->forward(in[i].data(), ref[i].data(), 1);
        }
        std::vector<std::thread> threads;
        for (size_t i = 0; i < 4; ++i)
            threads.emplace_back([&, i] {
                for (int rep = 0; rep < 20; ++rep) {
                    p->forward(in[i].data(), spec[i].data(), 1);
                    p->inverse(spec[i].data(), out[i].data(), 2);
                }
            });
        for (std::thread& t : threads)
            t.join();
        std::vector<float> back(out[0].size());
        for (size_t i = 0; i < 4; ++i) {
            EXPECT_EQ(spec[i], ref[i]) << fft_backend_name(b);
            p->inverse(ref[i].data(), back.data(), 1);
            EXPECT_EQ(out[i], back) << fft_backend_name(b);
        }
    }
}

TEST(Fft, InverseDropsNonHermitianParts)
{
    // A c2r transform reads only the real part of the self-conjugate bins (DC, Nyquist):
    // an imaginary part there must not leak into the output.
    const int w = 8, h = 6;
    for (FftBackend b : backends()) {
        auto p = plan(w, h, b);
        std::vector<Cpx> spec(p->spectrum_size(), Cpx(0.0f));
        spec[0] = Cpx(48.0f, 5.0f);
        spec[w / 2] = Cpx(0.0f, 7.0f);
        spec[3 * (w / 2 + 1)] = Cpx(0.0f, -3.0f);
        std::vector<float> y(size_t(w) * h);
        p->inverse(spec.data(), y.data());
        for (float v : y)
            EXPECT_NEAR(v, 1.0f, 1e-6) << fft_backend_name(b); // float rounding
    }
}

// TEXSYN_HAVE_FFTW is private to the library, so the test asks at run time.
TEST(Fft, FftwAgreesWithKiss)
{
    if (!fft_backend_available(FftBackend::Fftw))
        GTEST_SKIP() << "built without FFTW";
    for (auto [w, h] : std::vector<std::pair<int, int>> { { 7, 5 }, { 64, 48 }, { 257, 131 } }) {
        auto k = plan(w, h, FftBackend::Kiss), f = plan(w, h, FftBackend::Fftw);
        const auto x = test_signal(w, h, 5);
        std::vector<Cpx> sk(k->spectrum_size()), sf(sk.size());
        k->forward(x.data(), sk.data());
        f->forward(x.data(), sf.data());
        double scale = std::sqrt(double(w) * h), err = 0;
        for (size_t i = 0; i < sk.size(); ++i)
            err = std::max(err, double(std::abs(sk[i] - sf[i])));
        // Two float FFTs of unit-range noise: differences at the rounding level of |X| ~ sqrt(N).
        EXPECT_LT(err, 1e-5 * scale) << w << "x" << h;
    }
}

// Prime and prime-factor lengths go through Bluestein's algorithm in the KissFFT backend:
// it must agree with the direct DFT like any other length.
TEST(Fft, PrimeSizesMatchNaiveDft)
{
    for (auto [w, h] : { std::pair<int, int> { 97, 61 }, { 74, 131 }, { 113, 2 } }) {
        std::string error;
        auto fft = RealFft2D::create(w, h, FftBackend::Kiss, error);
        ASSERT_TRUE(fft) << error;
        std::vector<float> x(size_t(w) * h);
        for (size_t i = 0; i < x.size(); ++i)
            x[i] = float(std::sin(0.37 * double(i)) + 0.25 * std::cos(1.3 * double(i * i % 17)));
        std::vector<std::complex<float>> spec(fft->spectrum_size());
        fft->forward(x.data(), spec.data());
        double worst = 0.0, scale = 0.0;
        const int wc = w / 2 + 1;
        for (int ky = 0; ky < h; ++ky)
            for (int kx = 0; kx < wc; ++kx) {
                std::complex<double> sum = 0.0;
                for (int y = 0; y < h; ++y)
                    for (int xx = 0; xx < w; ++xx) {
                        const double a = -2.0 * M_PI * (double(kx) * xx / w + double(ky) * y / h);
                        sum += double(x[size_t(y) * w + xx])
                            * std::complex<double>(std::cos(a), std::sin(a));
                    }
                worst = std::max(
                    worst, std::abs(sum - std::complex<double>(spec[size_t(ky) * wc + kx])));
                scale = std::max(scale, std::abs(sum));
            }
        // float transforms of length ~100 (two of length 256 for Bluestein): ~1e-6 relative
        EXPECT_LT(worst / scale, 1e-5) << w << "x" << h;
        std::vector<float> back(x.size());
        fft->inverse(spec.data(), back.data());
        for (size_t i = 0; i < x.size(); ++i)
            ASSERT_NEAR(back[i], x[i], 1e-5f) << w << "x" << h;
    }
}
