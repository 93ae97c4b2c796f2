// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <tuple>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

#include <texsyn/pyramid.h>

using namespace texsyn;

namespace {

constexpr double pi = 3.14159265358979323846;

// Smooth structure plus deterministic noise, in [0, 1]-ish.
Plane test_image(int w, int h, unsigned seed = 1)
{
    Plane p(w, h);
    unsigned s = seed * 2654435761u + 12345u;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            s = s * 1664525u + 1013904223u;
            const float noise = float(s >> 8) / float(1 << 24);
            p(x, y) = 0.5f + 0.25f * std::sin(0.11f * x + 0.05f * y) + 0.3f * (noise - 0.5f);
        }
    return p;
}

// max |a - b| / (max b - min b)
double relative_error(const Plane& a, const Plane& b)
{
    double err = 0, lo = b.data()[0], hi = b.data()[0];
    for (size_t i = 0; i < b.size(); ++i) {
        err = std::max(err, double(std::abs(a.data()[i] - b.data()[i])));
        lo = std::min(lo, double(b.data()[i]));
        hi = std::max(hi, double(b.data()[i]));
    }
    return err / (hi - lo);
}

double energy(const Plane& p)
{
    double e = 0;
    for (size_t i = 0; i < p.size(); ++i)
        e += double(p.data()[i]) * p.data()[i];
    return e;
}

std::vector<FftBackend> backends()
{
    std::vector<FftBackend> b = { FftBackend::Kiss };
    if (fft_backend_available(FftBackend::Fftw))
        b.push_back(FftBackend::Fftw);
    return b;
}

std::unique_ptr<Pyramid> steerable(
    int w, int h, int scales, int orientations, FftBackend fft = FftBackend::Kiss)
{
    std::string error;
    auto p = make_steerable_pyramid(w, h, scales, orientations, fft, error);
    EXPECT_TRUE(p) << error;
    return p;
}

// cos(2 pi (fx x / w + fy y / h)): fx, fy whole cycles per image, so it is periodic.
Plane sinusoid(int w, int h, double fx, double fy, double amplitude = 1.0)
{
    Plane p(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            p(x, y) = float(amplitude * std::cos(2 * pi * (fx * x / w + fy * y / h)));
    return p;
}

} // namespace

TEST(Pyramid, Names)
{
    EXPECT_STREQ(pyramid_kind_name(PyramidKind::Steerable), "steerable");
    EXPECT_STREQ(pyramid_kind_name(PyramidKind::Laplacian), "laplacian");
}

TEST(Pyramid, MaxScales)
{
    EXPECT_EQ(max_pyramid_scales(128, 128), 4);
    EXPECT_EQ(max_pyramid_scales(256, 256), 5);
    EXPECT_EQ(max_pyramid_scales(143, 500), 4);
    EXPECT_EQ(max_pyramid_scales(15, 15), 0);
    EXPECT_EQ(max_pyramid_scales(16, 300), 1);
    EXPECT_EQ(max_pyramid_scales(1024, 1024), 7);
    EXPECT_EQ(max_pyramid_scales(0, 10), 0);
}

// ---- Laplacian ---------------------------------------------------------------------------

namespace {

// A Laplacian plan the test expects to be made.
std::unique_ptr<Pyramid> laplacian(int width, int height, int scales, Boundary boundary)
{
    std::string error;
    auto pyr = make_laplacian_pyramid(width, height, scales, boundary, error);
    EXPECT_TRUE(pyr) << error;
    return pyr;
}

std::unique_ptr<VolumePyramid> laplacian_3d(int width, int height, int depth, int scales)
{
    std::string error;
    auto pyr = make_laplacian_pyramid_3d(width, height, depth, scales, error);
    EXPECT_TRUE(pyr) << error;
    return pyr;
}

// Runs `make` in this (forked) process with the address space limited to what it uses now
// plus 256 MB, prints the message `make` leaves and exits with 0 if it made no plan.
template <class Make>
[[noreturn]] void exit_without_memory(Make&& make)
{
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t limit = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (rlim_t(256) << 20);
    const struct rlimit rl = { limit, limit };
    setrlimit(RLIMIT_AS, &rl);
    std::string error;
    const bool made = make(error);
    std::fprintf(stderr, "%s\n", error.c_str());
    std::exit(made ? 1 : 0);
}

} // namespace

TEST(Laplacian, RejectsBadArgumentsWithAMessage)
{
    std::string error;
    EXPECT_FALSE(make_laplacian_pyramid(64, 64, 0, Boundary::Circular, error));
    EXPECT_EQ(error,
        "Laplacian pyramid: scales=0 does not fit a 64x64 image (need scales >= 1 and width, "
        "height >= 2^scales)");
    EXPECT_FALSE(make_laplacian_pyramid(64, 7, 3, Boundary::Circular, error));
    EXPECT_TRUE(make_laplacian_pyramid(8, 8, 3, Boundary::Reflect, error));
}

// A plan that cannot be allocated says so (it used to fail with an empty message).
TEST(LaplacianDeathTest, OutOfMemoryIsAMessage)
{
    GTEST_FLAG_SET(death_test_style, "threadsafe"); // the process may hold OIIO's threads
    EXPECT_EXIT(exit_without_memory([](std::string& error) {
        return bool(make_laplacian_pyramid(1 << 28, 1 << 28, 3, Boundary::Circular, error));
    }),
        ::testing::ExitedWithCode(0),
        "Laplacian pyramid: out of memory for a 268435456x268435456 image");
    EXPECT_EXIT(exit_without_memory([](std::string& error) {
        return bool(make_laplacian_pyramid_3d(1 << 28, 1 << 28, 1 << 28, 3, error));
    }),
        ::testing::ExitedWithCode(0),
        "3-D Laplacian pyramid: out of memory for a 268435456x268435456x268435456 volume");
}

TEST(Laplacian, BandsAndPerfectReconstruction)
{
    for (Boundary b : { Boundary::Circular, Boundary::Reflect })
        for (auto [w, h] :
            std::vector<std::pair<int, int>> { { 64, 64 }, { 100, 60 }, { 37, 29 } }) {
            auto pyr = laplacian(w, h, 3, b);
            ASSERT_TRUE(pyr);
            EXPECT_EQ(
                pyr->band_names(), (std::vector<std::string> { "L0", "L1", "L2", "lowpass" }));
            const Plane img = test_image(w, h);
            std::vector<Plane> bands;
            pyr->build(img, bands);
            ASSERT_EQ(bands.size(), 4u);
            for (int s = 0; s <= 3; ++s) {
                const int d = 1 << s;
                EXPECT_EQ(bands[s].width(), (w + d - 1) / d);
                EXPECT_EQ(bands[s].height(), (h + d - 1) / d);
            }
            Plane out;
            pyr->collapse(bands, out);
            // Float adds and subtracts of the same values: rounding only.
            EXPECT_LT(relative_error(out, img), 1e-6) << w << "x" << h;
        }
}

TEST(Laplacian, ConstantImageHasZeroBands)
{
    for (Boundary b : { Boundary::Circular, Boundary::Reflect })
        for (auto [w, h] : std::vector<std::pair<int, int>> { { 64, 64 }, { 37, 29 } }) {
            auto pyr = laplacian(w, h, 3, b);
            std::vector<Plane> bands;
            pyr->build(Plane(w, h, 0.37f), bands);
            for (int s = 0; s < 3; ++s)
                for (size_t i = 0; i < bands[s].size(); ++i)
                    ASSERT_NEAR(bands[s].data()[i], 0.0f, 1e-7) << s; // float rounding of 0.37
            for (size_t i = 0; i < bands[3].size(); ++i)
                ASSERT_NEAR(bands[3].data()[i], 0.37f, 1e-7); // float rounding
        }
}

TEST(Laplacian, ThreadCountIndependent)
{
    auto pyr = laplacian(100, 60, 3, Boundary::Reflect);
    const Plane img = test_image(100, 60);
    std::vector<Plane> b1, b2;
    pyr->build(img, b1, 1);
    pyr->build(img, b2, 2);
    for (size_t i = 0; i < b1.size(); ++i)
        EXPECT_TRUE(std::equal(b1[i].data(), b1[i].data() + b1[i].size(), b2[i].data()));
}

// ---- Laplacian 3-D ------------------------------------------------------------------------

namespace {

Volume test_volume(int w, int h, int d)
{
    Volume v(w, h, d);
    for (int z = 0; z < d; ++z) {
        const Plane slice = test_image(w, h, unsigned(z + 1));
        std::copy(slice.data(), slice.data() + slice.size(), v.slab(z));
    }
    return v;
}

} // namespace

TEST(Laplacian3D, RejectsBadArgumentsWithAMessage)
{
    std::string error;
    EXPECT_FALSE(make_laplacian_pyramid_3d(32, 32, 32, 0, error));
    EXPECT_FALSE(make_laplacian_pyramid_3d(32, 32, 7, 3, error));
    EXPECT_EQ(error,
        "3-D Laplacian pyramid: scales=3 does not fit a 32x32x7 volume (need scales >= 1 and "
        "every side >= 2^scales)");
    EXPECT_TRUE(make_laplacian_pyramid_3d(8, 8, 8, 3, error));
}

TEST(Laplacian3D, BandsAndPerfectReconstruction)
{
    for (auto [w, h, d] :
        std::vector<std::tuple<int, int, int>> { { 32, 32, 32 }, { 40, 24, 16 }, { 17, 23, 19 } }) {
        auto pyr = laplacian_3d(w, h, d, 3);
        ASSERT_TRUE(pyr);
        EXPECT_EQ(pyr->band_names(), (std::vector<std::string> { "L0", "L1", "L2", "lowpass" }));
        const Volume v = test_volume(w, h, d);
        std::vector<Volume> bands;
        pyr->build(v, bands);
        ASSERT_EQ(bands.size(), 4u);
        for (int s = 0; s <= 3; ++s) {
            const int k = 1 << s;
            EXPECT_EQ(bands[s].width(), (w + k - 1) / k);
            EXPECT_EQ(bands[s].height(), (h + k - 1) / k);
            EXPECT_EQ(bands[s].depth(), (d + k - 1) / k);
        }
        Volume out;
        pyr->collapse(bands, out);
        ASSERT_EQ(out.depth(), d);
        // Float adds and subtracts of the same values: rounding only.
        EXPECT_LT(relative_error(out.voxels(), v.voxels()), 1e-6) << w << "x" << h << "x" << d;
    }
}

TEST(Laplacian3D, ConstantVolumeHasZeroBands)
{
    auto pyr = laplacian_3d(17, 23, 19, 3);
    std::vector<Volume> bands;
    pyr->build(Volume(17, 23, 19, 0.37f), bands);
    for (int s = 0; s < 3; ++s)
        for (size_t i = 0; i < bands[s].size(); ++i)
            ASSERT_NEAR(bands[s].data()[i], 0.0f, 1e-7) << s; // float rounding of 0.37
}

// A volume that repeats one image along z has, slice for slice, the bands of the circular
// 2-D pyramid of that image: the 3-D bands are in the same units as the 2-D ones, which is
// what lets a 2-D sample's band histograms drive a 3-D synthesis.
TEST(Laplacian3D, BandsOfAPrismAreThe2DBands)
{
    const int w = 40, h = 24, d = 16;
    const Plane img = test_image(w, h);
    Volume v(w, h, d);
    for (int z = 0; z < d; ++z)
        std::copy(img.data(), img.data() + img.size(), v.slab(z));
    std::vector<Volume> b3;
    std::vector<Plane> b2;
    laplacian_3d(w, h, d, 3)->build(v, b3);
    laplacian(w, h, 3, Boundary::Circular)->build(img, b2);
    for (size_t s = 0; s < b2.size(); ++s)
        for (int z = 0; z < b3[s].depth(); ++z) {
            Plane slice;
            extract_slice(b3[s], SliceAxis::Z, z, slice);
            EXPECT_LT(relative_error(slice, b2[s]), 1e-5) << s << " " << z; // float rounding
        }
}

TEST(Laplacian3D, ThreadCountIndependent)
{
    auto pyr = laplacian_3d(40, 24, 16, 3);
    const Volume v = test_volume(40, 24, 16);
    std::vector<Volume> b1, b2, b3;
    pyr->build(v, b1, 1);
    pyr->build(v, b2, 2);
    pyr->build(v, b3, 3);
    for (size_t i = 0; i < b1.size(); ++i) {
        EXPECT_TRUE(std::equal(b1[i].data(), b1[i].data() + b1[i].size(), b2[i].data()));
        EXPECT_TRUE(std::equal(b1[i].data(), b1[i].data() + b1[i].size(), b3[i].data()));
    }
}

// ---- Steerable ---------------------------------------------------------------------------

TEST(Steerable, RejectsBadArguments)
{
    std::string error;
    EXPECT_FALSE(make_steerable_pyramid(64, 64, 3, 0, FftBackend::Kiss, error));
    EXPECT_NE(error.find("orientations=0"), std::string::npos) << error;
    EXPECT_FALSE(make_steerable_pyramid(64, 64, 3, 9, FftBackend::Kiss, error));
    EXPECT_FALSE(make_steerable_pyramid(64, 64, 0, 4, FftBackend::Kiss, error));
    EXPECT_FALSE(make_steerable_pyramid(64, 31, 5, 4, FftBackend::Kiss, error));
    EXPECT_NE(error.find("scales=5"), std::string::npos) << error;
    EXPECT_TRUE(make_steerable_pyramid(32, 32, 5, 4, FftBackend::Kiss, error));
    if (!fft_backend_available(FftBackend::Fftw)) {
        EXPECT_FALSE(make_steerable_pyramid(64, 64, 3, 4, FftBackend::Fftw, error));
    }
}

TEST(Steerable, BandNamesAndSizes)
{
    auto pyr = steerable(200, 121, 3, 2);
    EXPECT_EQ(pyr->band_names(),
        (std::vector<std::string> {
            "highpass", "s0.o0", "s0.o1", "s1.o0", "s1.o1", "s2.o0", "s2.o1", "lowpass" }));
    std::vector<Plane> bands;
    pyr->build(test_image(200, 121), bands);
    ASSERT_EQ(bands.size(), 8u);
    const int expect[8][2] = { { 200, 121 }, { 200, 121 }, { 200, 121 }, { 100, 61 }, { 100, 61 },
        { 50, 31 }, { 50, 31 }, { 25, 16 } };
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(bands[i].width(), expect[i][0]) << i;
        EXPECT_EQ(bands[i].height(), expect[i][1]) << i;
    }
}

TEST(Steerable, PerfectReconstruction)
{
    struct Case {
        int w, h, scales;
    };
    const Case cases[] = { { 256, 256, 4 }, { 200, 120, 4 }, { 640, 480, 5 }, { 257, 131, 4 },
        { 33, 17, 4 }, { 16, 16, 4 } };
    for (FftBackend fft : backends())
        for (const Case& c : cases)
            for (int k : { 1, 2, 4, 6, 8 }) {
                auto pyr = steerable(c.w, c.h, c.scales, k, fft);
                const Plane img = test_image(c.w, c.h, unsigned(k));
                std::vector<Plane> bands;
                pyr->build(img, bands);
                Plane out;
                pyr->collapse(bands, out);
                // A tight frame in float: a few ulps per FFT pass and mask.
                EXPECT_LT(relative_error(out, img), 1e-5)
                    << fft_backend_name(fft) << " " << c.w << "x" << c.h << " K=" << k;
            }
}

TEST(Steerable, PerfectReconstructionLarge)
{
    auto pyr = steerable(1000, 1000, 5, 4);
    const Plane img = test_image(1000, 1000);
    std::vector<Plane> bands;
    pyr->build(img, bands);
    Plane out;
    pyr->collapse(bands, out);
    EXPECT_LT(relative_error(out, img), 1e-5); // as above
}

TEST(Steerable, TightFrame)
{
    // Parseval per band: the band energies, each weighted by its pixel area, add up to the
    // image energy.
    for (auto [w, h] :
        std::vector<std::pair<int, int>> { { 256, 256 }, { 200, 120 }, { 257, 131 } }) {
        const int scales = 4;
        auto pyr = steerable(w, h, scales, 4);
        const Plane img = test_image(w, h, 3);
        std::vector<Plane> bands;
        pyr->build(img, bands);
        double sum = 0;
        for (const Plane& b : bands)
            sum += energy(b) * (double(w) * h) / (double(b.width()) * b.height());
        // Float masks and FFTs; the energy is a sum of ~1e5 squares.
        EXPECT_NEAR(sum / energy(img), 1.0, 1e-5) << w << "x" << h;
    }
}

TEST(Steerable, OrientationSelectivity)
{
    // At r = pi/2, scale 0 holds most of the energy; with K = 4, |G_k|^2 ~ cos^6(theta - pi k/4)
    // puts 80% of it in the matching band (1 / (1 + 2 cos^6(pi/4))).
    const int n = 128;
    auto pyr = steerable(n, n, 3, 4);
    struct Case {
        double fx, fy;
        int band;
    };
    for (const Case& c : { Case { 32, 0, 0 }, Case { 0, 32, 2 } }) {
        std::vector<Plane> bands;
        pyr->build(sinusoid(n, n, c.fx, c.fy), bands);
        double e[4], total = 0;
        for (int k = 0; k < 4; ++k)
            total += e[k] = energy(bands[1 + size_t(k)]);
        EXPECT_GT(e[c.band] / total, 0.79) << c.fx << "," << c.fy; // 0.8 up to rounding
    }
    std::vector<Plane> bands;
    pyr->build(sinusoid(n, n, 23, 23), bands); // diagonal: o1 or o3 by the sign of y
    const double e1 = energy(bands[2]), e3 = energy(bands[4]);
    EXPECT_GT(std::max(e1, e3), 10 * std::min(e1, e3));
}

TEST(Steerable, BandUnitsIndependentOfImageSize)
{
    // The same wave in cycles per pixel, in a 128^2 and a 256^2 image, has the same
    // amplitude in every band: bands are in image units at every level.
    auto small = steerable(128, 128, 4, 4), large = steerable(256, 256, 4, 4);
    std::vector<Plane> bs, bl;
    small->build(sinusoid(128, 128, 8, 3), bs);
    large->build(sinusoid(256, 256, 16, 6), bl);
    bool some_band_has_it = false;
    for (size_t i = 0; i < bs.size(); ++i) {
        const double rms_s = std::sqrt(energy(bs[i]) / bs[i].size());
        const double rms_l = std::sqrt(energy(bl[i]) / bl[i].size());
        EXPECT_NEAR(rms_s, rms_l, 1e-4) << small->band_names()[i]; // float rounding
        some_band_has_it |= rms_s > 0.2;
    }
    EXPECT_TRUE(some_band_has_it);
}

TEST(Steerable, ThreadCountIndependent)
{
    for (FftBackend fft : backends()) {
        auto pyr = steerable(200, 120, 3, 4, fft);
        const Plane img = test_image(200, 120);
        std::vector<Plane> b1, b2;
        pyr->build(img, b1, 1);
        pyr->build(img, b2, 2);
        for (size_t i = 0; i < b1.size(); ++i)
            EXPECT_TRUE(std::equal(b1[i].data(), b1[i].data() + b1[i].size(), b2[i].data())) << i;
        Plane o1, o2;
        pyr->collapse(b1, o1, 1);
        pyr->collapse(b1, o2, 2);
        EXPECT_TRUE(std::equal(o1.data(), o1.data() + o1.size(), o2.data()));
    }
}

TEST(Steerable, BackendsAgree)
{
    if (!fft_backend_available(FftBackend::Fftw))
        GTEST_SKIP() << "built without FFTW";
    auto k = steerable(200, 120, 3, 4, FftBackend::Kiss);
    auto f = steerable(200, 120, 3, 4, FftBackend::Fftw);
    const Plane img = test_image(200, 120);
    std::vector<Plane> bk, bf;
    k->build(img, bk);
    f->build(img, bf);
    for (size_t i = 0; i < bk.size(); ++i)
        for (size_t j = 0; j < bk[i].size(); ++j)
            ASSERT_NEAR(bk[i].data()[j], bf[i].data()[j], 1e-5) << i; // float FFT rounding
}

// ---- Periodic + smooth -------------------------------------------------------------------

TEST(PeriodicComponent, SmoothPartSolvesPoisson)
{
    // Moisan's s = u - p solves (periodic Laplacian) s = v, the boundary image.
    const int w = 37, h = 24;
    const Plane u = test_image(w, h, 9);
    const Plane p = periodic_component(u, FftBackend::Kiss);
    ASSERT_EQ(p.width(), w);
    ASSERT_EQ(p.height(), h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            auto s = [&](int i, int j) {
                return double(u.at(i, j, Boundary::Circular)) - p.at(i, j, Boundary::Circular);
            };
            const double lap = s(x - 1, y) + s(x + 1, y) + s(x, y - 1) + s(x, y + 1) - 4 * s(x, y);
            double v = 0;
            if (x == 0)
                v += double(u(w - 1, y)) - u(0, y);
            if (x == w - 1)
                v += double(u(0, y)) - u(w - 1, y);
            if (y == 0)
                v += double(u(x, h - 1)) - u(x, 0);
            if (y == h - 1)
                v += double(u(x, 0)) - u(x, h - 1);
            EXPECT_NEAR(lap, v, 1e-5) << x << "," << y; // float FFT of values ~1
        }
}

TEST(PeriodicComponent, MatchedEdgesUnchanged)
{
    // A periodic image whose opposite edges are equal has a zero boundary image: p = u.
    // (Any other periodic image changes a little: Moisan's p matches u's Laplacian without
    // the wrap-around neighbours.)
    const int w = 40, h = 30;
    Plane u(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            u(x, y) = float(0.5 + 0.3 * std::cos(2 * pi * 3 * (x - (w - 1) / 2.0) / w)
                + 0.2 * std::cos(2 * pi * 2 * (y - (h - 1) / 2.0) / h));
    for (FftBackend fft : backends()) {
        const Plane p = periodic_component(u, fft);
        EXPECT_LT(relative_error(p, u), 1e-6) << fft_backend_name(fft); // float rounding
    }
}

TEST(PeriodicComponent, RampBecomesSeamless)
{
    const int w = 64, h = 48;
    Plane u(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            u(x, y) = float(x) / w + 0.5f * float(y) / h;
    const Plane p = periodic_component(u, FftBackend::Kiss, 2);
    auto seam = [&](const Plane& a) {
        double j = 0;
        for (int y = 0; y < h; ++y)
            j += std::abs(a(w - 1, y) - a(0, y));
        for (int x = 0; x < w; ++x)
            j += std::abs(a(x, h - 1) - a(x, 0));
        return j / (w + h);
    };
    EXPECT_LT(seam(p), 0.1 * seam(u));
    double mu = 0, mp = 0;
    for (size_t i = 0; i < u.size(); ++i) {
        mu += u.data()[i];
        mp += p.data()[i];
    }
    EXPECT_NEAR(mp / p.size(), mu / u.size(), 1e-6); // s-hat(0,0) = 0; float rounding
}

// transform_bands is build + modify + collapse with the bands processed in parallel: its
// result and its bands must be bit-identical to the sequential composition.
TEST(Pyramid, TransformBandsEqualsBuildModifyCollapse)
{
    auto modify = [](int b, Plane& band) {
        for (size_t i = 0; i < band.size(); ++i)
            band.data()[i] = std::tanh(2.0f * band.data()[i]) + 0.01f * float(b);
    };
    std::vector<std::unique_ptr<Pyramid>> pyramids;
    pyramids.push_back(steerable(200, 120, 3, 4));
    pyramids.push_back(steerable(131, 97, 2, 3));
    pyramids.push_back(laplacian(100, 60, 3, Boundary::Circular));
    for (auto& pyr : pyramids) {
        const Plane image = test_image(pyr->width(), pyr->height(), 3);
        std::vector<Plane> bands;
        pyr->build(image, bands, 1);
        for (int b = 0; b < int(bands.size()); ++b)
            modify(b, bands[size_t(b)]);
        Plane expected;
        pyr->collapse(bands, expected, 1);
        for (int nthreads : { 1, 2, 4 }) {
            Plane result = image;
            std::vector<Plane> modified;
            pyr->transform_bands(result, modified, modify, nthreads);
            ASSERT_EQ(modified.size(), bands.size());
            for (size_t b = 0; b < bands.size(); ++b)
                ASSERT_TRUE(std::equal(
                    bands[b].data(), bands[b].data() + bands[b].size(), modified[b].data()))
                    << pyr->band_names()[b] << " nthreads " << nthreads;
            ASSERT_TRUE(
                std::equal(expected.data(), expected.data() + expected.size(), result.data()))
                << "nthreads " << nthreads;
        }
    }
}

// A stop flag set while bands are processed skips every band not yet started: on one
// thread, the bands after the one that set it are never modified.
TEST(Pyramid, TransformBandsSkipsTheBandsLeftOnceStopped)
{
    std::vector<std::unique_ptr<Pyramid>> pyramids;
    pyramids.push_back(steerable(128, 96, 3, 4));
    pyramids.push_back(laplacian(100, 60, 3, Boundary::Circular));
    for (auto& pyr : pyramids) {
        Plane image = test_image(pyr->width(), pyr->height(), 3);
        StopFlag stop { false };
        std::vector<int> modified;
        std::vector<Plane> bands;
        pyr->transform_bands(
            image, bands,
            [&](int b, Plane&) {
                modified.push_back(b);
                if (modified.size() == 2)
                    stop = true;
            },
            1, &stop);
        EXPECT_EQ(modified.size(), 2u) << pyr->nbands() << " bands";
    }
}
