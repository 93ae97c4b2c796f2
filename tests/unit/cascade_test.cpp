// SPDX-License-Identifier: Apache-2.0
// The cascade of iterated maps and convolutions: maps, kernels against a direct
// implementation, dilation, wrap, determinism, transfer, ramps and bad options.
#include <texsyn/cascade.h>
#include <texsyn/fft.h>
#include <texsyn/random.h>

#include <cmath>
#include <complex>
#include <iostream>
#include <set>

#include <gtest/gtest.h>

#include "cascade/cascade_pvt.h"
#include "test_metrics.h"
#include "test_samples.h"

using namespace texsyn;

namespace {

using test::linear_sample;
using test::pixel_hash;
using test::planes_of;
using test::seam_ratio;

Plane random_plane(int w, int h, uint64_t seed)
{
    Plane p(w, h);
    for (size_t i = 0; i < p.size(); ++i)
        p.data()[i] = random_uniform(seed, 0, i);
    return p;
}

// The textbook circular convolution, one output pixel at a time.
Plane direct_convolution(const Plane& in, const detail::CascadeKernelWeights& k)
{
    const int w = in.width(), h = in.height(), half = k.size / 2;
    Plane out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sum = 0;
            for (int j = 0; j < k.size; ++j)
                for (int i = 0; i < k.size; ++i)
                    sum += double(k.at(i, j))
                        * in(((x + i - half) % w + w) % w, ((y + j - half) % h + h) % h);
            out(x, y) = float(sum);
        }
    return out;
}

CascadeOptions options(int w, int h)
{
    CascadeOptions opt;
    opt.width = w;
    opt.height = h;
    opt.seed = 4;
    return opt;
}

// Pearson correlation of two planes of equal size.
double correlation(const Plane& a, const Plane& b)
{
    double ma = 0, mb = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        ma += a.data()[i];
        mb += b.data()[i];
    }
    ma /= double(a.size());
    mb /= double(b.size());
    double ab = 0, aa = 0, bb = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double da = a.data()[i] - ma, db = b.data()[i] - mb;
        ab += da * db;
        aa += da * da;
        bb += db * db;
    }
    return ab / std::sqrt(aa * bb);
}

// The dominant feature wavelength of an image, as a fraction of its shorter side: 1 / the
// median frequency of its power spectrum (the channels' mean, DC left out), counting only
// frequencies up to `band` cycles per side, so that images of different resolutions are
// compared over the band they share (the finer one's sharper contours left out).
double wavelength(const OIIO::ImageBuf& image, double low, double band)
{
    const PlanarImage p = planes_of(image);
    const int w = p.width(), h = p.height(), side = std::min(w, h);
    std::vector<float> v(size_t(w) * size_t(h), 0.0f);
    for (const Plane& c : p.channels)
        for (size_t i = 0; i < v.size(); ++i)
            v[i] += c.data()[i] / float(p.channels.size());
    std::string error;
    const auto fft = RealFft2D::create(w, h, FftBackend::Kiss, error);
    std::vector<std::complex<float>> spectrum(fft->spectrum_size());
    fft->forward(v.data(), spectrum.data());
    std::vector<std::pair<double, double>> power; // (cycles per side, power)
    for (int ky = 0; ky < h; ++ky)
        for (int kx = 0; kx <= w / 2; ++kx) {
            const double fy = double(ky <= h / 2 ? ky : ky - h) * side / h,
                         fx = double(kx) * side / w, f = std::hypot(fx, fy);
            // Columns 1..w/2-1 stand for their negative twins too.
            const double twice = kx == 0 || 2 * kx == w ? 1.0 : 2.0;
            if (f >= low && f <= band)
                power.push_back({ f,
                    twice * std::norm(spectrum[size_t(ky) * size_t(w / 2 + 1) + size_t(kx)]) });
        }
    std::sort(power.begin(), power.end());
    double total = 0, sum = 0;
    for (const auto& [f, e] : power)
        total += e;
    for (const auto& [f, e] : power)
        if ((sum += e) >= 0.5 * total)
            return 1.0 / f;
    return 1.0;
}

} // namespace

TEST(CascadeMaps, ValuesAndPeaks)
{
    using detail::cascade_map_value;
    const std::vector<float> none;
    EXPECT_FLOAT_EQ(cascade_map_value(CascadeMap::Logistic, 3.9f, none, 0.5f), 0.975f);
    EXPECT_FLOAT_EQ(cascade_map_value(CascadeMap::Logistic, 3.9f, none, 0.2f), 3.9f * 0.2f * 0.8f);
    EXPECT_NEAR(cascade_map_value(CascadeMap::Sine, 4.0f, none, 0.5f), 1.0f, 1e-6);
    EXPECT_NEAR(cascade_map_value(CascadeMap::Sine, 2.0f, none, 0.25f),
        0.5f * std::sin(3.14159265f * 0.25f), 1e-6);
    EXPECT_FLOAT_EQ(cascade_map_value(CascadeMap::Tent, 3.0f, none, 0.5f), 0.75f);
    EXPECT_FLOAT_EQ(cascade_map_value(CascadeMap::Tent, 3.0f, none, 0.25f), 0.375f);
    EXPECT_NEAR(
        cascade_map_value(CascadeMap::Cubic, 3.0f, none, 1.0f / std::sqrt(3.0f)), 0.75f, 1e-6);
    const std::vector<float> curve = { 0.0f, 0.0f, 0.3f, 0.9f, 1.0f, 0.2f };
    EXPECT_NEAR(cascade_map_value(CascadeMap::Curve, 0, curve, 0.15f), 0.45f, 1e-6);
    EXPECT_NEAR(cascade_map_value(CascadeMap::Curve, 0, curve, 0.65f), 0.55f, 1e-6);
    // Inputs outside [0, 1] are clamped first; outputs stay in [0, 1].
    EXPECT_FLOAT_EQ(cascade_map_value(CascadeMap::Logistic, 3.9f, none, -0.5f), 0.0f);
    EXPECT_FLOAT_EQ(cascade_map_value(CascadeMap::Tent, 4.0f, none, 2.0f), 0.0f);
}

// Every kernel sums to 1, and the row-shifting convolution equals the textbook one.
TEST(CascadeKernels, ConvolutionMatchesTheDirectSum)
{
    const Plane in = random_plane(37, 23, 1);
    for (CascadeKernel k :
        { CascadeKernel::Box3, CascadeKernel::Box5, CascadeKernel::Box7, CascadeKernel::Gauss3,
            CascadeKernel::Gauss5, CascadeKernel::Gauss7, CascadeKernel::Dog5, CascadeKernel::Dog7,
            CascadeKernel::Aniso5, CascadeKernel::Aniso7, CascadeKernel::Custom }) {
        CascadeOptions opt;
        opt.kernel = { k };
        opt.angle = { 30.0f };
        opt.ksize = 3;
        opt.weights = { 1, 2, 1, 0, 4, 0, -1, 2, 3 };
        const detail::CascadeKernelWeights weights = detail::cascade_kernel(opt, 0);
        double sum = 0;
        for (float w : weights.weights)
            sum += w;
        EXPECT_NEAR(sum, 1.0, 1e-6) << int(k);
        Plane fast;
        detail::convolve_circular(in, weights, fast, 2);
        const Plane direct = direct_convolution(in, weights);
        for (size_t i = 0; i < in.size(); ++i)
            ASSERT_NEAR(fast.data()[i], direct.data()[i], 2e-6) << int(k) << " at " << i;
    }
}

// An anisotropic kernel is longer along its angle: at 0 degrees it spreads along x.
TEST(CascadeKernels, AnisotropicKernelFollowsItsAngle)
{
    CascadeOptions opt;
    opt.kernel = { CascadeKernel::Aniso7 };
    const detail::CascadeKernelWeights k0 = detail::cascade_kernel(opt, 0);
    EXPECT_GT(k0.at(6, 3), 10 * k0.at(3, 6));
    opt.angle = { 90.0f };
    const detail::CascadeKernelWeights k90 = detail::cascade_kernel(opt, 0);
    EXPECT_GT(k90.at(3, 6), 10 * k90.at(6, 3));
}

// Dilation 1 everywhere is exactly the undilated operator, in the convolution and in a
// whole cascade; dilation 2 spreads the taps.
TEST(CascadeDilation, OneEqualsTheUndilatedOperator)
{
    const Plane in = random_plane(40, 30, 2);
    CascadeOptions opt;
    opt.kernel = { CascadeKernel::Gauss5 };
    const detail::CascadeKernelWeights k = detail::cascade_kernel(opt, 0);
    Plane plain, dilated;
    detail::convolve_circular(in, k, plain, 1);
    detail::convolve_warped(in, k, Plane(40, 30, 1.0f), Plane(40, 30, 0.0f), dilated, 2);
    for (size_t i = 0; i < in.size(); ++i)
        ASSERT_EQ(plain.data()[i], dilated.data()[i]) << i;
    detail::convolve_warped(in, k, Plane(40, 30, 2.0f), Plane(), dilated, 2);
    // Dilation 2: the taps fall on even offsets.
    double sum = 0;
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i)
            sum += double(k.at(i, j)) * in((10 + 2 * (i - 2) + 40) % 40, (10 + 2 * (j - 2)) % 30);
    EXPECT_NEAR(dilated(10, 10), sum, 1e-5);

    OIIO::ImageBuf control;
    PlanarImage zero;
    zero.channels = { Plane(32, 32, 0.0f) };
    zero.channel_names = { "Y" };
    imagebuf_from_planes(zero, control, false);
    CascadeOptions c = options(64, 64);
    c.levels = 2;
    const OIIO::ImageBuf undilated = cascade_synthesize(c);
    const OIIO::ImageBuf one = cascade_synthesize(c, nullptr, &control);
    ASSERT_FALSE(one.has_error()) << one.geterror();
    EXPECT_EQ(pixel_hash(one), pixel_hash(undilated));
}

// Circular convolution makes the output a torus; the result ignores the thread count and
// depends on the seed; odd sizes work with several levels.
TEST(Cascade, TilesIsDeterministicAndTakesAnySize)
{
    CascadeOptions opt = options(300, 200);
    opt.levels = 3;
    opt.r = { 3.9f, 3.7f, 3.5f };
    opt.noise = { 0.0f, 0.2f };
    std::string first;
    for (int threads : { 1, 2, 4 }) {
        opt.nthreads = threads;
        const OIIO::ImageBuf out = cascade_synthesize(opt);
        ASSERT_FALSE(out.has_error()) << out.geterror();
        EXPECT_EQ(out.spec().width, 300);
        EXPECT_EQ(out.spec().height, 200);
        EXPECT_EQ(out.spec().get_string_attribute("synth:method"), "cascade");
        if (first.empty())
            first = pixel_hash(out);
        EXPECT_EQ(pixel_hash(out), first) << threads;
        EXPECT_LT(seam_ratio(out), 1.3);
    }
    opt.seed = 5;
    EXPECT_NE(pixel_hash(cascade_synthesize(opt)), first);
}

// Values stay in [0, 1] and the pattern is neither flat nor white noise: neighbours are
// correlated (the convolution's smoothness) but the values spread (the map's roughness).
// Progress comes once per iteration of every level, rises to 1, and changes nothing.
TEST(Cascade, ReportsProgressToTheEnd)
{
    CascadeOptions opt = options(64, 48);
    opt.levels = 3;
    opt.iterations = { 2, 3 };
    std::vector<float> seen;
    opt.progress = [&](float fraction) { seen.push_back(fraction); };
    const OIIO::ImageBuf out = cascade_synthesize(opt);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    ASSERT_EQ(seen.size(), 2u + 3u + 3u); // the last level repeats the last count
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_GT(seen.front(), 0.0f);
    EXPECT_FLOAT_EQ(seen.back(), 1.0f);
    opt.progress = nullptr;
    EXPECT_EQ(pixel_hash(cascade_synthesize(opt)), pixel_hash(out));
}

// Without size= a generator is 512x512 and a transfer its image's size.
TEST(Cascade, TheDefaultSizeIsTheImagesOr512)
{
    CascadeOptions opt;
    opt.iterations = { 1 };
    EXPECT_EQ(cascade_synthesize(opt).spec().width, 512);
    OIIO::ImageBuf image(OIIO::ImageSpec(40, 24, 1, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(image, { 0.5f });
    const OIIO::ImageBuf out = cascade_synthesize(opt, &image);
    EXPECT_EQ(out.spec().width, 40);
    EXPECT_EQ(out.spec().height, 24);
    EXPECT_EQ(out.spec().get_string_attribute("synth:options").find("preset=none:size=40x24:"), 0u)
        << out.spec().get_string_attribute("synth:options");
}

TEST(Cascade, TransientPatternBetweenSmoothAndRough)
{
    const OIIO::ImageBuf out = cascade_synthesize(options(128, 128));
    const Plane p = planes_of(out).channels[0];
    double lo = 1, hi = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        lo = std::min(lo, double(p.data()[i]));
        hi = std::max(hi, double(p.data()[i]));
    }
    EXPECT_GE(lo, 0.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_GT(hi - lo, 0.3);
    Plane shifted(128, 128);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x)
            shifted(x, y) = p((x + 1) % 128, y);
    const double c = correlation(p, shifted);
    EXPECT_GT(c, 0.2);
    EXPECT_LT(c, 0.99);
}

// Structured initial conditions (texture transfer): the sample's large features survive.
TEST(Cascade, TransferKeepsTheImagesFeatures)
{
    const OIIO::ImageBuf sample = linear_sample("marble_pink.png");
    CascadeOptions opt = options(128, 128);
    opt.iterations = { 2 };
    opt.r = { 3.0f };
    const Plane out = planes_of(cascade_synthesize(opt, &sample)).channels[0];
    const PlanarImage s = planes_of(sample);
    Plane lum(128, 128);
    for (size_t i = 0; i < lum.size(); ++i)
        lum.data()[i] = 0.2126f * s.channels[0].data()[i] + 0.7152f * s.channels[1].data()[i]
            + 0.0722f * s.channels[2].data()[i];
    const Plane noise_start = planes_of(cascade_synthesize(opt)).channels[0];
    EXPECT_GT(std::abs(correlation(out, lum)), 0.3);
    EXPECT_LT(std::abs(correlation(noise_start, lum)), 0.1);
    opt.transfer = CascadeTransfer::Channels;
    const OIIO::ImageBuf channels = cascade_synthesize(opt, &sample);
    EXPECT_EQ(channels.nchannels(), 3);
}

// A ramp colours the lattice: every pixel lies on the ramp's segment.
TEST(Cascade, RampColoursTheLattice)
{
    CascadeOptions opt = options(64, 64);
    opt.ramp = { 0, 0, 0, 1.0f, 0.5f, 0.25f };
    const PlanarImage out = planes_of(cascade_synthesize(opt));
    ASSERT_EQ(out.channels.size(), 3u);
    for (size_t i = 0; i < out.channels[0].size(); ++i) {
        const float r = out.channels[0].data()[i];
        EXPECT_NEAR(out.channels[1].data()[i], 0.5f * r, 1e-6);
        EXPECT_NEAR(out.channels[2].data()[i], 0.25f * r, 1e-6);
    }
}

TEST(Cascade, RefusesBadOptions)
{
    auto error_of = [](const CascadeOptions& opt) {
        OIIO::ImageBuf out;
        EXPECT_FALSE(cascade_synthesize(out, opt));
        return out.geterror();
    };
    CascadeOptions opt = options(64, 64);
    opt.map = { CascadeMap::Curve };
    opt.curve = { 0, 0 };
    EXPECT_NE(error_of(opt).find("at least 2 points"), std::string::npos);
    opt.curve = { 0.5f, 0, 0.2f, 1 };
    EXPECT_NE(error_of(opt).find("x must increase"), std::string::npos);
    opt = options(64, 64);
    opt.kernel = { CascadeKernel::Custom };
    opt.ksize = 3;
    opt.weights = { 1, 2, 3 };
    EXPECT_NE(error_of(opt).find("needs 9 weights"), std::string::npos);
    opt = options(64, 64);
    opt.ramp = { 1, 0 };
    EXPECT_NE(error_of(opt).find("r,g,b triples"), std::string::npos);
    opt = options(64, 64);
    opt.r = { 3.9f, 3.8f };
    EXPECT_NE(error_of(opt).find("values for levels=1"), std::string::npos);
    EXPECT_EQ(error_of(options(0, 64)), "size=0x64 : out of range 1..65536 (each side)");
    EXPECT_NE(error_of(options(65536, 65536)).find("memory"), std::string::npos);
}

// The named looks parse, differ from each other, and options after a preset override it.
TEST(Cascade, PresetsAreDistinctLooks)
{
    const OptionTable<CascadeOptions>& table = CascadeOptions::table();
    std::set<std::string> hashes;
    for (const char* name : { "cells", "blotches", "fibres", "bands", "caustics", "stone" }) {
        CascadeOptions opt = options(96, 96);
        std::string error;
        ASSERT_TRUE(table.set(opt, "preset", name, error)) << error;
        const OIIO::ImageBuf out = cascade_synthesize(opt);
        ASSERT_FALSE(out.has_error()) << name << ": " << out.geterror();
        EXPECT_EQ(out.nchannels(), 3) << name;
        hashes.insert(pixel_hash(out));
    }
    EXPECT_EQ(hashes.size(), 6u);
    CascadeOptions opt = options(96, 96);
    std::string error;
    ASSERT_TRUE(table.set(opt, "preset", "cells", error));
    ASSERT_TRUE(table.set(opt, "r", "3.5", error));
    EXPECT_EQ(opt.kernel, std::vector<CascadeKernel> { CascadeKernel::Dog7 });
    EXPECT_EQ(opt.r, std::vector<float> { 3.5f });
    EXPECT_FALSE(table.set(opt, "preset", "plaid", error));
    EXPECT_NE(error.find("cells|blotches"), std::string::npos);
}

// A rotation control of 0 is the plain operator; a quarter turn turns an anisotropic
// pattern from along x to along y.
TEST(CascadeRotation, QuarterTurnTurnsThePattern)
{
    auto control = [](float value) {
        PlanarImage p;
        p.channels = { Plane(16, 16, value) };
        p.channel_names = { "Y" };
        OIIO::ImageBuf buf;
        imagebuf_from_planes(p, buf, false);
        return buf;
    };
    CascadeOptions opt = options(96, 96);
    opt.kernel = { CascadeKernel::Aniso7 };
    const OIIO::ImageBuf zero = control(0.0f), quarter = control(0.25f);
    const OIIO::ImageBuf plain = cascade_synthesize(opt);
    EXPECT_EQ(pixel_hash(cascade_synthesize(opt, nullptr, nullptr, &zero)), pixel_hash(plain));
    auto along_x = [](const OIIO::ImageBuf& buf) {
        const Plane p = planes_of(buf).channels[0];
        double gx = 0, gy = 0;
        for (int y = 0; y + 1 < p.height(); ++y)
            for (int x = 0; x + 1 < p.width(); ++x) {
                gx += std::pow(p(x + 1, y) - p(x, y), 2.0);
                gy += std::pow(p(x, y + 1) - p(x, y), 2.0);
            }
        return gy / gx; // > 1: features stretched along x
    };
    EXPECT_GT(along_x(plain), 1.5);
    EXPECT_LT(along_x(cascade_synthesize(opt, nullptr, nullptr, &quarter)), 1.0 / 1.5);
}

// A palette image colours the lattice with its own colours by luminance rank.
TEST(Cascade, PaletteGivesTheImagesColours)
{
    PlanarImage flat;
    flat.channels = { Plane(8, 8, 0.4f), Plane(8, 8, 0.2f), Plane(8, 8, 0.1f) };
    flat.channel_names = { "R", "G", "B" };
    OIIO::ImageBuf palette;
    imagebuf_from_planes(flat, palette, false);
    CascadeOptions opt = options(32, 32);
    const PlanarImage out = planes_of(cascade_synthesize(opt, nullptr, nullptr, nullptr, &palette));
    ASSERT_EQ(out.channels.size(), 3u);
    for (size_t i = 0; i < out.channels[0].size(); ++i) {
        ASSERT_EQ(out.channels[0].data()[i], 0.4f);
        ASSERT_EQ(out.channels[2].data()[i], 0.1f);
    }
    // It replaces a ramp (a preset's, say).
    opt.ramp = { 0, 0, 0, 1, 1, 1 };
    EXPECT_EQ(pixel_hash(cascade_synthesize(opt, nullptr, nullptr, nullptr, &palette)),
        pixel_hash(cascade_synthesize(options(32, 32), nullptr, nullptr, nullptr, &palette)));
    // A palette colours one lattice.
    OIIO::ImageBuf rgb;
    imagebuf_from_planes(flat, rgb, false);
    opt.transfer = CascadeTransfer::Channels;
    OIIO::ImageBuf dst;
    EXPECT_FALSE(cascade_synthesize(dst, opt, &rgb, nullptr, nullptr, &palette));
    EXPECT_EQ(
        dst.geterror(), "a palette image colours one lattice; with transfer=channels there are 3");
}

// A transfer's size is checked against memory before its image is resized to it.
TEST(Cascade, AHugeTransferIsRefusedBeforeAllocating)
{
    OIIO::ImageBuf image(OIIO::ImageSpec(32, 32, 3, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(image, { 0.5f, 0.4f, 0.3f });
    CascadeOptions opt = options(65536, 65536);
    OIIO::ImageBuf dst;
    EXPECT_FALSE(cascade_synthesize(dst, opt, &image));
    EXPECT_EQ(dst.geterror().find("size=65536x65536 would need about "), 0u) << dst.geterror();
}

// Every operator option can change from level to level: map=, kernel= and angle= lists.
TEST(Cascade, EachLevelHasItsOwnOperator)
{
    const OptionTable<CascadeOptions>& table = CascadeOptions::table();
    CascadeOptions opt = options(64, 64);
    std::string error;
    ASSERT_TRUE(table.set(opt, "levels", "2", error));
    const std::string same = pixel_hash(cascade_synthesize(opt));
    ASSERT_TRUE(table.set(opt, "map", "logistic,sine", error)) << error;
    ASSERT_TRUE(table.set(opt, "kernel", "gauss5,aniso7", error)) << error;
    ASSERT_TRUE(table.set(opt, "angle", "0,45", error)) << error;
    EXPECT_EQ(opt.map, (std::vector<CascadeMap> { CascadeMap::Logistic, CascadeMap::Sine }));
    EXPECT_EQ(table.find("kernel")->format(&opt), "gauss5,aniso7");
    const OIIO::ImageBuf out = cascade_synthesize(opt);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_NE(pixel_hash(out), same);
    EXPECT_FALSE(table.set(opt, "kernel", "gauss5,plaid", error));
    EXPECT_NE(error.find("plaid"), std::string::npos);
    ASSERT_TRUE(table.set(opt, "map", "logistic,sine,tent", error));
    OIIO::ImageBuf dst;
    EXPECT_FALSE(cascade_synthesize(dst, opt));
    EXPECT_NE(dst.geterror().find("levels=2"), std::string::npos);
}

// Resampling to the same size is the identity; a period-long cosine stays that cosine at
// another size (Catmull-Rom is exact to ~1e-3 on it) and wraps around.
TEST(CascadeScale, ResamplingIsCircularAndSmooth)
{
    const Plane noise = random_plane(24, 16, 3);
    const Plane same = detail::resample_circular(noise, 24, 16, 0);
    for (size_t i = 0; i < noise.size(); ++i)
        ASSERT_EQ(same.data()[i], noise.data()[i]);
    auto cosine = [](int w, int h) {
        Plane p(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                p(x, y) = float(std::cos(6.2831853 * (x + 0.5) / w));
        return p;
    };
    for (auto [from, to] : { std::pair { 32, 128 }, { 128, 32 }, { 50, 77 } }) {
        const Plane out = detail::resample_circular(cosine(from, 8), to, 8, 0);
        const Plane want = cosine(to, 8);
        for (size_t i = 0; i < out.size(); ++i)
            ASSERT_NEAR(out.data()[i], want.data()[i], from < to ? 2e-3 : 2e-2)
                << from << " to " << to << " at " << i;
    }
}

// A preset is the same texture at any size: its dominant wavelength, as a fraction of the
// image, is the same at 256x256 and 1024x1024 (within 10%: the 1024 lattice is the 256 one,
// only resampled before its last map), and doubling scale doubles it (within 25%: another
// lattice, so other noise). Measured from 3 to 128 cycles per side (the band both sizes
// hold); so that a doubled wavelength stays well inside it, the doubling is measured from
// scale=1 where the wavelength is under 0.1 of the image, else from scale=0.5.
TEST(CascadeScale, PresetFeaturesKeepTheirSizeRelativeToTheImage)
{
    const OptionTable<CascadeOptions>& table = CascadeOptions::table();
    for (const char* name : { "cells", "blotches", "fibres", "bands", "caustics", "stone" }) {
        auto measure = [&](int side, float scale) {
            CascadeOptions opt = options(side, side);
            std::string error;
            EXPECT_TRUE(table.set(opt, "preset", name, error)) << error;
            opt.scale = scale;
            const OIIO::ImageBuf out = cascade_synthesize(opt);
            EXPECT_FALSE(out.has_error()) << out.geterror();
            return wavelength(out, 3.0, 128.0);
        };
        const double small = measure(256, 1.0f), big = measure(1024, 1.0f);
        const float from = big < 0.1 ? 1.0f : 0.5f;
        const double base = from == 1.0f ? big : measure(1024, from),
                     doubled = measure(1024, 2.0f * from);
        std::cout << name << ": wavelength 256 " << small << ", 1024 " << big << "; scale=" << from
                  << " " << base << ", scale=" << 2 * from << " " << doubled << "\n";
        EXPECT_NEAR(big / small, 1.0, 0.1) << name;
        EXPECT_NEAR(doubled / base, 2.0, 0.5) << name;
    }
}
