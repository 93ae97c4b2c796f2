// SPDX-License-Identifier: Apache-2.0
// Colour: PCA decorrelation (Heeger & Bergen 1995 §3.5) and OCIO colour management with
// the bundled config.
#include <texsyn/color.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <utility>

#include <unistd.h> // getpid

#include <Eigen/Dense>

#include <gtest/gtest.h>

using namespace texsyn;

namespace {

PlanarImage make_image(int w, int h, int nchannels)
{
    PlanarImage img;
    for (int c = 0; c < nchannels; ++c) {
        img.channels.emplace_back(w, h);
        img.channel_names.push_back(std::string(1, "RGBAZ"[c % 5]));
    }
    return img;
}

// Colours x = A z + b with z standard normal: strongly correlated channels.
PlanarImage correlated_rgb(int w, int h, unsigned seed)
{
    PlanarImage img = make_image(w, h, 3);
    std::mt19937 rng(seed);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    const float a[3][3]
        = { { 0.20f, 0.05f, 0.01f }, { 0.15f, 0.06f, -0.02f }, { 0.10f, 0.02f, 0.03f } };
    const float b[3] = { 0.5f, 0.4f, 0.3f };
    for (size_t i = 0; i < img.channels[0].size(); ++i) {
        const float z[3] = { normal(rng), normal(rng), normal(rng) };
        for (int c = 0; c < 3; ++c)
            img.channels[size_t(c)].data()[i]
                = b[c] + a[c][0] * z[0] + a[c][1] * z[1] + a[c][2] * z[2];
    }
    return img;
}

double covariance(const PlanarImage& img, int a, int b)
{
    const size_t n = img.channels[0].size();
    const float* pa = img.channels[size_t(a)].data();
    const float* pb = img.channels[size_t(b)].data();
    double ma = 0, mb = 0, s = 0;
    for (size_t i = 0; i < n; ++i) {
        ma += pa[i];
        mb += pb[i];
    }
    ma /= double(n);
    mb /= double(n);
    for (size_t i = 0; i < n; ++i)
        s += (pa[i] - ma) * (pb[i] - mb);
    return s / double(n);
}

void expect_round_trip(const PlanarImage& original, const ColorTransform& t, double tol)
{
    PlanarImage img = original;
    decorrelate(img, t);
    for (const Plane& p : img.channels)
        for (size_t i = 0; i < p.size(); ++i)
            ASSERT_TRUE(std::isfinite(p.data()[i]));
    recorrelate(img, t);
    for (int c = 0; c < original.nchannels(); ++c)
        for (size_t i = 0; i < original.channels[0].size(); ++i)
            ASSERT_NEAR(
                img.channels[size_t(c)].data()[i], original.channels[size_t(c)].data()[i], tol)
                << "channel " << c << " pixel " << i;
}

std::string temp_file(const std::string& name, const std::string& text)
{
    const std::string file = "texsyn_color_test_" + std::to_string(::getpid()) + "_" + name;
    const std::filesystem::path p = std::filesystem::temp_directory_path() / file;
    std::ofstream(p) << text;
    return p.string();
}

// Every OCIO test starts without $OCIO, so the bundled config is what loads.
class Ocio : public ::testing::Test {
protected:
    void SetUp() override
    {
        ::unsetenv("OCIO");
        std::string error;
        config = ColorConfig::load("", error);
        ASSERT_TRUE(config) << error;
    }
    std::unique_ptr<ColorConfig> config;
};

} // namespace

TEST(Decorrelation, CovarianceIsIdentity)
{
    PlanarImage img = correlated_rgb(128, 96, 1u);
    const ColorTransform t = fit_color_transform(img, 3);
    ASSERT_EQ(t.n, 3);
    for (int k = 0; k < 3; ++k)
        EXPECT_FALSE(t.constant[size_t(k)]);
    decorrelate(img, t);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            // Float storage of the components (~1e-7 relative) and a double fit.
            EXPECT_NEAR(covariance(img, a, b), a == b ? 1.0 : 0.0, 1e-4) << a << "," << b;
}

TEST(Decorrelation, RoundTripIsExact)
{
    const PlanarImage img = correlated_rgb(64, 64, 2u);
    // Two float roundings of values ~1 through a well-conditioned 3x3 map.
    expect_round_trip(img, fit_color_transform(img, 3), 1e-5);
}

TEST(Decorrelation, SignConventionAndOrder)
{
    const ColorTransform t = fit_color_transform(correlated_rgb(64, 64, 3u), 3);
    for (int k = 0; k < 3; ++k) {
        // Column k of M^-1 = U S: its largest-|.| entry is positive.
        int imax = 0;
        for (int c = 1; c < 3; ++c)
            if (std::abs(t.inverse[size_t(c * 3 + k)]) > std::abs(t.inverse[size_t(imax * 3 + k)]))
                imax = c;
        EXPECT_GT(t.inverse[size_t(imax * 3 + k)], 0.0) << "component " << k;
    }
    // Components come in decreasing variance: column norms of U S are S.
    auto norm = [&](int k) {
        double s = 0;
        for (int c = 0; c < 3; ++c)
            s += t.inverse[size_t(c * 3 + k)] * t.inverse[size_t(c * 3 + k)];
        return s;
    };
    EXPECT_GT(norm(0), norm(1));
    EXPECT_GT(norm(1), norm(2));
}

TEST(Decorrelation, ConstantImage)
{
    PlanarImage img = make_image(16, 16, 3);
    const float v[3] = { 0.3f, 0.5f, 0.7f };
    for (int c = 0; c < 3; ++c)
        std::fill(img.channels[size_t(c)].data(), img.channels[size_t(c)].data() + 256, v[c]);
    const ColorTransform t = fit_color_transform(img, 3);
    for (int k = 0; k < 3; ++k)
        EXPECT_TRUE(t.constant[size_t(k)]);
    // Unit scale: the round trip only rounds to float twice.
    expect_round_trip(img, t, 1e-7);
}

TEST(Decorrelation, ColoursOnALineAndAPlane)
{
    for (int rank : { 1, 2 }) {
        PlanarImage img = make_image(64, 32, 3);
        std::mt19937 rng(7u);
        std::normal_distribution<double> normal(0.0, 1.0);
        const double d0[3] = { 0.6, 0.3, 0.1 }, d1[3] = { -0.1, 0.2, 0.05 };
        for (size_t i = 0; i < img.channels[0].size(); ++i) {
            const double s = normal(rng), r = rank == 2 ? normal(rng) : 0.0;
            for (int c = 0; c < 3; ++c)
                img.channels[size_t(c)].data()[i] = float(0.4 + s * d0[c] + r * d1[c]);
        }
        const ColorTransform t = fit_color_transform(img, 3);
        int nconstant = 0;
        for (int k = 0; k < 3; ++k)
            nconstant += t.constant[size_t(k)] ? 1 : 0;
        // Float storage leaves ~1e-8 relative noise off the line/plane, far below 1e-6.
        EXPECT_EQ(nconstant, 3 - rank) << "rank " << rank;
        // Values ~1: two float roundings plus the off-subspace rounding noise.
        expect_round_trip(img, t, 1e-5);
        PlanarImage dec = img;
        decorrelate(dec, t);
        for (int k = 0; k < rank; ++k)
            EXPECT_NEAR(covariance(dec, k, k), 1.0, 1e-4) << "rank " << rank; // as above
    }
}

TEST(Decorrelation, OneChannelIsStandardisation)
{
    PlanarImage img = make_image(50, 20, 1);
    for (size_t i = 0; i < img.channels[0].size(); ++i)
        img.channels[0].data()[i] = float(i % 10); // mean 4.5, variance 8.25
    const ColorTransform t = fit_color_transform(img, 1);
    ASSERT_EQ(t.n, 1);
    EXPECT_NEAR(t.mean[0], 4.5, 1e-12);                      // exact sums of small integers
    EXPECT_NEAR(t.forward[0], 1.0 / std::sqrt(8.25), 1e-12); // double eigensolver on 1x1
    EXPECT_NEAR(t.inverse[0], std::sqrt(8.25), 1e-12);
    expect_round_trip(img, t, 1e-5); // two float roundings of values up to 9
}

TEST(Decorrelation, OnlyFirstChannelsTouchedAndThreadIndependent)
{
    PlanarImage img = correlated_rgb(80, 60, 4u);
    img.channels.emplace_back(80, 60, 0.25f);
    img.channel_names.push_back("A");
    img.alpha_channel = 3;
    const ColorTransform t = fit_color_transform(img, img.ncolor());
    PlanarImage one = img, many = img;
    decorrelate(one, t, 1);
    decorrelate(many, t, 4);
    for (int c = 0; c < 4; ++c)
        EXPECT_EQ(0,
            std::memcmp(one.channels[size_t(c)].data(), many.channels[size_t(c)].data(),
                one.channels[0].size() * sizeof(float)));
    for (size_t i = 0; i < one.channels[3].size(); ++i)
        ASSERT_EQ(one.channels[3].data()[i], 0.25f);
}

// Weights equal to the pixel shares give the moments of the pooled pixels (the law of total
// covariance), and the transform from them decorrelates the pooled image.
TEST(Decorrelation, MixtureMomentsAreThePooledPixelsMoments)
{
    PlanarImage a = correlated_rgb(40, 30, 5u), b = correlated_rgb(50, 20, 6u);
    for (size_t i = 0; i < b.channels[0].size(); ++i) // shift b: the means differ
        b.channels[1].data()[i] += 0.3f;
    PlanarImage pooled = make_image(int(a.channels[0].size() + b.channels[0].size()), 1, 3);
    for (size_t c = 0; c < 3; ++c) {
        std::copy_n(a.channels[c].data(), a.channels[c].size(), pooled.channels[c].data());
        std::copy_n(b.channels[c].data(), b.channels[c].size(),
            pooled.channels[c].data() + a.channels[c].size());
    }
    const ColorMoments m = mixture_moments(
        { color_moments(a, 3), color_moments(b, 3) }, { 1200.0, 1000.0 }); // 40x30, 50x20
    const ColorMoments want = color_moments(pooled, 3);
    ASSERT_EQ(m.n, 3);
    for (size_t i = 0; i < 3; ++i)
        EXPECT_NEAR(m.mean[i], want.mean[i], 1e-12);
    for (size_t i = 0; i < 9; ++i) // different summation orders
        EXPECT_NEAR(m.covariance[i], want.covariance[i], 1e-12);
    PlanarImage d = pooled;
    decorrelate(d, color_transform_from_moments(m));
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(covariance(d, r, c), r == c ? 1.0 : 0.0, 1e-4);
    EXPECT_EQ(mixture_moments({ color_moments(a, 3), color_moments(b, 2) }, { 1.0, 1.0 }).n, 0);
    EXPECT_EQ(mixture_moments({ color_moments(a, 3) }, { 0.0 }).n, 0);
}

TEST_F(Ocio, BundledConfigLoadsAndResolves)
{
    EXPECT_EQ(config->source(), ColorConfig::bundled_name);
    EXPECT_TRUE(config->is_bundled());
    EXPECT_EQ(config->scene_linear(), "Linear Rec.709 (sRGB)");
    const std::vector<std::string> expected
        = { "Linear Rec.709 (sRGB)", "sRGB - Texture", "ACEScg", "Raw", "CIE-XYZ-D65" };
    EXPECT_EQ(config->colorspace_names(), expected);
    EXPECT_EQ(config->resolve("sRGB"), "sRGB - Texture");
    EXPECT_EQ(config->resolve("srgb_tx"), "sRGB - Texture");
    EXPECT_EQ(config->resolve("linear"), "Linear Rec.709 (sRGB)");
    EXPECT_EQ(config->resolve("Linear"), "Linear Rec.709 (sRGB)");
    EXPECT_EQ(config->resolve("scene_linear"), "Linear Rec.709 (sRGB)");
    EXPECT_EQ(config->resolve("NoSuchSpace"), "");
    EXPECT_TRUE(config->is_data("Raw"));
    EXPECT_TRUE(config->is_data("data"));
    EXPECT_FALSE(config->is_data("ACEScg"));

    // The embedded text is the file that is installed.
    std::ifstream file(TEXSYN_BUNDLED_OCIO_CONFIG);
    std::stringstream text;
    text << file.rdbuf();
    EXPECT_EQ(text.str(), ColorConfig::bundled_config_text());
    std::string error;
    auto from_file = ColorConfig::load(TEXSYN_BUNDLED_OCIO_CONFIG, error);
    ASSERT_TRUE(from_file) << error;
    EXPECT_EQ(from_file->source(), TEXSYN_BUNDLED_OCIO_CONFIG);
}

TEST_F(Ocio, SrgbToLinear)
{
    PlanarImage img = make_image(1, 1, 3);
    for (Plane& p : img.channels)
        p.data()[0] = 0.5f;
    std::string error;
    ASSERT_TRUE(config->convert(img, "sRGB", "scene_linear", error)) << error;
    for (const Plane& p : img.channels)
        EXPECT_NEAR(p.data()[0], 0.214041f, 1e-5); // ((0.5 + 0.055)/1.055)^2.4, 6 digits given
}

TEST_F(Ocio, LinearRedToAcescg)
{
    PlanarImage img = make_image(1, 1, 3);
    img.channels[0].data()[0] = 1.0f;
    std::string error;
    ASSERT_TRUE(config->convert(img, "Linear Rec.709 (sRGB)", "ACEScg", error)) << error;
    // Bradford Rec.709 -> AP1 matrix, first column; reference values given to 4 decimals.
    EXPECT_NEAR(img.channels[0].data()[0], 0.6131f, 1e-4);
    EXPECT_NEAR(img.channels[1].data()[0], 0.0702f, 1e-4);
    EXPECT_NEAR(img.channels[2].data()[0], 0.0206f, 1e-4);
}

TEST_F(Ocio, RoundTripKeepsAlphaAndExtraChannels)
{
    PlanarImage img = make_image(33, 17, 5);
    img.alpha_channel = 3;
    for (int c = 0; c < 5; ++c)
        for (size_t i = 0; i < img.channels[0].size(); ++i)
            img.channels[size_t(c)].data()[i] = float((i * 7 + size_t(c) * 13) % 101) / 100.0f;
    const PlanarImage original = img;
    std::string error;
    ASSERT_TRUE(config->convert(img, "sRGB - Texture", "scene_linear", error, 2)) << error;
    EXPECT_NE(img.channels[0].data()[1], original.channels[0].data()[1]);
    ASSERT_TRUE(config->convert(img, "scene_linear", "sRGB - Texture", error, 2)) << error;
    for (int c = 0; c < 5; ++c)
        for (size_t i = 0; i < img.channels[0].size(); ++i) {
            const float got = img.channels[size_t(c)].data()[i];
            const float want = original.channels[size_t(c)].data()[i];
            if (c < 3)
                ASSERT_NEAR(got, want, 1e-5); // float pow and its inverse on [0, 1]
            else
                ASSERT_EQ(got, want);
        }
}

TEST_F(Ocio, GreyChannels)
{
    PlanarImage grey = make_image(4, 3, 1);
    std::fill(grey.channels[0].data(), grey.channels[0].data() + 12, 0.5f);
    std::string error;
    ASSERT_TRUE(config->convert(grey, "sRGB", "linear", error)) << error;
    for (size_t i = 0; i < 12; ++i)
        EXPECT_NEAR(grey.channels[0].data()[i], 0.214041f, 1e-5); // as for RGB

    PlanarImage grey_alpha = make_image(4, 3, 2);
    grey_alpha.alpha_channel = 1;
    std::fill(grey_alpha.channels[0].data(), grey_alpha.channels[0].data() + 12, 0.5f);
    std::fill(grey_alpha.channels[1].data(), grey_alpha.channels[1].data() + 12, 0.5f);
    ASSERT_TRUE(config->convert(grey_alpha, "sRGB", "ACEScg", error)) << error;
    for (size_t i = 0; i < 12; ++i) {
        // Grey stays grey in ACEScg (matrix rows sum to 1), so only the transfer applies.
        EXPECT_NEAR(grey_alpha.channels[0].data()[i], 0.214041f, 1e-5);
        EXPECT_EQ(grey_alpha.channels[1].data()[i], 0.5f);
    }
}

TEST_F(Ocio, DataAndIdentityAreNoOps)
{
    PlanarImage img = make_image(2, 2, 3);
    std::fill(img.channels[0].data(), img.channels[0].data() + 4, 0.5f);
    const PlanarImage original = img;
    std::string error;
    EXPECT_TRUE(config->convert(img, "Raw", "ACEScg", error));
    EXPECT_TRUE(config->convert(img, "sRGB", "Raw", error));
    EXPECT_TRUE(config->convert(img, "sRGB", "srgb_tx", error));
    for (int c = 0; c < 3; ++c)
        EXPECT_EQ(0,
            std::memcmp(img.channels[size_t(c)].data(), original.channels[size_t(c)].data(),
                4 * sizeof(float)));
}

namespace {

// convert_image() as the planes make it: the slow oracle of its copy between one space.
bool convert_image_through_planes(const ColorConfig& config, const OIIO::ImageBuf& src,
    const std::string& from, const std::string& to, bool associate, OIIO::ImageBuf& dst,
    std::string& error)
{
    PlanarImage planes;
    if (!planes_from_imagebuf(src, planes, error) || !config.convert(planes, from, to, error))
        return false;
    imagebuf_from_planes(planes, dst, associate);
    for (const OIIO::ParamValue& p : src.spec().extra_attribs)
        if (p.name() != "oiio:UnassociatedAlpha")
            dst.specmod().attribute(p.name(), p.type(), p.data());
    return true;
}

} // namespace

// convert_image takes two paths: finite float pixels without alpha are copied once and
// converted in place; the rest go through planes. Both give the planes' pixels bit for bit
// (extra channels untouched, rows in several parallel blocks), and the same spec and errors.
TEST_F(Ocio, ImageConversionIsThePlanesConversion)
{
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> value(-2.0f, 2.0f);
    auto image = [&](int nchannels, int alpha, OIIO::TypeDesc type, int w = 37, int h = 23) {
        OIIO::ImageSpec spec(w, h, nchannels, type);
        spec.x = 5;
        spec.y = -3;
        spec.alpha_channel = alpha;
        spec.attribute("synth:method", "test");
        OIIO::ImageBuf buf(spec);
        std::vector<float> px(size_t(w) * size_t(h) * size_t(nchannels));
        for (float& v : px)
            v = value(rng);
        px[0] = -0.0f;
        px[1] = 1e-40f; // denormal
        buf.set_pixels(buf.roi(), OIIO::TypeFloat, px.data());
        return buf;
    };
    const OIIO::ImageBuf rgb = image(3, -1, OIIO::TypeFloat), rgba = image(4, 3, OIIO::TypeFloat),
                         bytes = image(3, -1, OIIO::TypeUInt8),
                         five = image(5, -1, OIIO::TypeFloat),
                         wide = image(3, -1, OIIO::TypeFloat, 300, 200); // 4 row blocks
    OIIO::ImageBuf inf = image(3, -1, OIIO::TypeFloat);
    const float infinity[3] = { 0.5f, 0.5f, std::numeric_limits<float>::infinity() };
    inf.setpixel(11, 7, infinity);
    const std::vector<std::pair<std::string, std::string>> spaces
        = { { "scene_linear", "Linear Rec.709 (sRGB)" }, { "Raw", "ACEScg" },
              { "sRGB", "raw_data" }, { "sRGB", "ACEScg" } };
    for (const OIIO::ImageBuf* src : { &rgb, &rgba, &bytes, &five, &wide, &std::as_const(inf) })
        for (const auto& [from, to] : spaces)
            for (bool associate : { true, false }) {
                OIIO::ImageBuf got, want;
                std::string got_error, want_error;
                const bool ok = config->convert_image(*src, from, to, associate, got, got_error);
                ASSERT_EQ(ok,
                    convert_image_through_planes(
                        *config, *src, from, to, associate, want, want_error));
                EXPECT_EQ(got_error, want_error);
                if (!ok)
                    continue;
                EXPECT_EQ(got.spec().serialize(OIIO::ImageSpec::SerialText),
                    want.spec().serialize(OIIO::ImageSpec::SerialText));
                ASSERT_EQ(got.spec().image_bytes(), want.spec().image_bytes());
                EXPECT_EQ(
                    0, std::memcmp(got.localpixels(), want.localpixels(), got.spec().image_bytes()))
                    << from << " -> " << to << ", " << src->spec().nchannels << " channels";
            }
    OIIO::ImageBuf out;
    std::string error;
    EXPECT_FALSE(config->convert_image(inf, "linear", "linear", true, out, error));
    EXPECT_EQ(error, "pixel (11, 7) channel B is infinite; texsyn needs finite pixel values");
}

TEST_F(Ocio, UnknownSpaceFailsWithoutChanges)
{
    PlanarImage img = make_image(2, 2, 3);
    std::fill(img.channels[1].data(), img.channels[1].data() + 4, 0.5f);
    std::string error;
    EXPECT_FALSE(config->convert(img, "sRGB", "NoSuchSpace", error));
    EXPECT_EQ(error,
        "unknown colour space 'NoSuchSpace' (known: Linear Rec.709 (sRGB), sRGB - Texture, "
        "ACEScg, Raw, CIE-XYZ-D65; texsyn --colorspaces describes them)");
    // A near miss of a name or an alias is named.
    EXPECT_EQ(config->unknown_colorspace("srgb-tx").rfind(
                  "unknown colour space 'srgb-tx', did you mean 'srgb_tx'? (known: ", 0),
        0u);
    for (size_t i = 0; i < 4; ++i)
        EXPECT_EQ(img.channels[1].data()[i], 0.5f);
}

TEST_F(Ocio, BadConfigFileIsNamed)
{
    const std::string bad = temp_file("bad.ocio", "ocio_profile_version: 2.1\nroles: [oops\n");
    std::string error;
    EXPECT_FALSE(ColorConfig::load(bad, error));
    EXPECT_EQ(error.rfind("colour config '" + bad + "': ", 0), 0u) << error;
    EXPECT_GT(error.size(), bad.size() + 20) << "OCIO's message is included";

    const std::string missing = "/nonexistent/texsyn/config.ocio";
    EXPECT_FALSE(ColorConfig::load(missing, error));
    EXPECT_NE(error.find("'" + missing + "'"), std::string::npos) << error;
    std::filesystem::remove(bad);
}

TEST_F(Ocio, EnvironmentVariableIsHonoured)
{
    const std::string good = temp_file("env.ocio", ColorConfig::bundled_config_text());
    const std::string bad = temp_file("env_bad.ocio", "not: [a config");
    std::string error;

    ::setenv("OCIO", good.c_str(), 1);
    auto from_env = ColorConfig::load("", error);
    ASSERT_TRUE(from_env) << error;
    EXPECT_EQ(from_env->source(), good);

    ::setenv("OCIO", bad.c_str(), 1);
    EXPECT_FALSE(ColorConfig::load("", error));
    EXPECT_NE(error.find("'" + bad + "'"), std::string::npos) << error;
    // An explicit path takes precedence over $OCIO.
    auto explicit_path = ColorConfig::load(good, error);
    ASSERT_TRUE(explicit_path) << error;
    EXPECT_EQ(explicit_path->source(), good);

    ::unsetenv("OCIO");
    std::filesystem::remove(good);
    std::filesystem::remove(bad);
}

TEST_F(Ocio, GuessColorspace)
{
    OIIO::ImageSpec u8(8, 8, 3, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(config->guess_colorspace(u8).space, "sRGB - Texture");
    OIIO::ImageSpec u16(8, 8, 3, OIIO::TypeDesc::UINT16);
    EXPECT_EQ(config->guess_colorspace(u16).space, "sRGB - Texture");
    OIIO::ImageSpec f32(8, 8, 3, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(config->guess_colorspace(f32).space, "Linear Rec.709 (sRGB)");
    OIIO::ImageSpec f16(8, 8, 4, OIIO::TypeDesc::HALF);
    EXPECT_EQ(config->guess_colorspace(f16).space, "Linear Rec.709 (sRGB)");

    u8.attribute("oiio:ColorSpace", "sRGB"); // what OIIO's PNG reader sets
    EXPECT_EQ(config->guess_colorspace(u8).space, "sRGB - Texture");
    u8.attribute("oiio:ColorSpace", "NotInConfig");
    EXPECT_EQ(config->guess_colorspace(u8).space, "sRGB - Texture");
    f32.attribute("oiio:ColorSpace", "Linear"); // what OIIO reads back from float EXRs
    EXPECT_EQ(config->guess_colorspace(f32).space, "Linear Rec.709 (sRGB)");
    f16.attribute("oiio:ColorSpace", "ACEScg");
    EXPECT_EQ(config->guess_colorspace(f16).space, "ACEScg");
    u16.attribute("oiio:ColorSpace", "Raw");
    EXPECT_EQ(config->guess_colorspace(u16).space, "Raw");
}

TEST_F(Ocio, GuessSaysWhyAndDoubtsGenericTags)
{
    OIIO::ImageSpec f32(8, 8, 3, OIIO::TypeDesc::FLOAT);
    ColorConfig::Guess g = config->guess_colorspace(f32);
    EXPECT_EQ(g.reason, "no colour tag: floating-point files are taken as scene-linear");
    EXPECT_EQ(g.warning, "");
    f32.attribute("oiio:ColorSpace", "Linear");
    g = config->guess_colorspace(f32);
    EXPECT_EQ(g.reason, "its oiio:ColorSpace tag 'Linear'");
    EXPECT_EQ(g.warning.rfind("the tag 'Linear' is a generic name", 0), 0u) << g.warning;
    f32.attribute("oiio:ColorSpace", "scene_linear"); // a role: as generic
    EXPECT_NE(config->guess_colorspace(f32).warning, "");
    f32.attribute("oiio:ColorSpace", "NotInConfig");
    EXPECT_EQ(config->guess_colorspace(f32).reason,
        "a tag 'NotInConfig' the config does not know: floating-point files are taken as "
        "scene-linear");
    // texsyn's own tags come first; the description stands in where the format keeps none.
    f32.attribute("ImageDescription", "texsyn 0.1.0 --pyramid:size=8x8 seed 0, colorspace ACEScg");
    g = config->guess_colorspace(f32);
    EXPECT_EQ(g.space, "ACEScg");
    EXPECT_EQ(g.reason, "its texsyn ImageDescription (the format keeps no tag)");
    f32.attribute("synth:colorspace", "Raw");
    EXPECT_EQ(config->guess_colorspace(f32).space, "Raw");
    // Someone else's description is not read.
    OIIO::ImageSpec u8(8, 8, 3, OIIO::TypeDesc::UINT8);
    u8.attribute("ImageDescription", "scan, colorspace ACEScg");
    EXPECT_EQ(config->guess_colorspace(u8).space, "sRGB - Texture");
}

TEST_F(Ocio, ChromaticitiesComeFromTheInterchangeRole)
{
    float xy[8];
    ASSERT_TRUE(config->chromaticities("Linear Rec.709 (sRGB)", xy));
    const float rec709[8] = { 0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f };
    for (int i = 0; i < 8; ++i)
        EXPECT_NEAR(xy[i], rec709[i], 1e-4f) << i;
    ASSERT_TRUE(config->chromaticities("sRGB", xy)); // same primaries, other encoding
    EXPECT_NEAR(xy[0], 0.64f, 1e-4f);
    // ACEScg: AP1 primaries, Bradford-adapted from their D60 white to D65 as the config
    // converts them (red stays near AP1's 0.713, 0.293).
    ASSERT_TRUE(config->chromaticities("ACEScg", xy));
    EXPECT_NEAR(xy[0], 0.713f, 2e-3f);
    EXPECT_NEAR(xy[6], 0.3127f, 1e-4f);
    EXPECT_NEAR(xy[7], 0.3290f, 1e-4f);
    // A reader that builds its RGB -> XYZ matrix from them sees the colours the config
    // makes: ACEScg -> linear Rec.709 by the config, then Rec.709's own matrix.
    Eigen::Matrix3d primaries;
    for (int i = 0; i < 3; ++i)
        primaries.col(i) << xy[2 * i] / xy[2 * i + 1], 1.0,
            (1.0 - xy[2 * i] - xy[2 * i + 1]) / xy[2 * i + 1];
    const Eigen::Vector3d white(xy[6] / xy[7], 1.0, (1.0 - xy[6] - xy[7]) / xy[7]);
    const Eigen::Vector3d scale = primaries.colPivHouseholderQr().solve(white);
    const Eigen::Matrix3d to_xyz = primaries * scale.asDiagonal();
    Eigen::Matrix3d rec709_to_xyz;
    rec709_to_xyz << 0.4123908, 0.3575843, 0.1804808, 0.2126390, 0.7151687, 0.0721923, 0.0193308,
        0.1191948, 0.9505322;
    PlanarImage px = make_image(1, 1, 3);
    const Eigen::Vector3d cg(0.2, 0.5, 0.8);
    for (int c = 0; c < 3; ++c)
        px.channels[size_t(c)].data()[0] = float(cg[c]);
    std::string error;
    ASSERT_TRUE(config->convert(px, "ACEScg", "Linear Rec.709 (sRGB)", error)) << error;
    const Eigen::Vector3d lin(
        px.channels[0].data()[0], px.channels[1].data()[0], px.channels[2].data()[0]);
    EXPECT_LT((to_xyz * cg - rec709_to_xyz * lin).norm(), 1e-4);
    EXPECT_FALSE(config->chromaticities("Raw", xy));
    EXPECT_FALSE(config->chromaticities("NoSuchSpace", xy));
}

TEST_F(Ocio, TagsNameTheSpaceForEveryFormat)
{
    OIIO::ImageSpec spec(8, 8, 3, OIIO::TypeDesc::UINT8);
    config->tag_colorspace(spec, "sRGB - Texture");
    EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "sRGB - Texture");
    EXPECT_EQ(spec.get_string_attribute("synth:colorspace"), "sRGB - Texture");
    EXPECT_EQ(spec.get_int_attribute("Exif:ColorSpace"), 1);
    EXPECT_NE(spec.find_attribute("chromaticities"), nullptr);
    config->tag_colorspace(spec, "ACEScg");
    EXPECT_EQ(spec.get_int_attribute("Exif:ColorSpace"), 65535); // TIFF: "uncalibrated"
    config->tag_colorspace(spec, "Raw");
    EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "Raw");
    EXPECT_EQ(spec.find_attribute("Exif:ColorSpace"), nullptr);
    EXPECT_EQ(spec.find_attribute("chromaticities"), nullptr);
}
