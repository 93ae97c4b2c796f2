// SPDX-License-Identifier: Apache-2.0
// texsyn/homogeneity.h: the illumination fit, the tile measures, flattening, and issue #4's
// end-to-end claim (a gradient sample is flagged, and flattening it improves synthesis).
#include <texsyn/histogram.h>
#include <texsyn/homogeneity.h>
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/random.h>

#include <cmath>
#include <cstring>
#include <functional>

#include <gtest/gtest.h>

#include "test_samples.h"

using namespace texsyn;

namespace {

// A bundled sample as the tool sees it, as planes.
PlanarImage linear_planes(const std::string& name)
{
    return test::planes_of(test::linear_sample(name));
}

// Fitting 10^4 pixels of noise of std-dev 0.29: each coefficient is off by about 1 %
// (0.29 / sqrt(N var(monomial))); the peak-to-peak amplitude sums several of them.
constexpr double kAmplitudeTolerance = 0.04;

// A homogeneous texture: independent uniform noise in [0.5, 1.5) per pixel and channel.
PlanarImage noise_image(int w, int h, int nchannels, uint64_t seed = 1)
{
    PlanarImage img;
    for (int c = 0; c < nchannels; ++c) {
        Plane p(w, h);
        for (size_t i = 0; i < p.size(); ++i)
            p.data()[i] = 0.5f + random_uniform(seed, uint64_t(c), i);
        img.channels.push_back(std::move(p));
        img.channel_names.push_back(std::string(1, "RGBA"[c % 4]));
    }
    return img;
}

// Multiplies the colour channels by gain(u, v), u and v in (0, 1) left to right and top to
// bottom.
PlanarImage lit(PlanarImage img, const std::function<double(double, double)>& gain)
{
    for (int c = 0; c < img.ncolor(); ++c)
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x)
                img.channels[size_t(c)](x, y)
                    *= float(gain((x + 0.5) / img.width(), (y + 0.5) / img.height()));
    return img;
}

double ramp(double u, double)
{
    return 0.5 + u; // the issue's example: 0.5 -> 1.5 left to right
}

// A lens's cos⁴ fall-off with the corners 40 degrees off axis (corners at 0.34).
double vignette(double u, double v)
{
    const double r = std::hypot(u - 0.5, v - 0.5) / std::sqrt(0.5);
    return std::pow(std::cos(std::atan(r * std::tan(40.0 * M_PI / 180.0))), 4.0);
}

double mean(const Plane& p)
{
    double s = 0.0;
    for (size_t i = 0; i < p.size(); ++i)
        s += p.data()[i];
    return s / double(p.size());
}

// Relative standard deviation of a / b over the pixels: 0 when a is b times a constant.
double ratio_spread(const Plane& a, const Plane& b)
{
    double s = 0.0, ss = 0.0;
    for (size_t i = 0; i < a.size(); ++i) {
        const double r = double(a.data()[i]) / double(b.data()[i]);
        s += r;
        ss += r * r;
    }
    const double m = s / double(a.size());
    return std::sqrt(std::max(0.0, ss / double(a.size()) - m * m)) / m;
}

bool same_bits(const PlanarImage& a, const PlanarImage& b)
{
    if (a.nchannels() != b.nchannels())
        return false;
    for (int c = 0; c < a.nchannels(); ++c)
        if (std::memcmp(a.channels[size_t(c)].data(), b.channels[size_t(c)].data(),
                a.channels[size_t(c)].size() * sizeof(float))
            != 0)
            return false;
    return true;
}

Plane luminance_of(const PlanarImage& img)
{
    Plane y(img.width(), img.height());
    for (size_t i = 0; i < y.size(); ++i)
        y.data()[i] = 0.2126f * img.channels[0].data()[i] + 0.7152f * img.channels[1].data()[i]
            + 0.0722f * img.channels[2].data()[i];
    return y;
}

} // namespace

TEST(Homogeneity, RecoversASyntheticRampsAmplitudeAndDirection)
{
    // Brighter towards the top right at 30 degrees: gain 1 + 0.4 (cos30 u' + sin30 v'),
    // u', v' in (-1, 1) with v' up. Peak to peak over the pixel centres: 0.8 (cos30 + sin30)
    // (1 - 1/128) = 1.084 of the mean 1.
    const double a = 0.4, th = 30.0 * M_PI / 180.0;
    PlanarImage img = lit(noise_image(128, 128, 3), [&](double u, double v) {
        return 1.0 + a * (std::cos(th) * (2.0 * u - 1.0) + std::sin(th) * (1.0 - 2.0 * v));
    });
    HomogeneityReport r = check_homogeneity(img);
    EXPECT_NEAR(r.illumination_amplitude, 0.8 * (std::cos(th) + std::sin(th)) * 127.0 / 128.0,
        kAmplitudeTolerance);
    EXPECT_NEAR(r.illumination_direction, 30.0, 1.5); // atan of coefficients 1 % off: < 1 deg
    EXPECT_GT(r.illumination_planar_fraction, 0.95);
    EXPECT_EQ(r.illumination_description, "brighter towards the top right (30 deg)");
    EXPECT_TRUE(r.poor);
    EXPECT_LT(r.score, 0.5);
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_EQ(r.warnings[0].find("the lighting varies by 108%"), 0u) << r.warnings[0];
    EXPECT_NE(r.warnings[0].find("flatten=1"), std::string::npos);
}

TEST(Homogeneity, DirectionIsInImageTermsForNonSquareSamples)
{
    // Brighter towards the bottom on a wide sample: 270 degrees whatever the aspect.
    HomogeneityReport r
        = check_homogeneity(lit(noise_image(200, 64, 3), [](double, double v) { return 0.5 + v; }));
    EXPECT_NEAR(r.illumination_direction, 270.0, 1.5);
    EXPECT_EQ(r.illumination_description.find("brighter towards the bottom ("), 0u);
}

TEST(Homogeneity, AVignetteIsCurvedNotPlanar)
{
    HomogeneityReport r = check_homogeneity(lit(noise_image(128, 128, 3), vignette));
    EXPECT_LT(r.illumination_planar_fraction, 0.1); // symmetric: no planar part
    EXPECT_EQ(r.illumination_description, "darker towards the edges (vignette)");
    EXPECT_GT(r.illumination_amplitude, homogeneity_max_illumination_amplitude);
    EXPECT_TRUE(r.poor);
}

TEST(Homogeneity, NoiseIsHomogeneous)
{
    HomogeneityReport r = check_homogeneity(noise_image(128, 96, 3));
    EXPECT_LT(r.illumination_amplitude, 0.05); // fit of pure noise: a few coefficient errors
    EXPECT_LT(r.local_mean_variation, 0.02);   // 16 tiles of 1024 pixels: 0.29/32/1 ≈ 1 %
    EXPECT_LT(r.local_contrast_variation, 0.03);
    EXPECT_GT(r.score, 0.99);
    EXPECT_FALSE(r.poor);
    EXPECT_TRUE(r.warnings.empty());
    // 4 tiles of 24 across the shorter side; 5 fit across 128, centred.
    EXPECT_EQ(r.tile_size, 24);
    EXPECT_EQ(r.tiles_x, 5);
    EXPECT_EQ(r.tiles_y, 4);
}

TEST(Homogeneity, ContrastThatChangesAcrossTheSampleIsFlagged)
{
    // Left half rough, right half smooth (a fifth of the contrast), same mean: no
    // lighting change, but not one texture either.
    PlanarImage img = noise_image(128, 128, 3);
    for (Plane& p : img.channels)
        for (int y = 0; y < 128; ++y)
            for (int x = 64; x < 128; ++x)
                p(x, y) = 1.0f + 0.2f * (p(x, y) - 1.0f);
    HomogeneityReport r = check_homogeneity(img);
    EXPECT_LT(r.illumination_amplitude, 0.05);
    EXPECT_LT(r.local_mean_variation, 0.02);
    EXPECT_NEAR(r.local_contrast_variation, 0.4 / 0.6, 0.03); // tiles at c and c/5
    EXPECT_TRUE(r.poor);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].find("the local contrast varies"), 0u) << r.warnings[0];
}

TEST(Homogeneity, FlattenRemovesAMultiplicativeGradient)
{
    // A ramp plus curvature: within the quadratic model, so only the noise limits it.
    const PlanarImage texture = noise_image(128, 128, 3);
    PlanarImage img = lit(texture, [](double u, double v) {
        return 0.6 + 0.8 * u + 0.3 * (v - 0.5) * (v - 0.5) - 0.2 * u * v;
    });
    const double mean_before = mean(luminance_of(img));
    flatten_illumination(img);
    for (int c = 0; c < 3; ++c) // what is left is the texture times a constant
        EXPECT_LT(ratio_spread(img.channels[size_t(c)], texture.channels[size_t(c)]), 0.01) << c;
    EXPECT_NEAR(mean(luminance_of(img)), mean_before, 1e-5 * mean_before); // float sums
    EXPECT_LT(check_homogeneity(img).illumination_amplitude, 0.05);
}

TEST(Homogeneity, FlattenChangesAHomogeneousSampleLittle)
{
    const PlanarImage stucco = linear_planes("stucco_yellow.png");
    PlanarImage flat = stucco;
    flatten_illumination(flat);
    // stucco's own fitted amplitude is 2 %: no pixel moves by more than that.
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        for (size_t i = 0; i < flat.channels[size_t(c)].size(); ++i)
            worst = std::max(worst,
                std::abs(double(flat.channels[size_t(c)].data()[i])
                        / double(stucco.channels[size_t(c)].data()[i])
                    - 1.0));
    EXPECT_LT(worst, check_homogeneity(stucco).illumination_amplitude);
    EXPECT_GT(worst, 0.0);
}

TEST(Homogeneity, BitIdenticalAtAnyThreadCount)
{
    // 100x75: the last row block is partial.
    const PlanarImage img = lit(noise_image(100, 75, 4), ramp);
    HomogeneityReport r1 = check_homogeneity(img, 1);
    for (int n : { 2, 3, 0 }) {
        HomogeneityReport rn = check_homogeneity(img, n);
        EXPECT_EQ(rn.illumination.coefficients, r1.illumination.coefficients) << n;
        EXPECT_EQ(rn.illumination_amplitude, r1.illumination_amplitude) << n;
        EXPECT_EQ(rn.local_mean_variation, r1.local_mean_variation) << n;
        EXPECT_EQ(rn.local_contrast_variation, r1.local_contrast_variation) << n;
        EXPECT_EQ(rn.score, r1.score) << n;
    }
    PlanarImage a = img, b = img;
    flatten_illumination(a, 1);
    for (int n : { 2, 3, 0 }) {
        b = img;
        flatten_illumination(b, n);
        EXPECT_TRUE(same_bits(a, b)) << n;
    }
}

TEST(Homogeneity, ConstantAndBlackImages)
{
    PlanarImage grey = noise_image(64, 64, 3);
    for (Plane& p : grey.channels)
        std::fill(p.data(), p.data() + p.size(), 0.18f);
    HomogeneityReport r = check_homogeneity(grey);
    EXPECT_LT(r.illumination_amplitude, 1e-9); // rounding of the normal equations
    EXPECT_EQ(r.illumination_description, "flat");
    EXPECT_LT(r.local_mean_variation, 1e-9);
    EXPECT_EQ(r.local_contrast_variation, 0.0);
    EXPECT_FALSE(r.poor);
    PlanarImage flat = grey;
    flatten_illumination(flat);
    for (const Plane& p : flat.channels)
        for (size_t i = 0; i < p.size(); ++i)
            ASSERT_NEAR(p.data()[i], 0.18f, 1e-6f);

    PlanarImage black = grey;
    for (Plane& p : black.channels)
        std::fill(p.data(), p.data() + p.size(), 0.0f);
    r = check_homogeneity(black);
    EXPECT_EQ(r.illumination_amplitude, 0.0);
    EXPECT_FALSE(r.poor);
    flat = black;
    flatten_illumination(flat); // nothing to divide by: unchanged
    EXPECT_TRUE(same_bits(flat, black));
}

TEST(Homogeneity, OneChannelIsItsOwnLuminance)
{
    PlanarImage grey = lit(noise_image(96, 96, 1), ramp);
    HomogeneityReport r = check_homogeneity(grey);
    EXPECT_NEAR(r.illumination_amplitude, 95.0 / 96.0, kAmplitudeTolerance); // pixel centres
    EXPECT_NEAR(r.illumination_direction, 0.0, 1.5);
    flatten_illumination(grey);
    EXPECT_LT(ratio_spread(grey.channels[0], noise_image(96, 96, 1).channels[0]), 0.01);
}

TEST(Homogeneity, AlphaAndExtraChannelsAreNeitherMeasuredNorChanged)
{
    // RGBA + Z, with a steep gradient in A and Z only.
    PlanarImage img = lit(noise_image(64, 64, 3), ramp);
    img.channels.emplace_back(64, 64);
    img.channels.emplace_back(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            img.channels[3](x, y) = float(x) / 63.0f;
            img.channels[4](x, y) = 10.0f + float(y);
        }
    img.channel_names = { "R", "G", "B", "A", "Z" };
    img.alpha_channel = 3;
    PlanarImage rgb = img;
    rgb.channels.resize(3);
    rgb.channel_names.resize(3);
    rgb.alpha_channel = -1;
    EXPECT_EQ(check_homogeneity(img).illumination.coefficients,
        check_homogeneity(rgb).illumination.coefficients);

    PlanarImage flat = img;
    flatten_illumination(flat);
    flatten_illumination(rgb);
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(std::memcmp(flat.channels[size_t(c)].data(), rgb.channels[size_t(c)].data(),
                      rgb.channels[size_t(c)].size() * sizeof(float)),
            0);
    for (int c = 3; c < 5; ++c)
        EXPECT_EQ(std::memcmp(flat.channels[size_t(c)].data(), img.channels[size_t(c)].data(),
                      img.channels[size_t(c)].size() * sizeof(float)),
            0)
            << c;
}

TEST(Homogeneity, TooSmallOrEmptyImagesSaySo)
{
    HomogeneityReport r = check_homogeneity(lit(noise_image(12, 40, 3), ramp));
    EXPECT_EQ(r.tiles_x, 0);
    EXPECT_GT(r.illumination_amplitude, 0.5); // the fit still works
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_EQ(r.warnings.back(), "the sample is 12x40: too small to compare tiles (needs 16x16)");

    r = check_homogeneity(PlanarImage());
    EXPECT_TRUE(r.poor);
    EXPECT_EQ(r.score, 0.0);
    ASSERT_EQ(r.warnings.size(), 1u);
    PlanarImage empty;
    flatten_illumination(empty); // no crash, nothing to do
    EXPECT_EQ(empty.nchannels(), 0);
}

// Issue #4: the bundled samples are not flagged; with the issue's ramp or a lens
// vignette multiplied in (in scene-linear) they are. docs/homogeneity.md has the numbers.
TEST(Homogeneity, BundledSamplesPassAndTheirLitVersionsAreFlagged)
{
    for (const char* name :
        { "stucco_yellow.png", "rust.png", "marble_pink.png", "paper_crinkled.png" }) {
        const PlanarImage s = linear_planes(name);
        HomogeneityReport clean = check_homogeneity(s);
        EXPECT_FALSE(clean.poor) << name << " score " << clean.score;
        // rust.png has a real 46% ramp: fine for the pyramid, uneven for copying methods.
        const bool ramped_already = std::string(name) == "rust.png";
        EXPECT_EQ(clean.uneven_for_copying, ramped_already) << name;
        EXPECT_EQ(clean.warnings.size(), ramped_already ? 1u : 0u) << name;
        HomogeneityReport ramped = check_homogeneity(lit(s, ramp));
        EXPECT_TRUE(ramped.poor) << name << " with a ramp, score " << ramped.score;
        EXPECT_LT(ramped.score, clean.score) << name;
        EXPECT_TRUE(check_homogeneity(lit(s, vignette)).poor) << name << " with a vignette";
    }
}

// Issue #4: synthesis from a sample with a lighting gradient is blotchy, and flatten=1
// fixes it. "Blotchy" in numbers: the output's tile means vary (local mean variation),
// and its luminance histogram is the gradient-widened one instead of the texture's.
TEST(Homogeneity, FlatteningTheSampleImprovesTheSynthesis)
{
    const PlanarImage clean = linear_planes("stucco_yellow.png");
    OIIO::ImageBuf sample;
    imagebuf_from_planes(lit(clean, ramp), sample);
    PyramidOptions opt;
    opt.width = opt.height = 128;
    opt.iterations = 3;
    opt.seed = 3;
    auto synthesize = [&](int flatten) {
        opt.flatten = flatten;
        OIIO::ImageBuf out = pyramid_synthesize(sample, opt);
        EXPECT_FALSE(out.has_error()) << out.geterror();
        PlanarImage planes;
        std::string error;
        EXPECT_TRUE(planes_from_imagebuf(out, planes, error)) << error;
        return planes;
    };
    const PlanarImage plain = synthesize(0), flattened = synthesize(1);
    const QuantileTable clean_y(luminance_of(clean));
    const double blotch_plain = check_homogeneity(plain).local_mean_variation;
    const double blotch_flat = check_homogeneity(flattened).local_mean_variation;
    const double w1_plain = wasserstein1(QuantileTable(luminance_of(plain)), clean_y);
    const double w1_flat = wasserstein1(QuantileTable(luminance_of(flattened)), clean_y);
    // Measured: tile means vary by 5.4 % against 1.9 % (the clean sample's own synthesis:
    // 1.8 %); W1 to the clean luminance 0.12 against 0.0007. Asserted with room for other
    // seeds and platforms.
    EXPECT_LT(2.0 * blotch_flat, blotch_plain);
    EXPECT_LT(10.0 * w1_flat, w1_plain) << w1_flat << " " << w1_plain;
}

// The copying methods' evenness test: a lighting ramp that explains how the sample's regions
// differ, and leaves its relative contrast even, is uneven for them above 30%; large
// features that a quadratic fit follows (the flowers' blooms) are not lighting.
TEST(Homogeneity, ALightingRampIsUnevenForTheCopyingMethods)
{
    EXPECT_TRUE(check_homogeneity(linear_planes("bricks.png")).uneven_for_copying);
    const HomogeneityReport flowers = check_homogeneity(linear_planes("flowers.png"));
    EXPECT_GT(flowers.illumination_amplitude, homogeneity_max_lighting_for_copying);
    EXPECT_FALSE(flowers.uneven_for_copying);
    for (const char* name : { "stucco_yellow.png", "pebbles.png", "grass.png" }) {
        const PlanarImage s = linear_planes(name);
        EXPECT_FALSE(check_homogeneity(s).uneven_for_copying) << name;
        const HomogeneityReport ramped = check_homogeneity(lit(s, ramp));
        EXPECT_TRUE(ramped.uneven_for_copying)
            << name << ": " << ramped.illumination_amplitude << ", share " << ramped.lighting_share;
        EXPECT_GT(ramped.lighting_share, homogeneity_min_lighting_share) << name;
    }
}
