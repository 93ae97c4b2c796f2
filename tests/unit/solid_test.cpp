// SPDX-License-Identifier: Apache-2.0
// Solid textures (Heeger & Bergen 1995 §4): slices along every axis look like the sample.
#include <texsyn/histogram.h>
#include <texsyn/pyramid.h>
#include <texsyn/solid.h>
#include <texsyn/volume.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <OpenImageIO/hash.h>

#include <gtest/gtest.h>

#include "test_samples.h"

using namespace texsyn;

namespace {

using test::linear_sample;
using test::planes_of;

constexpr SliceAxis kAxes[3] = { SliceAxis::X, SliceAxis::Y, SliceAxis::Z };

SolidOptions options(int w, int h, int d, int iterations = 5)
{
    SolidOptions opt;
    opt.width = w;
    opt.height = h;
    opt.depth = d;
    opt.iterations = iterations;
    opt.seed = 11;
    return opt;
}

// solid_synthesize's 3-D image as planar volumes; false with the message otherwise.
bool solid_volume(
    PlanarVolume& v, const OIIO::ImageBuf& sample, const SolidOptions& opt, std::string& error)
{
    OIIO::ImageBuf out;
    if (!solid_synthesize(out, sample, opt)) {
        error = out.geterror();
        return false;
    }
    return volume_from_imagebuf(out, v, error);
}

PlanarVolume solid(const OIIO::ImageBuf& sample, const SolidOptions& opt)
{
    PlanarVolume v;
    std::string error;
    EXPECT_TRUE(solid_volume(v, sample, opt, error)) << error;
    return v;
}

uint64_t volume_hash(const PlanarVolume& v)
{
    uint64_t h = 0;
    for (const Volume& c : v.channels)
        h = OIIO::farmhash::Hash(reinterpret_cast<const char*>(c.data()), c.size() * sizeof(float))
            ^ (h * 31);
    return h;
}

// Mean over voxels of |v(i) - v(i + 1)| along `axis`, between slice `a` and slice `b`.
double slice_step(const Volume& v, SliceAxis axis, int a, int b)
{
    Plane pa, pb;
    extract_slice(v, axis, a, pa);
    extract_slice(v, axis, b, pb);
    double s = 0.0;
    for (size_t i = 0; i < pa.size(); ++i)
        s += std::abs(pa.data()[i] - pb.data()[i]);
    return s / double(pa.size());
}

// Variance of each band of the circular 2-D Laplacian pyramid (scales 1..) of every slice
// along `axis`, averaged over the slices.
std::vector<double> slice_band_variances(const Volume& v, SliceAxis axis, int scales)
{
    Plane slice;
    extract_slice(v, axis, 0, slice);
    std::string error;
    auto pyr
        = make_laplacian_pyramid(slice.width(), slice.height(), scales, Boundary::Circular, error);
    std::vector<double> var(size_t(scales), 0.0);
    std::vector<Plane> bands;
    const int n = slice_count(v, axis);
    for (int i = 0; i < n; ++i) {
        extract_slice(v, axis, i, slice);
        pyr->build(slice, bands);
        for (int s = 0; s < scales; ++s) {
            double sum = 0.0, sum2 = 0.0;
            for (size_t k = 0; k < bands[s].size(); ++k) {
                sum += bands[s].data()[k];
                sum2 += double(bands[s].data()[k]) * bands[s].data()[k];
            }
            const double m = double(bands[s].size());
            var[size_t(s)] += (sum2 / m - (sum / m) * (sum / m)) / n;
        }
    }
    return var;
}

// Mean W1 between the sample and its own n x n windows (at a stride of n/4): how far a
// slice-sized piece of the texture itself strays from the whole sample's histogram.
double window_w1(const Plane& sample, int n)
{
    const QuantileTable whole(sample);
    double sum = 0.0;
    int count = 0;
    for (int y0 = 0; y0 + n <= sample.height(); y0 += n / 4)
        for (int x0 = 0; x0 + n <= sample.width(); x0 += n / 4) {
            Plane window(n, n);
            for (int y = 0; y < n; ++y)
                std::copy_n(sample.row(y0 + y) + x0, n, window.row(y));
            sum += wasserstein1(QuantileTable(window), whole);
            ++count;
        }
    return sum / count;
}

} // namespace

TEST(SolidSynthesis, OutputHasTheRequestedSizeChannelsAndMetadata)
{
    const OIIO::ImageBuf sample = linear_sample("stucco_yellow.png");
    const PlanarVolume v = solid(sample, options(40, 24, 16, 1));
    ASSERT_EQ(v.nchannels(), 3);
    EXPECT_EQ(v.width(), 40);
    EXPECT_EQ(v.height(), 24);
    EXPECT_EQ(v.depth(), 16);
    EXPECT_EQ(v.channel_names, (std::vector<std::string> { "R", "G", "B" }));
    EXPECT_EQ(v.attributes.get_string("synth:method"), "solid");
    EXPECT_EQ(v.attributes.get_int("synth:seed"), 11);
    // 1 scale: the most that keeps a 16-voxel side's coarsest band at 8.
    EXPECT_EQ(v.attributes.get_string("synth:options"),
        "size=40x24x16:iterations=1:pyramid=combined:scales=1:orientations=4:histogram=exact:"
        "fft=kiss:flatten=0");
}

// The issue's quality bar on a real sample: every axis's slices have the sample's
// histograms and subband statistics, and the block tiles in x, y and z.
TEST(SolidSynthesis, SlicesAlongEveryAxisLookLikeTheSample)
{
    const OIIO::ImageBuf sample = linear_sample("marble_pink.png");
    const PlanarImage s = planes_of(sample);
    const int n = 64;
    const PlanarVolume v = solid(sample, options(n, n, n));
    ASSERT_EQ(v.nchannels(), 3);
    const int scales = 3; // what the block chose: 64 -> coarsest band 8
    ASSERT_NE(v.attributes.get_string("synth:options").find("scales=3"), std::string::npos);
    for (int c = 0; c < 3; ++c) {
        const Volume& ch = v.channels[size_t(c)];
        const QuantileTable target(s.channels[size_t(c)]);
        const double windows = window_w1(s.channels[size_t(c)], n);
        // The whole block (every axis's slices pooled) has the sample's histogram: the
        // last step of the synthesis matches it exactly, so only quantile interpolation
        // between the sample's 16K and the block's 262K values remains.
        EXPECT_LT(wasserstein1(QuantileTable(ch.voxels()), target), 0.001) << "channel " << c;
        std::printf("channel %d: sample's own %dx%d windows: mean W1 %.4f\n", c, n, n, windows);
        std::vector<double> variances[3];
        for (int a = 0; a < 3; ++a) {
            const SliceAxis axis = kAxes[a];
            // Single slices vary about the sample's histogram like the sample's own windows
            // of their size do (the coarsest scale's blobs are a good part of a slice): the
            // axes' mean within 2x of that, and the slices of all axes pooled (the block)
            // within the issue's W1 < 0.01.
            double mean_w1 = 0.0;
            Plane slice;
            for (int i = 0; i < n; ++i) {
                extract_slice(ch, axis, i, slice);
                mean_w1 += wasserstein1(QuantileTable(slice), target) / n;
            }
            EXPECT_LT(mean_w1, 2.0 * windows)
                << "channel " << c << " axis " << slice_axis_name(axis) << " sample windows "
                << windows;
            // Seamless: the step across the wrap is like the steps inside.
            double interior = 0.0;
            for (int i = 0; i + 1 < n; ++i)
                interior += slice_step(ch, axis, i, i + 1) / (n - 1);
            EXPECT_LE(slice_step(ch, axis, n - 1, 0), 1.2 * interior)
                << "channel " << c << " axis " << slice_axis_name(axis);
            variances[a] = slice_band_variances(ch, axis, scales);
            std::printf("channel %d axis %s: mean slice W1 %.4f, seam/interior %.3f, band "
                        "variances %.3g %.3g %.3g\n",
                c, slice_axis_name(axis), mean_w1, slice_step(ch, axis, n - 1, 0) / interior,
                variances[a][0], variances[a][1], variances[a][2]);
        }
        // The three axes' slices have the same subband statistics: band variances agree
        // within 25% (the block is isotropic; 64 slices of 64^2 voxels leave a few per
        // cent of sampling noise, and the averaged solids are not exactly isotropic).
        for (int sc = 0; sc < scales; ++sc) {
            const double lo = std::min(
                { variances[0][size_t(sc)], variances[1][size_t(sc)], variances[2][size_t(sc)] });
            const double hi = std::max(
                { variances[0][size_t(sc)], variances[1][size_t(sc)], variances[2][size_t(sc)] });
            EXPECT_LT(hi / lo, 1.25) << "channel " << c << " band L" << sc;
        }
    }
}

TEST(SolidSynthesis, BitIdenticalForASeedAtAnyThreadCount)
{
    const OIIO::ImageBuf sample = linear_sample("marble_pink.png");
    SolidOptions opt = options(40, 24, 16, 2);
    opt.nthreads = 1;
    const uint64_t a = volume_hash(solid(sample, opt));
    opt.nthreads = 2;
    const uint64_t b = volume_hash(solid(sample, opt));
    opt.nthreads = 3;
    const uint64_t c = volume_hash(solid(sample, opt));
    EXPECT_EQ(a, b);
    EXPECT_EQ(a, c);
    opt.seed = 12;
    EXPECT_NE(a, volume_hash(solid(sample, opt)));
}

TEST(SolidSynthesis, LaplacianModeAndNonCubicSizes)
{
    const OIIO::ImageBuf sample = linear_sample("stucco_yellow.png");
    const PlanarImage s = planes_of(sample);
    SolidOptions opt = options(64, 48, 24, 3);
    opt.pyramid = SolidPyramid::Laplacian;
    const PlanarVolume v = solid(sample, opt);
    ASSERT_EQ(v.nchannels(), 3);
    EXPECT_EQ(v.depth(), 24);
    EXPECT_NE(
        v.attributes.get_string("synth:options").find("pyramid=laplacian"), std::string::npos);
    for (int c = 0; c < 3; ++c) // the final match: quantile interpolation only
        EXPECT_LT(wasserstein1(QuantileTable(v.channels[size_t(c)].voxels()),
                      QuantileTable(s.channels[size_t(c)])),
            0.001);
    opt.pyramid = SolidPyramid::Combined;
    const PlanarVolume combined = solid(sample, opt);
    EXPECT_EQ(combined.width(), 64);
    EXPECT_NE(volume_hash(v), volume_hash(combined));
}

TEST(SolidSynthesis, AlphaIsSynthesizedAsItsOwnChannel)
{
    Plane alpha;
    const OIIO::ImageBuf sample = test::stucco_with_alpha(alpha);
    const PlanarVolume v = solid(sample, options(32, 32, 32, 2));
    ASSERT_EQ(v.nchannels(), 4);
    EXPECT_EQ(v.alpha_channel, 3);
    EXPECT_LT(wasserstein1(QuantileTable(v.channels[3].voxels()), QuantileTable(alpha)), 0.001);
}

TEST(SolidSynthesis, BadRequestsAreRefusedWithAMessage)
{
    const OIIO::ImageBuf sample = linear_sample("stucco_yellow.png");
    PlanarVolume v;
    std::string error;
    SolidOptions opt = options(64, 64, 8, 1);
    opt.scales = 4;
    EXPECT_FALSE(solid_volume(v, sample, opt, error));
    EXPECT_EQ(error, "size=64x64x8 is too small for 4 scales (each side at least 16)");
    opt.scales = 5;
    EXPECT_FALSE(solid_volume(v, sample, opt, error));
    EXPECT_EQ(error, "scales=5 is too many for a 128x128 sample (at most 4)");
    opt = options(16384, 16384, 16384);
    EXPECT_FALSE(solid_volume(v, sample, opt, error));
    EXPECT_EQ(error.find("size=16384x16384x16384 would need about "), 0u) << error;
    opt = options(1, 64, 64);
    EXPECT_FALSE(solid_volume(v, sample, opt, error));
    EXPECT_EQ(error, "size=1x64x64 is too small for 1 scales (each side at least 2)");
    opt = options(32, 32, 32);
    opt.orientations = 9;
    EXPECT_FALSE(solid_volume(v, sample, opt, error));
    EXPECT_EQ(error, "orientations=9 : out of range 1..8");
    OIIO::ImageBuf tiny(OIIO::ImageSpec(8, 8, 3, OIIO::TypeFloat));
    EXPECT_FALSE(solid_volume(v, tiny, options(32, 32, 32), error));
    EXPECT_EQ(error, "sample is 8x8: the pyramid method needs at least 16x16");
    EXPECT_EQ(v.nchannels(), 0); // untouched on failure
}

TEST(SolidOptions, TableParsesAndFormats)
{
    SolidOptions opt;
    std::string error;
    EXPECT_TRUE(SolidOptions::table().set(opt, "size", "256x256x64", error)) << error;
    EXPECT_EQ(opt.depth, 64);
    EXPECT_FALSE(SolidOptions::table().set(opt, "size", "64x64", error));
    EXPECT_EQ(error, "size=64x64 : not a size (expected WxHxD, e.g. 128x128x128)");
    EXPECT_FALSE(SolidOptions::table().set(opt, "size", "0x1x1", error));
    EXPECT_EQ(error, "size=0x1x1 : out of range 1..16384 (each side)");
    EXPECT_FALSE(SolidOptions::table().set(opt, "pyramid", "steerable", error));
    EXPECT_EQ(error, "pyramid=steerable : not one of combined|laplacian");
    EXPECT_EQ(SolidOptions::table().format(SolidOptions()),
        "size=0x0x0:iterations=5:pyramid=combined:scales=0:orientations=4:histogram=exact:"
        "fft=kiss:flatten=0");
}
