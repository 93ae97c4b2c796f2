// SPDX-License-Identifier: Apache-2.0
#include <texsyn/color.h>
#include <texsyn/fft.h>
#include <texsyn/histogram.h>
#include <texsyn/io.h>
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/random.h>

#include <cmath>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "test_samples.h"

using namespace texsyn;
using texsyn::test::linear_sample;
using texsyn::test::planes_of;

namespace {

PyramidOptions options(int w, int h, int iterations = 5)
{
    PyramidOptions opt;
    opt.width = w;
    opt.height = h;
    opt.iterations = iterations;
    opt.seed = 11;
    return opt;
}

// Mean absolute difference between column x0 and column x1 (wrapping), over all rows.
double column_step(const Plane& p, int x0, int x1)
{
    double s = 0.0;
    for (int y = 0; y < p.height(); ++y)
        s += std::abs(p(x0, y) - p(x1 % p.width(), y));
    return s / p.height();
}

double row_step(const Plane& p, int y0, int y1)
{
    double s = 0.0;
    for (int x = 0; x < p.width(); ++x)
        s += std::abs(p(x, y0) - p(x, y1 % p.height()));
    return s / p.width();
}

// Fraction of a plane's (non-DC) spectral energy on the two frequency axes, where the
// cross-shaped energy of a discontinuity at the wrap lives.
double axis_energy_fraction(const Plane& p)
{
    std::string error;
    auto fft = RealFft2D::create(p.width(), p.height(), FftBackend::Kiss, error);
    std::vector<std::complex<float>> spec(fft->spectrum_size());
    fft->forward(p.data(), spec.data());
    const int hw = p.width() / 2 + 1;
    double axis = 0.0, total = 0.0;
    for (int ky = 0; ky < p.height(); ++ky)
        for (int kx = 0; kx < hw; ++kx) {
            if (kx == 0 && ky == 0)
                continue;
            double e = std::norm(spec[size_t(ky) * hw + kx]);
            total += e;
            if (kx == 0 || ky == 0)
                axis += e;
        }
    return axis / total;
}

} // namespace

TEST(PyramidSynthesis, OutputHasTheRequestedSizeChannelsAndMetadata)
{
    OIIO::ImageBuf sample = linear_sample("stucco_yellow.png");
    OIIO::ImageBuf out = pyramid_synthesize(sample, options(200, 72, 2));
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_EQ(out.spec().width, 200);
    EXPECT_EQ(out.spec().height, 72);
    EXPECT_EQ(out.nchannels(), 3);
    EXPECT_EQ(out.spec().format, OIIO::TypeFloat);
    EXPECT_EQ(out.spec().get_string_attribute("synth:method"), "pyramid");
    EXPECT_EQ(out.spec().get_int_attribute("synth:seed"), 11);
    EXPECT_EQ(out.spec().get_string_attribute("synth:options"),
        "size=200x72:iterations=2:pyramid=steerable:scales=3:orientations=4:"
        "histogram=exact:fft=kiss:gain=1:balance=0:flatten=0");
}

TEST(PyramidSynthesis, BitIdenticalForASeedAtAnyThreadCount)
{
    OIIO::ImageBuf sample = linear_sample("marble_pink.png");
    PyramidOptions opt = options(160, 96, 2);
    opt.nthreads = 1;
    OIIO::ImageBuf a = pyramid_synthesize(sample, opt);
    opt.nthreads = 2;
    OIIO::ImageBuf b = pyramid_synthesize(sample, opt);
    opt.nthreads = 5;
    OIIO::ImageBuf c = pyramid_synthesize(sample, opt);
    ASSERT_FALSE(a.has_error() || b.has_error() || c.has_error());
    EXPECT_EQ(
        OIIO::ImageBufAlgo::computePixelHashSHA1(a), OIIO::ImageBufAlgo::computePixelHashSHA1(b));
    EXPECT_EQ(
        OIIO::ImageBufAlgo::computePixelHashSHA1(a), OIIO::ImageBufAlgo::computePixelHashSHA1(c));
    opt.seed = 12;
    OIIO::ImageBuf d = pyramid_synthesize(sample, opt);
    EXPECT_NE(
        OIIO::ImageBufAlgo::computePixelHashSHA1(a), OIIO::ImageBufAlgo::computePixelHashSHA1(d));
}

// The quality bar on three real samples: per-channel W1 < 0.005 (values in [0,1])
// and a wrap seam no rougher than 1.2x the interior.
class SynthesisQuality : public ::testing::TestWithParam<std::string> { };

TEST_P(SynthesisQuality, HistogramsMatchAndTheOutputTilesSeamlessly)
{
    OIIO::ImageBuf sample = linear_sample(GetParam());
    OIIO::ImageBuf out = pyramid_synthesize(sample, options(256, 256));
    ASSERT_FALSE(out.has_error()) << out.geterror();
    PlanarImage s = planes_of(sample), o = planes_of(out);
    for (int c = 0; c < 3; ++c) {
        double w1 = wasserstein1(QuantileTable(s.channels[c]), QuantileTable(o.channels[c]));
        EXPECT_LT(w1, 0.005) << GetParam() << " channel " << c;
        const Plane& p = o.channels[c];
        double interior_x = 0.0, interior_y = 0.0;
        for (int x = 0; x + 1 < p.width(); ++x)
            interior_x += column_step(p, x, x + 1) / (p.width() - 1);
        for (int y = 0; y + 1 < p.height(); ++y)
            interior_y += row_step(p, y, y + 1) / (p.height() - 1);
        EXPECT_LE(column_step(p, p.width() - 1, p.width()), 1.2 * interior_x) << GetParam();
        EXPECT_LE(row_step(p, p.height() - 1, p.height()), 1.2 * interior_y) << GetParam();
    }
}

INSTANTIATE_TEST_SUITE_P(Samples, SynthesisQuality,
    ::testing::Values("rust.png", "stucco_yellow.png", "marble_pink.png"));

TEST(PyramidSynthesis, NonPeriodicSampleGivesNoSeamLikeArtefacts)
{
    // A sample with a strong left-to-right ramp: as a torus it has a big edge at the wrap,
    // which a circular analysis would see as cross-shaped (axis) energy and reproduce as
    // straight horizontal and vertical streaks.
    OIIO::ImageBuf stucco = linear_sample("stucco_yellow.png");
    PlanarImage s = planes_of(stucco);
    Plane grey(128, 128);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x)
            grey(x, y) = s.channels[1](x, y) + 0.6f * float(x) / 127.0f + 0.4f * float(y) / 127.0f;
    PlanarImage sample_planes;
    sample_planes.channels.push_back(grey);
    sample_planes.channel_names = { "Y" };
    OIIO::ImageBuf sample;
    imagebuf_from_planes(sample_planes, sample);

    OIIO::ImageBuf out = pyramid_synthesize(sample, options(256, 256));
    ASSERT_FALSE(out.has_error()) << out.geterror();
    Plane p = periodic_component(grey, FftBackend::Kiss);
    double sample_axis = axis_energy_fraction(grey);
    double periodic_axis = axis_energy_fraction(p);
    double output_axis = axis_energy_fraction(planes_of(out).channels[0]);
    ASSERT_GT(sample_axis, 5.0 * periodic_axis) << "the test sample is not non-periodic enough";
    // An isotropic texture puts ~2/N of its energy on the axes; allow 2x the periodic
    // component's fraction for the statistics' sampling noise.
    EXPECT_LT(output_axis, 2.0 * periodic_axis)
        << "sample " << sample_axis << " periodic " << periodic_axis;
}

TEST(PyramidSynthesis, AlphaIsSynthesizedAsItsOwnChannel)
{
    Plane alpha;
    const OIIO::ImageBuf sample = test::stucco_with_alpha(alpha);
    OIIO::ImageBuf out = pyramid_synthesize(sample, options(128, 128, 3));
    ASSERT_FALSE(out.has_error()) << out.geterror();
    ASSERT_EQ(out.nchannels(), 4);
    EXPECT_EQ(out.spec().alpha_channel, 3);
    PlanarImage o = planes_of(out);
    // Exact-mode matching makes the alpha histogram the sample's up to quantile spacing.
    EXPECT_LT(wasserstein1(QuantileTable(alpha), QuantileTable(o.channels[3])), 1e-3);
}

TEST(PyramidSynthesis, LaplacianAndBins256ModesWork)
{
    OIIO::ImageBuf sample = linear_sample("paper_crinkled.png");
    PyramidOptions opt = options(128, 128, 3);
    opt.pyramid = PyramidKind::Laplacian;
    opt.histogram = HistogramMode::Bins256;
    OIIO::ImageBuf out = pyramid_synthesize(sample, opt);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    PlanarImage s = planes_of(sample), o = planes_of(out);
    for (int c = 0; c < 3; ++c) // 256 bins quantise the cdf: a looser bound than exact mode
        EXPECT_LT(wasserstein1(QuantileTable(s.channels[c]), QuantileTable(o.channels[c])), 0.01);
}

TEST(PyramidSynthesis, DegenerateColoursGiveFiniteCorrectResults)
{
    // Constant sample: the output is the constant.
    OIIO::ImageBuf flat(OIIO::ImageSpec(32, 32, 3, OIIO::TypeFloat));
    const float grey[3] = { 0.2f, 0.3f, 0.4f };
    OIIO::ImageBufAlgo::fill(flat, grey);
    OIIO::ImageBuf out = pyramid_synthesize(flat, options(40, 40, 2));
    ASSERT_FALSE(out.has_error()) << out.geterror();
    auto stats = OIIO::ImageBufAlgo::computePixelStats(out);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(stats.min[c], grey[c], 1e-6);
        EXPECT_NEAR(stats.max[c], grey[c], 1e-6);
    }
    // Colours on a line (grey texture in RGB): finite, and still grey.
    PlanarImage g = planes_of(linear_sample("stucco_yellow.png"));
    g.channels[0] = g.channels[1];
    g.channels[2] = g.channels[1];
    OIIO::ImageBuf line;
    imagebuf_from_planes(g, line);
    out = pyramid_synthesize(line, options(64, 64, 2));
    ASSERT_FALSE(out.has_error()) << out.geterror();
    PlanarImage o = planes_of(out); // fails on NaN/Inf
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            ASSERT_NEAR(o.channels[0](x, y), o.channels[2](x, y), 1e-4f);
}

TEST(PyramidSynthesis, RefusesSamplesTooSmallAndAbsurdSizes)
{
    OIIO::ImageBuf tiny(OIIO::ImageSpec(12, 12, 3, OIIO::TypeFloat));
    OIIO::ImageBuf out = pyramid_synthesize(tiny, options(64, 64));
    ASSERT_TRUE(out.has_error());
    EXPECT_EQ(out.geterror(), "sample is 12x12: the pyramid method needs at least 16x16");

    OIIO::ImageBuf sample = linear_sample("stucco_yellow.png");
    PyramidOptions opt = options(64, 64);
    opt.scales = 9;
    out = pyramid_synthesize(sample, opt);
    EXPECT_EQ(out.geterror(), "scales=9 is too many for a 128x128 sample (at most 4)");

    out = pyramid_synthesize(sample, options(200000, 200000));
    ASSERT_TRUE(out.has_error());
    std::string msg = out.geterror();
    EXPECT_EQ(msg.find("size=200000x200000 would need about "), 0u) << msg;
    EXPECT_NE(msg.find("TB of memory"), std::string::npos) << msg;
}

namespace {

// Mean square of band `name` of component 0 of `image`, analysed in `basis`.
double band_energy(
    const OIIO::ImageBuf& image, const ColorTransform& basis, int scales, const std::string& name)
{
    PyramidOptions opt;
    opt.scales = scales;
    TextureStatistics stats;
    std::string error;
    EXPECT_TRUE(analyze_texture(image, opt, stats, error, &basis)) << error;
    for (size_t b = 0; b < stats.band_names.size(); ++b)
        if (stats.band_names[b] == name) {
            double sum = 0.0;
            for (float v : stats.components[0].bands[b].sorted())
                sum += double(v) * v;
            return sum / double(stats.components[0].bands[b].sorted().size());
        }
    ADD_FAILURE() << "no band " << name;
    return 0.0;
}

} // namespace

TEST(PyramidSynthesis, GainAndBalanceSlidersChangeTheBandsTheyName)
{
    const OIIO::ImageBuf sample = linear_sample("stucco_yellow.png");
    PyramidOptions opt = options(128, 128, 4);
    opt.scales = 3;
    TextureStatistics stats;
    std::string error;
    ASSERT_TRUE(analyze_texture(sample, opt, stats, error)) << error;
    const OIIO::ImageBuf plain = pyramid_synthesize(sample, opt);
    opt.gain = { 1.0f, 1.0f, 2.0f };
    const OIIO::ImageBuf gained = pyramid_synthesize(sample, opt);
    opt.gain.clear();
    opt.balance = { 0.0f, 0.8f };
    const OIIO::ImageBuf balanced = pyramid_synthesize(sample, opt);
    ASSERT_FALSE(plain.has_error() || gained.has_error() || balanced.has_error());

    // gain=1,1,2: scale 2 carries clearly more contrast, scale 0 about the same.
    double s2 = 0.0, s2_gained = 0.0;
    for (const char* band : { "s2.o0", "s2.o1", "s2.o2", "s2.o3" }) {
        s2 += band_energy(plain, stats.color, 3, band);
        s2_gained += band_energy(gained, stats.color, 3, band);
    }
    EXPECT_GT(s2_gained / s2, 2.0);
    const double s0_ratio = band_energy(gained, stats.color, 3, "s0.o1")
        / band_energy(plain, stats.color, 3, "s0.o1");
    EXPECT_NEAR(s0_ratio, 1.0, 0.35);

    // balance=0,0.8: at scale 1, orientation 0 gains on orientation 2 (x1.8 vs x0.2).
    const double plain_tilt
        = band_energy(plain, stats.color, 3, "s1.o0") / band_energy(plain, stats.color, 3, "s1.o2");
    const double balanced_tilt = band_energy(balanced, stats.color, 3, "s1.o0")
        / band_energy(balanced, stats.color, 3, "s1.o2");
    EXPECT_GT(balanced_tilt / plain_tilt, 4.0);
}

TEST(PyramidSynthesis, SlidersAreChecked)
{
    const OIIO::ImageBuf sample = linear_sample("stucco_yellow.png");
    PyramidOptions opt = options(64, 64, 1);
    opt.scales = 2;
    opt.gain = { 1.0f, 1.0f, 1.0f };
    OIIO::ImageBuf out = pyramid_synthesize(sample, opt);
    EXPECT_EQ(out.geterror(), "gain=1,1,1 : 3 values but the pyramid has 2 scales");
    opt.gain = { 1.0f, -0.5f }; // a range set in code is checked as text is
    out = pyramid_synthesize(sample, opt);
    EXPECT_EQ(out.geterror(), "gain=1,-0.5 : -0.5 is out of range 0..16");
    opt.gain = { 0.0f }; // 0 takes a scale's bands out
    out = pyramid_synthesize(sample, opt);
    EXPECT_FALSE(out.has_error()) << out.geterror();
    opt.gain.clear();
    opt.balance = { 0.5f };
    opt.pyramid = PyramidKind::Laplacian;
    out = pyramid_synthesize(sample, opt);
    EXPECT_EQ(out.geterror(),
        "balance=0.5 : needs pyramid=steerable (the laplacian pyramid has no orientations)");
}
