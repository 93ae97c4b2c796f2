// SPDX-License-Identifier: Apache-2.0
// Wei & Levoy neighbourhood synthesis: copies, determinism, source maps, errors.
#include <texsyn/neighborhood.h>

#include <OpenImageIO/hash.h>
#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "test_samples.h"

using namespace texsyn;

namespace {

using test::linear_sample;
using test::planes_of;

// The top-left w x h of a bundled sample.
OIIO::ImageBuf crop(const std::string& name, int w, int h)
{
    return OIIO::ImageBufAlgo::cut(linear_sample(name), OIIO::ROI(0, w, 0, h));
}

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

std::string pixel_hash(const OIIO::ImageBuf& buf)
{
    std::vector<float> px(size_t(buf.spec().image_pixels()) * size_t(buf.nchannels()));
    buf.get_pixels(buf.roi(), OIIO::TypeFloat, px.data());
    return OIIO::Strutil::fmt::format("{:016x}",
        OIIO::Strutil::strhash(
            std::string_view(reinterpret_cast<const char*>(px.data()), px.size() * sizeof(float))));
}

} // namespace

TEST(Neighborhood, EveryPixelIsASamplePixelAndTheMapSaysWhich)
{
    const OIIO::ImageBuf sample = crop("rust.png", 40, 40);
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
    const OIIO::ImageBuf sample = crop("stucco_yellow.png", 64, 64);
    NeighborhoodOptions opt = options(80, 80, 2, { 7, 5 });
    opt.nthreads = 1;
    const std::string one = pixel_hash(neighborhood_synthesize(sample, opt));
    opt.nthreads = 3;
    EXPECT_EQ(pixel_hash(neighborhood_synthesize(sample, opt)), one);
    opt.seed = 6;
    EXPECT_NE(pixel_hash(neighborhood_synthesize(sample, opt)), one);
}

TEST(Neighborhood, RefusesBadSizes)
{
    const OIIO::ImageBuf sample = crop("rust.png", 40, 40);
    auto error_of = [&](const NeighborhoodOptions& opt) {
        OIIO::ImageBuf dst;
        EXPECT_FALSE(neighborhood_synthesize(dst, sample, opt));
        return dst.geterror();
    };
    EXPECT_NE(error_of(options(64, 64, 1, { 8 })).find("not an odd width"), std::string::npos);
    EXPECT_NE(
        error_of(options(64, 64, 1, { 41 })).find("smaller than the n=41"), std::string::npos);
    EXPECT_NE(error_of(options(64, 64, 4, { 9 })).find("use levels=3 or less"), std::string::npos);
    EXPECT_NE(error_of(options(8, 8, 1, { 9 })).find("size=8x8 is too small"), std::string::npos);
}

TEST(Neighborhood, SourceMapChecksItsInput)
{
    const OIIO::ImageBuf sample = crop("rust.png", 40, 40);
    OIIO::ImageBuf map;
    ASSERT_FALSE(neighborhood_synthesize(sample, options(40, 40, 1, { 5 }), &map).has_error());
    OIIO::ImageBuf dst;
    EXPECT_FALSE(apply_source_map(dst, map, crop("rust.png", 30, 40)));
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
