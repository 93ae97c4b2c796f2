// SPDX-License-Identifier: Apache-2.0
// texture_fill(): pixels outside the mask are kept bit for bit; the hole gets texture like
// its surroundings (histogram and band energies) with no edge at the mask's boundary, far
// closer than push-pull interpolation (the baseline every compositor has); soft masks
// blend; exclude= keeps regions out of the sources; the cost follows the holes; same seed,
// same pixels at any thread count; bad masks are refused.
#include <texsyn/fft.h>
#include <texsyn/fill.h>
#include <texsyn/homogeneity.h>
#include <texsyn/source_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstring>
#include <iostream>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "structure_metric.h"
#include "test_metrics.h"
#include "test_samples.h"

using namespace texsyn;
using namespace texsyn::test;

namespace {

// A one-channel w x h mask: `inside` within the ellipse of radii (rx, ry) around (cx, cy).
OIIO::ImageBuf ellipse_mask(
    int w, int h, float cx, float cy, float rx, float ry, float inside = 1.0f)
{
    OIIO::ImageBuf mask(OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::FLOAT));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float u = (x - cx) / rx, v = (y - cy) / ry;
            const float m = u * u + v * v <= 1.0f ? inside : 0.0f;
            mask.setpixel(x, y, &m);
        }
    return mask;
}

// Pixel values of channel c where `where(x, y)` holds.
template <class Where>
std::vector<float> values(const OIIO::ImageBuf& image, int c, Where where)
{
    std::vector<float> v;
    for (int y = 0; y < image.spec().height; ++y)
        for (int x = 0; x < image.spec().width; ++x)
            if (where(x, y))
                v.push_back(image.getchannel(x, y, 0, c));
    return v;
}

// The 1-Wasserstein distance between two sets of values (their quantile functions).
double w1(std::vector<float> a, std::vector<float> b)
{
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    const int n = 256;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double q = (i + 0.5) / n;
        sum += std::abs(a[size_t(q * double(a.size()))] - b[size_t(q * double(b.size()))]);
    }
    return sum / n;
}

// The mean squared difference of luminance between horizontally and vertically adjacent
// pixels (both in `a`), of the image reduced `scale` times by 2 (box): a band energy.
template <class Where>
double band_energy(const OIIO::ImageBuf& image, int scale, Where where)
{
    const int f = 1 << scale, w = image.spec().width / f, h = image.spec().height / f;
    auto lum = [&](int x, int y) {
        double s = 0.0;
        for (int j = 0; j < f; ++j)
            for (int i = 0; i < f; ++i)
                for (int c = 0; c < 3; ++c)
                    s += image.getchannel(x * f + i, y * f + j, 0, c) / 3.0;
        return s / (f * f);
    };
    double sum = 0.0;
    size_t n = 0;
    for (int y = 0; y + 1 < h; ++y)
        for (int x = 0; x + 1 < w; ++x) {
            if (!where(x * f + f / 2, y * f + f / 2))
                continue;
            const double l = lum(x, y), dx = lum(x + 1, y) - l, dy = lum(x, y + 1) - l;
            sum += dx * dx + dy * dy;
            ++n;
        }
    return sum / double(std::max<size_t>(n, 1));
}

// The mask's ellipse and the ring around it (to 1.6 times its radii).
struct Ellipse {
    float cx, cy, rx, ry;
    float r(int x, int y) const
    {
        const float u = (x - cx) / rx, v = (y - cy) / ry;
        return std::sqrt(u * u + v * v);
    }
    bool hole(int x, int y) const { return r(x, y) <= 1.0f; }
    bool ring(int x, int y) const { return r(x, y) > 1.15f && r(x, y) <= 1.6f; }
};

// How a filled image compares with its surroundings: the worst channel's W1 between hole and
// ring, the hole's band energies over the ring's (scales 0, 1, 2; 1 = the same), and the
// boundary step: the mean squared step across the mask's edge over that between adjacent
// ring pixels.
struct FillQuality {
    double w1 = 0.0;
    double energy[3] = { 0, 0, 0 };
    double seam = 0.0;
};

FillQuality quality(const OIIO::ImageBuf& filled, const Ellipse& e)
{
    FillQuality q;
    for (int c = 0; c < 3; ++c)
        q.w1 = std::max(q.w1,
            w1(values(filled, c, [&](int x, int y) { return e.hole(x, y); }),
                values(filled, c, [&](int x, int y) { return e.ring(x, y); })));
    for (int s = 0; s < 3; ++s)
        q.energy[s] = band_energy(filled, s, [&](int x, int y) { return e.r(x, y) <= 0.9f; })
            / band_energy(filled, s, [&](int x, int y) { return e.ring(x, y); });
    double across = 0.0, inside = 0.0;
    size_t na = 0, ni = 0;
    const int w = filled.spec().width, h = filled.spec().height;
    for (int y = 0; y + 1 < h; ++y)
        for (int x = 0; x + 1 < w; ++x)
            for (int d = 0; d < 2; ++d) {
                const int x2 = x + (d == 0), y2 = y + (d == 1);
                double step = 0.0;
                for (int c = 0; c < 3; ++c) {
                    const double v
                        = filled.getchannel(x, y, 0, c) - filled.getchannel(x2, y2, 0, c);
                    step += v * v;
                }
                if (e.hole(x, y) != e.hole(x2, y2)) {
                    across += step;
                    ++na;
                } else if (e.ring(x, y) && e.ring(x2, y2)) {
                    inside += step;
                    ++ni;
                }
            }
    q.seam = (across / double(na)) / (inside / double(ni));
    return q;
}

std::ostream& operator<<(std::ostream& o, const FillQuality& q)
{
    return o << "W1 " << q.w1 << ", band energy ratios " << q.energy[0] << " " << q.energy[1] << " "
             << q.energy[2] << ", seam ratio " << q.seam;
}

// The baseline: OIIO's push-pull hole filling (colour premultiplied by 1 - mask, which is
// the alpha).
OIIO::ImageBuf pushpull(const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask)
{
    const int w = image.spec().width, h = image.spec().height;
    OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::FLOAT);
    spec.alpha_channel = 3;
    OIIO::ImageBuf rgba(spec);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float keep = 1.0f - mask.getchannel(x, y, 0, 0);
            float p[4] = { 0, 0, 0, keep };
            for (int c = 0; c < 3; ++c)
                p[c] = keep * image.getchannel(x, y, 0, c);
            rgba.setpixel(x, y, p);
        }
    OIIO::ImageBuf filled = OIIO::ImageBufAlgo::fillholes_pushpull(rgba);
    return OIIO::ImageBufAlgo::channels(filled, 3, {});
}

FillOptions seeded(uint64_t seed, int nthreads = 0)
{
    FillOptions opt;
    opt.seed = seed;
    opt.nthreads = nthreads;
    return opt;
}

// Whether a and b hold the same bits everywhere `keep(x, y)` holds.
template <class Keep>
bool identical_where(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, Keep keep)
{
    const int nc = a.nchannels();
    std::vector<float> pa(static_cast<size_t>(nc)), pb(static_cast<size_t>(nc));
    for (int y = 0; y < a.spec().height; ++y)
        for (int x = 0; x < a.spec().width; ++x)
            if (keep(x, y)) {
                a.getpixel(x, y, pa.data());
                b.getpixel(x, y, pb.data());
                if (std::memcmp(pa.data(), pb.data(), pa.size() * sizeof(float)) != 0)
                    return false;
            }
    return true;
}

} // namespace

// Bricks with an elliptical hole across three courses: the fill matches its surroundings'
// histogram and band energies and leaves no step at the mask's edge; push-pull is smooth.
TEST(Fill, BricksHoleLooksLikeItsSurroundings)
{
    const OIIO::ImageBuf bricks = linear_sample("bricks.png");
    const Ellipse e { 128.0f, 120.0f, 40.0f, 30.0f };
    const OIIO::ImageBuf mask = ellipse_mask(256, 256, e.cx, e.cy, e.rx, e.ry);
    FillReport report;
    const OIIO::ImageBuf filled = texture_fill(bricks, mask, seeded(3), nullptr, nullptr, &report);
    ASSERT_FALSE(filled.has_error()) << filled.geterror();
    EXPECT_EQ(report.holes, 1);
    const OIIO::ImageBuf smooth = pushpull(bricks, mask);
    const FillQuality ours = quality(filled, e), baseline = quality(smooth, e),
                      original = quality(bricks, e);
    std::cout << "fill: " << ours << "\npush-pull: " << baseline << "\noriginal: " << original
              << "\n";
    for (const auto& [name, q] :
        { std::pair { "fill", ours }, { "pushpull", baseline }, { "original", original } }) {
        test::doc_number(std::string("fill.bricks.") + name + ".w1", q.w1, 3);
        for (int s = 0; s < 3; ++s)
            test::doc_number(
                std::string("fill.bricks.") + name + ".energy" + std::to_string(s), q.energy[s], 2);
        test::doc_number(std::string("fill.bricks.") + name + ".seam", q.seam, 2);
    }
    // Measured (seed 3): W1 0.021 against push-pull's 0.032; band energies 0.97, 0.95, 0.77
    // of the ring's (push-pull 0.03, 0.05, 0.15); seam 2.05, the original's 1.65.
    EXPECT_LT(ours.w1, 0.025);
    EXPECT_LT(ours.w1, 0.7 * baseline.w1);
    for (int s = 0; s < 3; ++s) {
        EXPECT_GT(ours.energy[s], 0.55) << "scale " << s;
        EXPECT_LT(ours.energy[s], 1.5) << "scale " << s;
        EXPECT_LT(baseline.energy[s], 0.2) << "scale " << s;
    }
    EXPECT_LT(ours.seam, 1.5 * original.seam);
}

// Outside the mask every channel (alpha and an extra channel too) keeps its bits, whatever
// the outline; inside, with outline=copy, each pixel is one of the image's pixels.
TEST(Fill, UnmaskedPixelsAreBitIdentical)
{
    Plane alpha;
    const OIIO::ImageBuf stucco = stucco_with_alpha(alpha);
    const OIIO::ImageBuf mask = ellipse_mask(128, 128, 60.0f, 70.0f, 18.0f, 12.0f);
    FillOptions opt = seeded(1);
    for (FillOutline outline : { FillOutline::Match, FillOutline::Copy }) {
        opt.outline = outline;
        const OIIO::ImageBuf f = texture_fill(stucco, mask, opt);
        ASSERT_FALSE(f.has_error()) << f.geterror();
        EXPECT_TRUE(identical_where(
            f, stucco, [&](int x, int y) { return mask.getchannel(x, y, 0, 0) == 0.0f; }));
    }
    const OIIO::ImageBuf filled = texture_fill(stucco, mask, opt);
    EXPECT_EQ(filled.nchannels(), 4);
    EXPECT_FALSE(identical_where(
        filled, stucco, [&](int x, int y) { return mask.getchannel(x, y, 0, 0) > 0.0f; }));
    // A filled pixel is a copy of a pixel outside the mask.
    std::vector<std::array<float, 4>> known;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x)
            if (mask.getchannel(x, y, 0, 0) == 0.0f) {
                std::array<float, 4> p;
                stucco.getpixel(x, y, p.data());
                known.push_back(p);
            }
    std::sort(known.begin(), known.end());
    for (int y = 58; y < 82; y += 3)
        for (int x = 44; x < 76; x += 3) {
            std::array<float, 4> p;
            filled.getpixel(x, y, p.data());
            EXPECT_TRUE(std::binary_search(known.begin(), known.end(), p)) << x << "," << y;
        }
}

TEST(Fill, AnEmptyMaskChangesNothing)
{
    const OIIO::ImageBuf grass = linear_crop("grass.png", 96, 80);
    const OIIO::ImageBuf filled
        = texture_fill(grass, ellipse_mask(96, 80, 0, 0, 0.1f, 0.1f, 0.0f), seeded(1));
    ASSERT_FALSE(filled.has_error()) << filled.geterror();
    EXPECT_TRUE(identical_where(filled, grass, [](int, int) { return true; }));
}

// A soft mask blends: m x the hard mask's fill + (1 - m) x the image.
TEST(Fill, SoftMasksBlend)
{
    const OIIO::ImageBuf stucco = linear_sample("stucco_yellow.png");
    const OIIO::ImageBuf hard = ellipse_mask(128, 128, 64.0f, 64.0f, 16.0f, 16.0f, 1.0f);
    const OIIO::ImageBuf soft = ellipse_mask(128, 128, 64.0f, 64.0f, 16.0f, 16.0f, 0.25f);
    const OIIO::ImageBuf a = texture_fill(stucco, hard, seeded(5));
    const OIIO::ImageBuf b = texture_fill(stucco, soft, seeded(5));
    ASSERT_FALSE(a.has_error() || b.has_error()) << a.geterror() << b.geterror();
    const OIIO::ImageBuf expected = OIIO::ImageBufAlgo::add(
        OIIO::ImageBufAlgo::mul(a, 0.25f), OIIO::ImageBufAlgo::mul(stucco, 0.75f));
    const auto diff = OIIO::ImageBufAlgo::compare(b, expected, 1e-6f, 1e-6f);
    EXPECT_EQ(diff.nfail, 0u) << diff.maxerror;
}

// exclude= keeps a red square (another marker) out of the patches the fill copies.
TEST(Fill, ExcludedRegionsAreNeverCopied)
{
    OIIO::ImageBuf stucco = linear_sample("stucco_yellow.png");
    const float red[3] = { 1.0f, 0.0f, 0.0f };
    OIIO::ImageBufAlgo::fill(stucco, red, OIIO::ROI(80, 100, 20, 40));
    OIIO::ImageBuf exclude(OIIO::ImageSpec(128, 128, 1, OIIO::TypeDesc::FLOAT));
    const float one = 1.0f;
    OIIO::ImageBufAlgo::fill(exclude, &one, OIIO::ROI(80, 100, 20, 40));
    const OIIO::ImageBuf mask = ellipse_mask(128, 128, 64.0f, 80.0f, 30.0f, 24.0f);
    auto reds = [&](const OIIO::ImageBuf& img) {
        return values(img, 1, [&](int x, int y) {
            return mask.getchannel(x, y, 0, 0) > 0.0f && img.getchannel(x, y, 0, 1) == 0.0f;
        }).size();
    };
    const OIIO::ImageBuf excluded = texture_fill(stucco, mask, seeded(2), nullptr, &exclude);
    ASSERT_FALSE(excluded.has_error()) << excluded.geterror();
    EXPECT_EQ(reds(excluded), 0u);
}

// Another sample fills a mask that covers the whole image; without one, that is an error.
TEST(Fill, AFullMaskNeedsASample)
{
    const OIIO::ImageBuf grass = linear_crop("grass.png", 64, 64);
    const OIIO::ImageBuf full = ellipse_mask(64, 64, 32, 32, 1000.0f, 1000.0f);
    OIIO::ImageBuf dst;
    EXPECT_FALSE(texture_fill(dst, grass, full, seeded(1)));
    EXPECT_NE(dst.geterror().find("covers the whole image"), std::string::npos) << dst.geterror();
    const OIIO::ImageBuf stucco = linear_sample("stucco_yellow.png");
    const OIIO::ImageBuf filled = texture_fill(grass, full, seeded(1), &stucco);
    ASSERT_FALSE(filled.has_error()) << filled.geterror();
    // Every pixel now comes from the stucco: its colours, not the grass's.
    auto all = [](int, int) { return true; };
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(w1(values(filled, c, all), values(stucco, c, all)),
            0.5 * w1(values(grass, c, all), values(stucco, c, all)))
            << c;
}

// The work is the holes' crops: the same hole in a 4x larger image costs the same pixels,
// and two far-apart holes are two regions.
TEST(Fill, CostFollowsTheHolesNotTheImage)
{
    const OIIO::ImageBuf stucco = linear_sample("stucco_yellow.png");
    auto tiled = [&](int n) {
        OIIO::ImageBuf big(OIIO::ImageSpec(128 * n, 128 * n, 3, OIIO::TypeDesc::FLOAT));
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                OIIO::ImageBufAlgo::paste(big, 128 * i, 128 * j, 0, 0, stucco);
        return big;
    };
    FillReport small, large;
    ASSERT_FALSE(texture_fill(
        tiled(4), ellipse_mask(512, 512, 256, 256, 12, 12), seeded(1), nullptr, nullptr, &small)
                     .has_error());
    ASSERT_FALSE(texture_fill(
        tiled(8), ellipse_mask(1024, 1024, 256, 256, 12, 12), seeded(1), nullptr, nullptr, &large)
                     .has_error());
    EXPECT_EQ(small.work_pixels, large.work_pixels);
    EXPECT_LT(large.work_pixels, size_t(1024 * 1024 / 8));

    OIIO::ImageBuf two = ellipse_mask(512, 512, 100, 100, 10, 10);
    OIIO::ImageBufAlgo::add(two, two, ellipse_mask(512, 512, 400, 420, 10, 10));
    FillReport both;
    ASSERT_FALSE(texture_fill(tiled(4), two, seeded(1), nullptr, nullptr, &both).has_error());
    EXPECT_EQ(both.holes, 2);
}

TEST(Fill, ResultIgnoresThreadCount)
{
    const OIIO::ImageBuf bricks = linear_crop("bricks.png", 160, 160);
    const OIIO::ImageBuf mask = ellipse_mask(160, 160, 70, 90, 20, 26);
    const OIIO::ImageBuf one = texture_fill(bricks, mask, seeded(9, 1));
    const OIIO::ImageBuf two = texture_fill(bricks, mask, seeded(9, 2));
    ASSERT_FALSE(one.has_error() || two.has_error());
    EXPECT_TRUE(identical_where(one, two, [](int, int) { return true; }));
}

TEST(Fill, BadMasksAreRefused)
{
    const OIIO::ImageBuf grass = linear_crop("grass.png", 64, 64);
    OIIO::ImageBuf dst;
    EXPECT_FALSE(texture_fill(dst, grass, ellipse_mask(63, 64, 30, 30, 5, 5), seeded(1)));
    EXPECT_NE(dst.geterror().find("the mask is 63x64 with 1 channel; it must be one channel of "
                                  "the image's size (64x64)"),
        std::string::npos)
        << dst.geterror();
    OIIO::ImageBuf rgb_mask(OIIO::ImageSpec(64, 64, 3, OIIO::TypeDesc::FLOAT));
    dst.clear();
    EXPECT_FALSE(texture_fill(dst, grass, rgb_mask, seeded(1)));
    EXPECT_NE(dst.geterror().find("3 channels"), std::string::npos) << dst.geterror();
    OIIO::ImageBuf nan_mask = ellipse_mask(64, 64, 30, 30, 5, 5);
    const float nan = std::nanf("");
    nan_mask.setpixel(3, 4, &nan);
    dst.clear();
    EXPECT_FALSE(texture_fill(dst, grass, nan_mask, seeded(1)));
    EXPECT_NE(dst.geterror().find("mask: "), std::string::npos) << dst.geterror();
    // A mask blends by its value: outside 0..1 it would extrapolate past the image's values.
    for (const float beyond : { 2.5f, -0.5f }) {
        OIIO::ImageBuf over = ellipse_mask(64, 64, 30, 30, 5, 5);
        over.setpixel(30, 31, &beyond);
        dst.clear();
        EXPECT_FALSE(texture_fill(dst, grass, over, seeded(1)));
        EXPECT_EQ(dst.geterror(),
            "the mask has the value " + std::string(beyond > 0 ? "2.5" : "-0.5")
                + " at 30,31; its values must be in 0..1");
    }
    // A hole too large for its small image at the levels asked for.
    FillOptions opt = seeded(1);
    opt.levels = 5;
    opt.iterations = { 2 };
    dst.clear();
    EXPECT_FALSE(texture_fill(dst, grass, ellipse_mask(64, 64, 32, 32, 20, 20), opt));
    EXPECT_NE(dst.geterror().find("no 11x11 patch of known pixels"), std::string::npos)
        << dst.geterror();
}

// The wrap-around lines' rank among all lines of the image, by mean absolute step across
// the line (columns for x, rows for y): the fraction of lines stepping at least as much as
// the wrap's, the smaller of the two axes. ~0: the seam is the image's worst edge; a
// seamless tile's wrap is a line like the others.
double seam_rank(const OIIO::ImageBuf& image)
{
    const PlanarImage p = planes_of(image);
    const int w = p.width(), h = p.height();
    std::vector<double> cols(size_t(w), 0.0), rows(size_t(h), 0.0);
    for (const Plane& c : p.channels)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                cols[size_t(x)] += std::abs(c((x + 1) % w, y) - c(x, y));
                rows[size_t(y)] += std::abs(c(x, (y + 1) % h) - c(x, y));
            }
    auto rank = [](const std::vector<double>& steps) {
        const double wrap = steps.back();
        return double(std::count_if(steps.begin(), steps.end(), [&](double s) {
            return s >= wrap;
        })) / double(steps.size());
    };
    return std::min(rank(cols), rank(rows));
}

// --tileable: samples whose wrap-around seams show tile at their own size, with only the
// band across the seams changed. Stochastic samples: the seam ratio (wrap step over interior
// steps) <= 1.1, the bound. Structured ones, whose rows differ by nature (a mortar
// line's edge steps more than a brick's middle): the wrap is no longer among their worst
// lines.
TEST(Tileable, SamplesTileAndKeepTheirMiddle)
{
    struct Case {
        const char* name;
        bool structured;
        bool lit; // check_homogeneity's uneven_for_copying: flatten=1, as the tool advises
    };
    for (const Case& c : { Case { "rust.png", false, true }, Case { "grass.png", false, false },
             Case { "stucco_yellow.png", false, false }, Case { "bricks.png", true, true },
             Case { "tiles_green.png", true, true }, Case { "wood_grain.png", true, false } }) {
        SCOPED_TRACE(c.name);
        const OIIO::ImageBuf sample = linear_sample(c.name);
        const int w = sample.spec().width, h = sample.spec().height;
        TileableOptions opt;
        opt.options.seed = 1;
        opt.flatten = c.lit;
        TileableReport report;
        const OIIO::ImageBuf tile = make_tileable(sample, opt, &report);
        ASSERT_FALSE(tile.has_error()) << tile.geterror();
        const std::string key = std::string("tileable.") + c.name;
        test::doc_number(key + ".seam_before", test::seam_ratio(sample), 2);
        test::doc_number(key + ".seam_after", test::seam_ratio(tile), 2);
        test::doc_number(key + ".rank_before", seam_rank(sample), 3);
        test::doc_number(key + ".rank_after", seam_rank(tile), 3);
        test::doc_number(key + ".changed", 100.0 * report.changed_fraction, 0);
        std::cout << c.name << ": seam ratio " << test::seam_ratio(sample) << " -> "
                  << test::seam_ratio(tile) << ", seam rank " << seam_rank(sample) << " -> "
                  << seam_rank(tile) << ", band " << report.band << ", changed "
                  << report.changed_fraction << "\n";
        // Measured (seed 1): seam ratio 1.83 -> 0.93 (rust), 1.57 -> 0.94 (grass), 1.19 ->
        // 0.91 (stucco); seam rank 0.004 -> 0.027 (bricks), 0.016 -> 0.070 (tiles), 0.008 ->
        // 0.68 (wood).
        if (c.structured) {
            EXPECT_GE(seam_rank(tile), 4.0 * seam_rank(sample));
            EXPECT_GE(seam_rank(tile), 0.02);
        } else {
            EXPECT_LE(test::seam_ratio(tile), 1.1);
            EXPECT_GE(seam_rank(tile), 0.1);
        }
        EXPECT_EQ(tile.spec().get_string_attribute("wrapmodes"), "periodic,periodic");
        // The band straddles the seams: it is half at each edge of the image.
        const int half = report.band / 2;
        auto in_band = [&](int x, int y) {
            return x < report.band - half || x >= w - half || y < report.band - half
                || y >= h - half;
        };
        // Outside the band: the sample's pixels (flattened, with flatten=1).
        PlanarImage kept = planes_of(sample);
        if (opt.flatten)
            flatten_illumination(kept);
        OIIO::ImageBuf kept_image;
        imagebuf_from_planes(kept, kept_image);
        EXPECT_TRUE(
            identical_where(tile, kept_image, [&](int x, int y) { return !in_band(x, y); }));
        const double band_fraction
            = 1.0 - double(w - report.band) * double(h - report.band) / (double(w) * double(h));
        EXPECT_LE(report.changed_fraction, band_fraction + 1e-9);
        EXPECT_GT(report.changed_fraction, 0.5 * band_fraction);
    }
}

TEST(Tileable, ABandTooWideIsRefused)
{
    TileableOptions opt;
    opt.band = 50;
    OIIO::ImageBuf dst;
    EXPECT_FALSE(make_tileable(dst, linear_sample("wood_grain.png"), opt));
    EXPECT_NE(dst.geterror().find("band=50 : too wide for a 128x128 image (at most a third of "
                                  "its shorter side, 42)"),
        std::string::npos)
        << dst.geterror();
}

TEST(Tileable, SmallImagesWorkWithTheDefaultsOrSayWhatToChange)
{
    // 96x96: the default band leaves the coarsest levels no whole patch to copy; the
    // automatic levels stop above them.
    TileableOptions opt;
    TileableReport report;
    const OIIO::ImageBuf small = linear_crop("grass.png", 96, 96);
    const OIIO::ImageBuf tile = make_tileable(small, opt, &report);
    ASSERT_FALSE(tile.has_error()) << tile.geterror();
    EXPECT_EQ(report.band, 22);
    EXPECT_GT(report.changed_fraction, 0.0);
    // 64x64: two 11-pixel patches are over a third of the side.
    OIIO::ImageBuf dst;
    EXPECT_FALSE(make_tileable(dst, linear_crop("grass.png", 64, 64), opt));
    EXPECT_EQ(dst.geterror(),
        "a 64x64 image is too small for a band two 11-pixel patches wide (at most a third of "
        "its shorter side, 21): give a smaller patch= or band=");
    opt.options.patch = { 7, 5 };
    EXPECT_FALSE(make_tileable(linear_crop("grass.png", 64, 64), opt).has_error());
}

namespace {

// A soft plate: the top-left 64x64 of a bundled sample enlarged 8 times (OIIO's resize),
// as a photograph blown up for a matte painting is.
OIIO::ImageBuf soft_plate(const char* name)
{
    return OIIO::ImageBufAlgo::resize(
        linear_crop(name, 64, 64), "", 0.0f, OIIO::ROI(0, 512, 0, 512));
}

// A one-channel w x h mask: 1 in the box, optionally blurred by a `feather`-pixel box.
OIIO::ImageBuf box_mask(int w, int h, OIIO::ROI box, int feather = 0)
{
    OIIO::ImageBuf mask(OIIO::ImageSpec(w, h, 1, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(mask, { 1.0f }, box);
    if (feather > 0)
        mask = OIIO::ImageBufAlgo::convolve(
            mask, OIIO::ImageBufAlgo::make_kernel("box", float(feather), float(feather)));
    return mask;
}

// The outline measure: the mean luminance step between each filled pixel and its
// kept 4-neighbours (across the mask's outline), in the result over the same in the image.
double outline_step_ratio(
    const OIIO::ImageBuf& filled, const OIIO::ImageBuf& image, const OIIO::ImageBuf& mask)
{
    const Plane f = test::luminance_of(filled), o = test::luminance_of(image);
    const int w = f.width(), h = f.height();
    double sf = 0.0, so = 0.0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            if (!(mask.getchannel(x, y, 0, 0) > 0.0f))
                continue;
            for (const auto& [dx, dy] : { std::pair { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } })
                if (!(mask.getchannel(x + dx, y + dy, 0, 0) > 0.0f)) {
                    sf += std::abs(f(x, y) - f(x + dx, y + dy));
                    so += std::abs(o(x, y) - o(x + dx, y + dy));
                }
        }
    return sf / so;
}

// The power spectrum (Hann-windowed, 3x3-smoothed, centred) of a square of `l`.
std::vector<double> spectrum_of(const Plane& l, int x0, int y0, int n)
{
    std::string error;
    const auto fft = RealFft2D::create(n, n, FftBackend::Kiss, error);
    std::vector<float> v(size_t(n) * size_t(n));
    double mean = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            mean += l(x0 + x, y0 + y) / (double(n) * n);
    const double pi = 3.14159265358979323846;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            v[size_t(y) * size_t(n) + size_t(x)]
                = float((l(x0 + x, y0 + y) - mean) * (0.5 - 0.5 * std::cos(2 * pi * (x + 0.5) / n))
                    * (0.5 - 0.5 * std::cos(2 * pi * (y + 0.5) / n)));
    std::vector<std::complex<float>> s(fft->spectrum_size());
    fft->forward(v.data(), s.data());
    const int half = n / 2 + 1;
    std::vector<double> p(size_t(n) * size_t(n));
    for (int ky = 0; ky < n; ++ky)
        for (int kx = 0; kx < n; ++kx) {
            const int hx = kx < half ? kx : n - kx, hy = kx < half ? ky : (n - ky) % n;
            p[size_t((ky + n / 2) % n) * size_t(n) + size_t((kx + n / 2) % n)]
                = std::norm(s[size_t(hy) * size_t(half) + size_t(hx)]);
        }
    std::vector<double> smooth(p.size(), 0.0);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i)
                    smooth[size_t(y) * size_t(n) + size_t(x)]
                        += p[size_t((y + j + n) % n) * size_t(n) + size_t((x + i + n) % n)] / 9.0;
    return smooth;
}

// A square's spectral peakiness: over rings of wavelengths from 4 pixels to a quarter of the
// square, the largest power over the ring's median. A regular lattice is a line standing
// far above its ring; texture spreads its energy round it.
double peakiness(const Plane& l, int x0, int y0, int n)
{
    const std::vector<double> p = spectrum_of(l, x0, y0, n);
    double worst = 0.0;
    for (int k = 4; k <= n / 4; ++k) {
        std::vector<double> ring;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                if (int(std::lround(std::hypot(x - n / 2, y - n / 2))) == k)
                    ring.push_back(p[size_t(y) * size_t(n) + size_t(x)]);
        const double top = *std::max_element(ring.begin(), ring.end());
        std::nth_element(ring.begin(), ring.begin() + std::ptrdiff_t(ring.size() / 2), ring.end());
        worst = std::max(worst, top / std::max(ring[ring.size() / 2], 1e-30));
    }
    return worst;
}

// The lattice measure: the peakiness of a square inside the hole over the largest of four
// squares around it (the plate's own lines: its resampling grid, a weave's period).
double lattice_peak(const OIIO::ImageBuf& filled, OIIO::ROI hole)
{
    const Plane l = test::luminance_of(filled);
    const int n = std::min(hole.width(), hole.height()) * 3 / 4;
    const int cx = (hole.xbegin + hole.xend) / 2, cy = (hole.ybegin + hole.yend) / 2;
    double around = 0.0;
    for (const auto& [x0, y0] :
        { std::pair { cx - n / 2, hole.ybegin - n }, { cx - n / 2, hole.yend },
            { hole.xbegin - n, cy - n / 2 }, { hole.xend, cy - n / 2 } })
        around = std::max(around, peakiness(l, x0, y0, n));
    return peakiness(l, cx - n / 2, cy - n / 2, n) / around;
}

} // namespace

// The soft-plate test: on a plate enlarged 8 times, the step across the mask's
// outline is at most 1.5x the plate's own step there; and on a sharp plate.
TEST(Fill, TheOutlineDoesNotShowOnSoftOrSharpPlates)
{
    struct Case {
        OIIO::ImageBuf plate;
        OIIO::ImageBuf mask;
        const char* what;
        const char* key;
    };
    const Case cases[] = {
        { soft_plate("flowers.png"), box_mask(512, 512, OIIO::ROI(208, 304, 208, 304)), "soft",
            "soft_flowers" },
        { soft_plate("pebbles.png"), box_mask(512, 512, OIIO::ROI(110, 390, 140, 360)),
            "soft, object-sized", "soft_pebbles_large" },
        { linear_sample("bricks.png"), box_mask(256, 256, OIIO::ROI(100, 160, 100, 160)), "sharp",
            "sharp_bricks" },
        { linear_sample("rust.png"), box_mask(256, 256, OIIO::ROI(90, 170, 80, 150)), "sharp",
            "sharp_rust" },
    };
    for (const Case& c : cases) {
        FillOptions opt = seeded(1);
        const OIIO::ImageBuf filled = texture_fill(c.plate, c.mask, opt);
        ASSERT_FALSE(filled.has_error()) << filled.geterror();
        const double matched = outline_step_ratio(filled, c.plate, c.mask);
        opt.outline = FillOutline::Copy;
        const double copied
            = outline_step_ratio(texture_fill(c.plate, c.mask, opt), c.plate, c.mask);
        test::doc_number(std::string("fill.outline.") + c.key + ".match", matched, 2);
        test::doc_number(std::string("fill.outline.") + c.key + ".copy", copied, 2);
        std::cout << c.what << ": outline step " << matched
                  << " x the plate's (outline=copy: " << copied << ")\n";
        EXPECT_LE(matched, 1.5) << c.what;
    }
}

// No regular lattice inside a large or a feathered hole: the hole's spectrum holds no line
// twice as prominent as the plate's around it; a lattice pasted into the hole (a 12-pixel
// tile of the plate repeated) does.
TEST(Fill, LargeAndFeatheredHolesHoldNoLattice)
{
    const OIIO::ROI hole(176, 336, 176, 336);
    for (const char* name : { "flowers.png", "pebbles.png" }) {
        const OIIO::ImageBuf plate = soft_plate(name);
        const double own = lattice_peak(plate, hole); // a square of the plate among its own
        for (int feather : { 0, 41 }) {
            const OIIO::ImageBuf filled
                = texture_fill(plate, box_mask(512, 512, hole, feather), seeded(1));
            ASSERT_FALSE(filled.has_error()) << filled.geterror();
            const double peak = lattice_peak(filled, hole);
            test::doc_number(
                std::string("fill.lattice.") + name + (feather ? ".feathered" : ".hard"), peak, 2);
            std::cout << name << (feather ? " feathered" : "") << ": lattice peak " << peak
                      << " (the plate's own " << own << ")\n";
            EXPECT_LT(peak, 2.0) << name << " feather " << feather;
        }
        // The control: a 12x12 tile of the plate repeated over the hole.
        OIIO::ImageBuf lattice = plate;
        for (int y = hole.ybegin; y < hole.yend; ++y)
            for (int x = hole.xbegin; x < hole.xend; ++x) {
                float p[3];
                plate.getpixel(240 + (x % 12), 240 + (y % 12), p);
                lattice.setpixel(x, y, p);
            }
        EXPECT_GT(lattice_peak(lattice, hole), 2.0) << name;
    }
}

// map= gives the fill's source map: applied to the image it gives the fill with
// outline=copy; to another map aligned with the image (a material's height), the same
// copies, blended by the mask.
TEST(Fill, ItsSourceMapFillsAnotherMapWithTheSameCopies)
{
    const OIIO::ImageBuf image = linear_sample("bricks.png");
    const OIIO::ImageBuf mask = box_mask(256, 256, OIIO::ROI(100, 160, 100, 160), 9);
    FillOptions opt = seeded(1);
    opt.outline = FillOutline::Copy;
    OIIO::ImageBuf map;
    const OIIO::ImageBuf filled = texture_fill(image, mask, opt, nullptr, nullptr, nullptr, &map);
    ASSERT_FALSE(filled.has_error()) << filled.geterror();
    ASSERT_EQ(map.nchannels(), 3);
    EXPECT_EQ(map.spec().channel_name(2), "m");
    const OIIO::ImageBuf again = apply_source_map(map, image);
    ASSERT_FALSE(again.has_error()) << again.geterror();
    double worst = 0.0;
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x)
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst,
                    double(std::abs(again.getchannel(x, y, 0, c) - filled.getchannel(x, y, 0, c))));
    EXPECT_LT(worst, 1e-6); // the blend's float rounding
    // From a sample there is no one image to map to.
    OIIO::ImageBuf none;
    OIIO::ImageBuf from_sample = texture_fill(image, mask, opt, &image, nullptr, nullptr, &none);
    EXPECT_TRUE(from_sample.has_error());
    EXPECT_NE(from_sample.geterror().find("map= : a fill from sample="), std::string::npos);
}

namespace {

// A region's structure at three scales: the mean squared luminance difference at shifts of
// 1, 2 and 4 pixels (along x and y), i.e. the energy of its bands.
std::array<double, 3> band_energies(const Plane& l, int x0, int y0, int w, int h)
{
    std::array<double, 3> e {};
    for (int k = 0; k < 3; ++k) {
        const int s = 1 << k;
        double sum = 0.0;
        size_t n = 0;
        for (int y = y0; y + s < y0 + h; ++y)
            for (int x = x0; x + s < x0 + w; ++x) {
                sum += std::pow(l(x + s, y) - l(x, y), 2) + std::pow(l(x, y + s) - l(x, y), 2);
                n += 2;
            }
        e[size_t(k)] = sum / double(n);
    }
    return e;
}

double band_distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
    double d = 0.0;
    for (size_t k = 0; k < 3; ++k)
        d += std::abs(std::log(a[k] / b[k])) / 3.0;
    return d;
}

} // namespace

// The small-sample test: on samples of 128 px, the band --tileable changed has the
// sample's band energies within 1.5x the spread of the untouched middle's own strips, and
// the result tiles (seam ratio <= 1.1).
TEST(Tileable, SmallSamplesGetABandLikeTheirMiddle)
{
    for (const char* name : { "marble_pink.png", "paper_crinkled.png", "stucco_yellow.png",
             "leaves_autumn.png", "pebbles.png", "flowers.png", "wood_grain.png" }) {
        SCOPED_TRACE(name);
        const OIIO::ImageBuf sample = linear_crop(name, 128, 128);
        TileableOptions opt;
        opt.options.seed = 1;
        TileableReport report;
        const OIIO::ImageBuf tile = make_tileable(sample, opt, &report);
        ASSERT_FALSE(tile.has_error()) << tile.geterror();
        const Plane l = test::luminance_of(tile), s = test::luminance_of(sample);
        const auto target = band_energies(s, 0, 0, 128, 128);
        const int b = report.band, strip_h = 128 / 2 - b / 2 - b / 2;
        // The changed band: the columns around the left/right seam (x < b/2 or >= 128 - b/2),
        // rolled together, above the crossing with the horizontal band.
        Plane band(b, strip_h);
        for (int y = 0; y < strip_h; ++y)
            for (int x = 0; x < b; ++x)
                band(x, y) = l((x + 128 - b / 2) % 128, b / 2 + y);
        const double in_band = band_distance(band_energies(band, 0, 0, b, strip_h), target);
        // The middle's own strips of the same size, away from the band.
        double middle = 0.0;
        for (int x0 = b / 2 + 4; x0 + b <= 128 - b / 2 - 4; x0 += 8)
            middle
                = std::max(middle, band_distance(band_energies(l, x0, b / 2, b, strip_h), target));
        test::doc_number(std::string("tileable.small.") + name + ".band", in_band, 2);
        test::doc_number(std::string("tileable.small.") + name + ".middle", middle, 2);
        test::doc_number(
            std::string("tileable.small.") + name + ".seam", test::seam_ratio(tile), 2);
        std::cout << name << ": band " << b << " px, band energies off by " << in_band
                  << " (the middle's strips up to " << middle << "), seam ratio "
                  << test::seam_ratio(tile) << "\n";
        EXPECT_LE(in_band, 1.5 * middle);
        EXPECT_LE(test::seam_ratio(tile), 1.1);
    }
}
