// SPDX-License-Identifier: Apache-2.0
// Wei & Levoy neighbourhood synthesis: copies, determinism, source maps, errors.
#include <texsyn/histogram.h>
#include <texsyn/neighborhood.h>

#include <algorithm>
#include <cmath>

#include <OpenImageIO/hash.h>
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "test_metrics.h"
#include "test_samples.h"

using namespace texsyn;

namespace {

using test::linear_crop;
using test::linear_sample;
using test::pixel_hash;
using test::planes_of;
using test::seam_ratio;
using test::worst_w1;

NeighborhoodOptions options(
    int w, int h, int levels, std::vector<int> n, SearchMethod search = SearchMethod::Exhaustive)
{
    NeighborhoodOptions opt;
    opt.width = w;
    opt.height = h;
    opt.levels = levels;
    opt.n = std::move(n);
    opt.search = search;
    opt.seed = 5;
    return opt;
}

} // namespace

TEST(Neighborhood, EveryPixelIsASamplePixelAndTheMapSaysWhich)
{
    const OIIO::ImageBuf sample = linear_crop("rust.png", 40, 40);
    OIIO::ImageBuf map;
    const OIIO::ImageBuf out = neighborhood_synthesize(sample, options(48, 40, 1, { 7 }), &map);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    ASSERT_EQ(out.spec().width, 48);
    ASSERT_EQ(map.nchannels(), 2);
    EXPECT_EQ(map.spec().get_string_attribute("synth:sample_size"), "40x40");
    const PlanarImage o = planes_of(out), s = planes_of(sample);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 48; ++x) {
            float xy[2];
            map.getpixel(x, y, xy, 2);
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(
                    o.channels[size_t(c)](x, y), s.channels[size_t(c)](int(xy[0]), int(xy[1])));
        }
    // apply_source_map re-applies it.
    const OIIO::ImageBuf again = apply_source_map(map, sample);
    ASSERT_FALSE(again.has_error()) << again.geterror();
    EXPECT_EQ(pixel_hash(again), pixel_hash(out));
}

TEST(Neighborhood, ResultIgnoresThreadCount)
{
    const OIIO::ImageBuf sample = linear_crop("stucco_yellow.png", 64, 64);
    NeighborhoodOptions opt = options(80, 80, 2, { 7, 5 });
    opt.nthreads = 1;
    const std::string one = pixel_hash(neighborhood_synthesize(sample, opt));
    opt.nthreads = 3;
    EXPECT_EQ(pixel_hash(neighborhood_synthesize(sample, opt)), one);
    opt.seed = 6;
    EXPECT_NE(pixel_hash(neighborhood_synthesize(sample, opt)), one);
}

// Rows run as a wavefront on the workers: the result must be the one-thread result for
// every back-end.
TEST(Neighborhood, EveryBackEndIgnoresThreadCount)
{
    const OIIO::ImageBuf sample = linear_crop("grass.png", 96, 96);
    for (SearchMethod search :
        { SearchMethod::Tsvq, SearchMethod::KdTree, SearchMethod::Coherent }) {
        NeighborhoodOptions opt = options(128, 96, 3, { 9, 7, 5 }, search);
        opt.nthreads = 1;
        const std::string one = pixel_hash(neighborhood_synthesize(sample, opt));
        for (int threads : { 2, 4 }) {
            opt.nthreads = threads;
            EXPECT_EQ(pixel_hash(neighborhood_synthesize(sample, opt)), one)
                << search_method_name(search) << " at " << threads << " threads";
        }
    }
}

TEST(Neighborhood, RefusesBadSizes)
{
    const OIIO::ImageBuf sample = linear_crop("rust.png", 40, 40);
    auto error_of = [&](const NeighborhoodOptions& opt) {
        OIIO::ImageBuf dst;
        EXPECT_FALSE(neighborhood_synthesize(dst, sample, opt));
        return dst.geterror();
    };
    EXPECT_NE(error_of(options(64, 64, 1, { 8 })).find("n=8 : not odd"), std::string::npos);
    EXPECT_NE(
        error_of(options(64, 64, 1, { 41 })).find("smaller than the n=41"), std::string::npos);
    EXPECT_NE(error_of(options(64, 64, 4, { 9 })).find("use levels=3 or less"), std::string::npos);
    EXPECT_NE(error_of(options(8, 8, 1, { 9 })).find("size=8x8 is too small"), std::string::npos);
}

TEST(Neighborhood, SourceMapChecksItsInput)
{
    const OIIO::ImageBuf sample = linear_crop("rust.png", 40, 40);
    OIIO::ImageBuf map;
    ASSERT_FALSE(neighborhood_synthesize(sample, options(40, 40, 1, { 5 }), &map).has_error());
    OIIO::ImageBuf dst;
    EXPECT_FALSE(apply_source_map(dst, map, linear_crop("rust.png", 30, 40)));
    EXPECT_NE(dst.geterror().find("made from a 40x40 sample"), std::string::npos) << dst.geterror();
    OIIO::ImageBuf bad;
    bad.copy(map);
    const float off[2] = { 40.0f, 3.0f };
    bad.setpixel(2, 1, off, 2);
    OIIO::ImageBuf dst2;
    EXPECT_FALSE(apply_source_map(dst2, bad, sample));
    EXPECT_NE(dst2.geterror().find("pixel (2, 1) holds (40, 3)"), std::string::npos)
        << dst2.geterror();
}

// The issue's quality bar: per-channel W1 < 0.02 against the sample, and a seamless tile,
// for stochastic (stucco, marble, rust) and structured or oriented (bricks, grass) samples,
// with the default method settings.
TEST(NeighborhoodQuality, HistogramsMatchAndTheOutputTiles)
{
    for (const char* name :
        { "stucco_yellow.png", "marble_pink.png", "rust.png", "grass.png", "bricks.png" }) {
        const OIIO::ImageBuf sample = linear_crop(name, 128, 128);
        NeighborhoodOptions opt;
        opt.width = opt.height = 192;
        opt.seed = 3;
        const OIIO::ImageBuf out = neighborhood_synthesize(sample, opt);
        ASSERT_FALSE(out.has_error()) << out.geterror();
        EXPECT_LT(worst_w1(out, sample), 0.02) << name;
        // Interior neighbours differ as much as neighbours across the seam: 1.3 allows for
        // the variation between images of this size (measured 0.9..1.15 on these samples).
        EXPECT_LT(seam_ratio(out), 1.3) << name;
    }
}

// Wei & Levoy's single pass matches its first rows and columns against noise, which leaves a
// seam on a structured sample; the seam band pass (tile=1, the default) removes it.
TEST(NeighborhoodQuality, TheSeamPassMakesAStructuredSampleTile)
{
    const OIIO::ImageBuf sample = linear_crop("bricks.png", 128, 128);
    NeighborhoodOptions opt = options(128, 128, 3, { 7 });
    opt.tile = 0;
    const double single_pass = seam_ratio(neighborhood_synthesize(sample, opt));
    opt.tile = 1;
    const double repaired = seam_ratio(neighborhood_synthesize(sample, opt));
    EXPECT_GT(single_pass, 1.4); // measured 1.56 (columns 3.0x the interior, rows 0.97x)
    EXPECT_LT(repaired, 1.3);    // measured 0.67
}

// The report's Figure 3: with the unsynthesized noise in the neighbourhood (shape=square)
// the result is measurably worse than with the causal L. Measured on 64x64 crops, W1 rises
// from 0.010 to 0.015 (stucco) and from 0.007 to 0.022 (grass).
TEST(NeighborhoodQuality, TheCausalShapeBeatsTheSquareWithNoise)
{
    for (const char* name : { "stucco_yellow.png", "grass.png" }) {
        const OIIO::ImageBuf sample = linear_crop(name, 64, 64);
        NeighborhoodOptions opt = options(96, 96, 1, { 7 });
        const double causal = worst_w1(neighborhood_synthesize(sample, opt), sample);
        opt.shape = NeighborhoodShape::Square;
        const double square = worst_w1(neighborhood_synthesize(sample, opt), sample);
        EXPECT_GT(square, 1.4 * causal) << name << ": causal " << causal << ", square " << square;
    }
}

// Alpha and extra channels are copied with the colour, from the same sample pixel.
TEST(Neighborhood, AlphaIsCopiedWithTheColour)
{
    Plane alpha;
    const OIIO::ImageBuf sample = OIIO::ImageBufAlgo::cut(
        test::stucco_with_alpha(alpha), OIIO::ROI(0, 48, 0, 48, 0, 1, 0, 4));
    OIIO::ImageBuf map;
    const OIIO::ImageBuf out = neighborhood_synthesize(sample, options(56, 56, 2, { 7, 5 }), &map);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    ASSERT_EQ(out.nchannels(), 4);
    EXPECT_EQ(out.spec().alpha_channel, 3);
    const PlanarImage o = planes_of(out), s = planes_of(sample);
    for (int y = 0; y < 56; ++y)
        for (int x = 0; x < 56; ++x) {
            float xy[2];
            map.getpixel(x, y, xy, 2);
            const int sx = int(xy[0]), sy = int(xy[1]);
            ASSERT_EQ(o.channels[3](x, y), s.channels[3](sx, sy));
            for (int c = 0; c < 3; ++c) // un-associated again after re-association
                ASSERT_NEAR(o.channels[size_t(c)](x, y), s.channels[size_t(c)](sx, sy), 1e-6f);
        }
}

// Every channel is part of the neighbourhood: a sample whose colour is flat and whose only
// structure is in alpha (vertical stripes, period 8) gives striped alpha, not noise.
TEST(Neighborhood, AlphaIsPartOfTheNeighbourhood)
{
    PlanarImage s;
    for (int c = 0; c < 4; ++c)
        s.channels.emplace_back(48, 48, 0.5f);
    s.channel_names = { "R", "G", "B", "A" };
    s.alpha_channel = 3;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            s.channels[3](x, y) = (x / 4) % 2 ? 1.0f : 0.25f;
    OIIO::ImageBuf sample;
    imagebuf_from_planes(s, sample);
    const PlanarImage o = planes_of(neighborhood_synthesize(sample, options(64, 64, 1, { 9 })));
    size_t same_below = 0, changes_across = 0;
    for (int y = 0; y < 63; ++y)
        for (int x = 0; x < 63; ++x) {
            same_below += o.channels[3](x, y) == o.channels[3](x, y + 1);
            changes_across += o.channels[3](x, y) != o.channels[3](x + 1, y);
        }
    EXPECT_GT(double(same_below) / (63.0 * 63.0), 0.9);
    // The sample's stripes change every 4 pixels: a quarter of horizontal neighbours differ.
    EXPECT_NEAR(double(changes_across) / (63.0 * 63.0), 0.25, 0.05);
}
