// SPDX-License-Identifier: Apache-2.0
// The patch method: PatchMatch against the exhaustive search, the vote, the histogram kept,
// the repetition penalty, determinism, the seams, bad input, and the structure of bricks,
// tiles, weave, wood and flowers against the neighbourhood method's.
#include <texsyn/feature_scale.h>
#include <texsyn/fill.h>
#include <texsyn/neighborhood.h>
#include <texsyn/patch.h>
#include <texsyn/random.h>
#include <texsyn/source_map.h>

#include <cmath>
#include <limits>
#include <set>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "feature_scale/structure_distance_pvt.h"
#include "patch/patch_pvt.h"
#include "structure_metric.h"
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

PatchOptions options(int w, int h)
{
    PatchOptions opt;
    opt.width = w;
    opt.height = h;
    opt.seed = 5;
    return opt;
}

// options(w, h) with a fixed schedule (the one the defaults were before they tuned
// themselves): for tests of what one option does, whatever the automatic schedule picks.
PatchOptions fixed_options(int w, int h)
{
    PatchOptions opt = options(w, h);
    opt.levels = 3;
    opt.patch = { 11, 7 };
    opt.iterations = { 1, 2, 4 };
    return opt;
}

// A field of seeded random sources inside `range`.
detail::PatchField random_field(int w, int h, const detail::CentreRange& range, uint64_t seed)
{
    detail::PatchField f { w, h, std::vector<uint32_t>(size_t(w) * size_t(h)),
        std::vector<float>(size_t(w) * size_t(h)) };
    for (size_t q = 0; q < f.source.size(); ++q) {
        const uint64_t bits = random_bits(seed, 1, q);
        f.source[q]
            = range.clamp(range.column_x(int(bits % 1000)), range.y0() + int((bits >> 32) % 1000));
    }
    return f;
}

// The mean over output pixels of the nearest sample patch's distance, exactly.
double exhaustive_mean(const detail::SampleLevel& sample, const detail::PixelImage& padded, int pad,
    int w, int h, int patch)
{
    const detail::CentreRange range { sample.pixels.width, sample.pixels.height, patch / 2 };
    double sum = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float best = std::numeric_limits<float>::infinity();
            for (int sy = range.y0(); sy <= range.y1(); ++sy)
                for (int sx = range.column_x(0); sx <= range.column_x(range.columns() - 1); ++sx)
                    best = std::min(best,
                        detail::patch_distance(padded, pad, x, y, sample.pixels,
                            uint32_t(sy * sample.pixels.width + sx), patch, best));
            sum += best;
        }
    return sum / double(w * h);
}

double mean(const std::vector<float>& v)
{
    double s = 0.0;
    for (float x : v)
        s += x;
    return s / double(v.size());
}

} // namespace

// PatchMatch's passes (propagation at steps 4, 2, 1 with k-coherence and the random
// search) bring the field's mean distance to within 15% of the exhaustive search's after
// four searches, from a random start, on real texture (a bricks crop matched against
// another part of the wall).
TEST(PatchMatch, ApproachesTheExhaustiveSearch)
{
    const PlanarImage wall = planes_of(linear_crop("bricks.png", 96, 96));
    std::vector<Plane> sample_planes, target_planes;
    for (const Plane& c : wall.channels) {
        Plane s(48, 48), t(32, 32);
        for (int y = 0; y < 48; ++y)
            for (int x = 0; x < 48; ++x)
                s(x, y) = c(x, y);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                t(x, y) = c(x + 60, y + 55);
        sample_planes.push_back(s);
        target_planes.push_back(t);
    }
    const int patch = 7, pad = patch / 2;
    const detail::SampleLevel sample = detail::sample_level(sample_planes, 0, 0);
    const detail::PixelImage padded = detail::interleave_padded(target_planes, pad, 0);
    const detail::CentreRange range { 48, 48, pad };
    detail::PatchField field = random_field(32, 32, range, 3);
    const std::vector<uint32_t> similar
        = detail::similar_patches(sample.pixels, 0, patch, 2, 0, nullptr);
    detail::MatchSettings match;
    match.patch = patch;
    match.coherence = 2;
    double first = 0.0;
    for (int it = 0; it < 4; ++it) {
        match.stream = uint64_t(it);
        detail::patch_match(sample, padded, pad, similar, match, field);
        if (it == 0)
            first = mean(field.distance);
    }
    const double exact = exhaustive_mean(sample, padded, pad, 32, 32, patch);
    const double found = mean(field.distance);
    EXPECT_GE(found, exact * 0.9999);
    EXPECT_LE(found, exact * 1.15) << "exact " << exact << " first pass " << first;
    EXPECT_LT(found, first); // later searches improve on the first
}

// The vote of a field that copies a periodic sample consistently (every patch agrees)
// gives the sample's pixels exactly, and so does the final copy.
TEST(PatchVote, AConsistentFieldOfAPeriodicSampleReproducesItExactly)
{
    const int period = 12, patch = 5;
    const PlanarImage noise = planes_of(linear_crop("rust.png", period, period));
    std::vector<Plane> sample_planes;
    for (const Plane& c : noise.channels) {
        Plane s(3 * period, 3 * period);
        for (int y = 0; y < s.height(); ++y)
            for (int x = 0; x < s.width(); ++x)
                s(x, y) = c(x % period, y % period);
        sample_planes.push_back(s);
    }
    const detail::SampleLevel sample = detail::sample_level(sample_planes, 0, 0);
    // Output = one period (a torus); pixel (x, y) copies sample (x + 12, y + 12).
    detail::PatchField field { period, period, {}, std::vector<float>(period * period, 0.0f) };
    for (int y = 0; y < period; ++y)
        for (int x = 0; x < period; ++x)
            field.source.push_back(uint32_t((y + period) * 3 * period + x + period));
    for (PatchVote kind : { PatchVote::Mean, PatchVote::Robust }) {
        std::vector<Plane> out;
        detail::vote(sample, field, patch, kind, 0, nullptr, out);
        const std::vector<uint32_t> chosen
            = detail::nearest_votes(sample, field, patch, out, 0, nullptr);
        for (size_t c = 0; c < out.size(); ++c)
            for (int y = 0; y < period; ++y)
                for (int x = 0; x < period; ++x) {
                    EXPECT_NEAR(out[c](x, y), noise.channels[c](x, y), 1e-6f);
                    EXPECT_EQ(sample_planes[c].data()[chosen[size_t(y * period + x)]],
                        noise.channels[c](x, y));
                }
    }
}

TEST(PatchSynthesize, AConstantSampleGivesAConstantOutput)
{
    OIIO::ImageBuf sample(OIIO::ImageSpec(40, 40, 3, OIIO::TypeFloat));
    const float grey[3] = { 0.25f, 0.5f, 0.75f };
    OIIO::ImageBufAlgo::fill(sample, grey);
    OIIO::ImageBuf out = patch_synthesize(sample, options(64, 48));
    ASSERT_FALSE(out.has_error()) << out.geterror();
    ASSERT_EQ(out.spec().width, 64);
    ASSERT_EQ(out.spec().height, 48);
    const auto stats = OIIO::ImageBufAlgo::computePixelStats(out);
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(stats.min[size_t(c)], grey[c]);
        EXPECT_EQ(stats.max[size_t(c)], grey[c]);
    }
}

// The result copies sample pixels (its source map reproduces it exactly, as --apply-map
// does for a material's other maps), keeps the sample's histogram (matched inside the
// loop; the average alone washes it out), tiles, and carries alpha.
TEST(PatchSynthesize, CopiesKeepsTheHistogramTilesAndCarriesAlpha)
{
    Plane alpha;
    const OIIO::ImageBuf sample = test::stucco_with_alpha(alpha);
    OIIO::ImageBuf map;
    PatchReport report;
    const OIIO::ImageBuf out = patch_synthesize(sample, options(160, 144), &map, nullptr, &report);
    ASSERT_FALSE(out.has_error()) << out.geterror();
    EXPECT_EQ(out.nchannels(), 4);
    EXPECT_EQ(out.spec().alpha_channel, 3);
    EXPECT_EQ(out.spec().get_string_attribute("synth:method"), "patch");
    const OIIO::ImageBuf again = apply_source_map(map, sample);
    ASSERT_FALSE(again.has_error()) << again.geterror();
    EXPECT_EQ(pixel_hash(again), pixel_hash(out));
    EXPECT_LT(worst_w1(out, sample), 0.02);
    EXPECT_LT(seam_ratio(out), 1.3);
    EXPECT_GT(report.used_fraction, 0.5);
    EXPECT_LE(report.used_fraction, 1.0);
    EXPECT_GT(report.largest_copy, 0u);
    EXPECT_GE(report.levels, 2);
}

// repetition= spreads the result over the sample: more of it used. (It balances how often
// each source is used, not how far a coherent copy runs: verbatim copies barely shrink.)
TEST(PatchSynthesize, TheRepetitionPenaltyUsesMoreOfTheSample)
{
    const OIIO::ImageBuf sample = linear_crop("bricks.png", 96, 96);
    PatchReport plain, spread;
    PatchOptions opt = fixed_options(192, 192);
    opt.repetition = 0.0f;
    ASSERT_FALSE(patch_synthesize(sample, opt, nullptr, nullptr, &plain).has_error());
    opt.repetition = 2.0f;
    ASSERT_FALSE(patch_synthesize(sample, opt, nullptr, nullptr, &spread).has_error());
    EXPECT_GT(spread.used_fraction, plain.used_fraction + 0.03)
        << plain.used_fraction << " -> " << spread.used_fraction;
}

TEST(PatchSynthesize, IsBitIdenticalAtAnyThreadCount)
{
    const OIIO::ImageBuf sample = linear_crop("bricks.png", 96, 96);
    std::string first;
    for (int threads : { 1, 2, 4 }) {
        PatchOptions opt = options(150, 130);
        opt.nthreads = threads;
        OIIO::ImageBuf map;
        const OIIO::ImageBuf out = patch_synthesize(sample, opt, &map);
        ASSERT_FALSE(out.has_error()) << out.geterror();
        const std::string hash = pixel_hash(out) + pixel_hash(map);
        if (first.empty())
            first = hash;
        EXPECT_EQ(hash, first) << threads << " threads";
    }
    PatchOptions other = options(150, 130);
    other.seed = 6;
    EXPECT_NE(pixel_hash(patch_synthesize(sample, other)), first.substr(0, 16));
}

// The variants of isotropic=1: each a permutation of the sample's pixels, all different.
TEST(PatchVariants, AreTheSamplesRotationsAndMirrorImages)
{
    EXPECT_EQ(detail::variant_count(6, 6, false), 1);
    EXPECT_EQ(detail::variant_count(6, 6, true), 8);
    EXPECT_EQ(detail::variant_count(6, 4, true), 4);
    Plane p(5, 5);
    for (size_t i = 0; i < p.size(); ++i)
        p.data()[i] = float(i);
    std::set<std::vector<float>> seen;
    for (int t = 0; t < 8; ++t) {
        const Plane v = detail::variant_plane(p, t);
        std::vector<float> values(v.data(), v.data() + v.size());
        seen.insert(values);
        std::sort(values.begin(), values.end());
        for (size_t i = 0; i < values.size(); ++i)
            EXPECT_EQ(values[i], float(i)) << t;
    }
    EXPECT_EQ(seen.size(), 8u);
    // t = 5: transposed ((1, 0) -> (0, 1)), then mirrored in x ((0, 1) -> (4, 1)).
    EXPECT_EQ(detail::variant_source(5, 5, 5, 1, 0), 1u * 5 + 4);
}

// Horizontal over vertical gradient energy of the first channel: far from 1 for a texture
// with a direction.
double gradient_ratio(const OIIO::ImageBuf& buf)
{
    const Plane p = planes_of(buf).channels[0];
    double gx = 0, gy = 0;
    for (int y = 0; y + 1 < p.height(); ++y)
        for (int x = 0; x + 1 < p.width(); ++x) {
            gx += double(p(x + 1, y) - p(x, y)) * double(p(x + 1, y) - p(x, y));
            gy += double(p(x, y + 1) - p(x, y)) * double(p(x, y + 1) - p(x, y));
        }
    return gx / gy;
}

// isotropic=1 takes patches from the rotated sample too: wood grain loses its direction,
// and the source map still names pixels of the sample as given.
TEST(PatchSynthesize, IsotropicTakesRotatedPatches)
{
    const OIIO::ImageBuf sample = linear_crop("wood_grain.png", 96, 96);
    PatchOptions opt = fixed_options(128, 128);
    const double kept = gradient_ratio(patch_synthesize(sample, opt));
    opt.isotropic = 1;
    OIIO::ImageBuf map;
    const OIIO::ImageBuf turned = patch_synthesize(sample, opt, &map);
    ASSERT_FALSE(turned.has_error()) << turned.geterror();
    const double ratio = gradient_ratio(turned);
    EXPECT_GT(std::abs(std::log(kept)), 2.0 * std::abs(std::log(ratio)))
        << "kept " << kept << ", isotropic " << ratio;
    EXPECT_EQ(pixel_hash(apply_source_map(map, sample)), pixel_hash(turned));
}

TEST(PatchSynthesize, AGuideImageSteersTheLayout)
{
    const OIIO::ImageBuf sample = linear_crop("bricks.png", 96, 96);
    // A guide that is the sample's own rows: left half 0, right half 1.
    OIIO::ImageBuf guide(OIIO::ImageSpec(96, 96, 1, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(guide, { 1.0f }, OIIO::ROI(48, 96, 0, 96, 0, 1, 0, 1));
    const OIIO::ImageBuf with = patch_synthesize(sample, options(96, 96), nullptr, &guide);
    ASSERT_FALSE(with.has_error()) << with.geterror();
    EXPECT_NE(pixel_hash(with), pixel_hash(patch_synthesize(sample, options(96, 96))));

    OIIO::ImageBuf wrong(OIIO::ImageSpec(90, 96, 1, OIIO::TypeFloat));
    OIIO::ImageBuf out = patch_synthesize(sample, options(96, 96), nullptr, &wrong);
    EXPECT_EQ(out.geterror(),
        "the guide is 90x96 with 1 channel; it must be one channel of the sample's size (96x96)");
    PatchOptions none = options(96, 96);
    none.guidance = 0.0f;
    out = patch_synthesize(sample, none, nullptr, &guide);
    EXPECT_EQ(out.geterror(), "guidance=0 : a guide needs a guidance weight above 0");
}

TEST(PatchSynthesize, BadInputIsRefused)
{
    const OIIO::ImageBuf sample = linear_crop("bricks.png", 64, 64);
    auto error_of = [&](const OIIO::ImageBuf& s, const PatchOptions& opt) {
        const OIIO::ImageBuf out = patch_synthesize(s, opt);
        EXPECT_TRUE(out.has_error());
        return out.geterror();
    };
    EXPECT_EQ(error_of(linear_crop("bricks.png", 6, 40), fixed_options(64, 64)),
        "the sample (6x40) is smaller than the 7-pixel patch (give a smaller patch=)");
    EXPECT_EQ(
        error_of(sample, fixed_options(5, 64)), "size=5x64 is smaller than the 7-pixel patch");
    // Automatic patch sizes shrink with a small sample or output, down to 3 pixels.
    EXPECT_FALSE(patch_synthesize(linear_crop("bricks.png", 6, 40), options(64, 64)).has_error());
    EXPECT_FALSE(patch_synthesize(sample, options(5, 64)).has_error());
    EXPECT_EQ(error_of(linear_crop("bricks.png", 2, 40), options(64, 64)),
        "the sample (2x40) is smaller than the 3-pixel patch (give a smaller patch=)");
    PatchOptions opt = options(64, 64);
    opt.levels = 4;
    EXPECT_EQ(error_of(sample, opt),
        "levels=4 is too many for a 64x64 sample and a 64x64 output: level 3 would be smaller "
        "than its 11-pixel patch (use levels=3 or less)");
    opt = options(64, 64);
    opt.patch = { 5, 9 };
    EXPECT_EQ(error_of(sample, opt), "patch=5,9 : list the sizes largest first");
    opt = options(64, 64);
    opt.patch = { 8 };
    EXPECT_EQ(error_of(sample, opt), "patch=8 : not odd");
    opt = options(60000, 60000);
    EXPECT_NE(error_of(sample, opt).find("size=60000x60000 would need about"), std::string::npos);
    OIIO::ImageBuf nan = sample;
    nan.setpixel(3, 4, 0, std::vector<float> { NAN, 0.0f, 0.0f }.data());
    EXPECT_NE(error_of(nan, options(64, 64)).find("NaN"), std::string::npos);
}

TEST(PatchOptions, ADefaultScheduleFollowsFewerLevels)
{
    // The automatic iterations follow the levels: 1 at the finest, 3 at the next, 8 at the
    // coarser ones and at the coarsest. A list the user gives must fit.
    PatchOptions opt;
    opt.levels = 2;
    std::string error;
    EXPECT_TRUE(opt.validate(error)) << error;
    EXPECT_EQ(opt.iterations_at(0), 1);
    EXPECT_EQ(opt.iterations_at(1), 8);
    opt.levels = 4;
    EXPECT_EQ(opt.iterations_at(0), 1);
    EXPECT_EQ(opt.iterations_at(1), 3);
    EXPECT_EQ(opt.iterations_at(2), 8);
    EXPECT_EQ(opt.iterations_at(3), 8);
    opt.levels = 2;
    opt.iterations = { 1, 2, 3 };
    EXPECT_FALSE(opt.validate(error));
    EXPECT_EQ(error, "iterations=1,2,3 : 3 values for levels=2 (give 1..2)");
    FillOptions fill;
    fill.levels = 1;
    EXPECT_TRUE(fill.validate(error)) << error;
    EXPECT_EQ(fill.iterations_at(0), 4);
    fill.iterations = { 4, 6 };
    EXPECT_FALSE(fill.validate(error));
}

// A small sample whose features are half its side (paper crinkles, 128 px) gets 4
// automatic levels, and one fewer is tried on the output (256 px: twice the sample, the
// largest trial). The schedule kept is the one whose result the tests' own,
// independent structure measure also finds nearer the sample (within 10%), its output is
// that schedule's exactly, and -v says so. Given levels, or a repeating sample, are not
// second-guessed.
TEST(PatchSynthesize, ASmallSampleKeepsTheNearerOfTwoLevelCounts)
{
    const OIIO::ImageBuf sample = linear_sample("paper_crinkled.png");
    PatchReport report;
    const OIIO::ImageBuf chosen
        = patch_synthesize(sample, options(256, 256), nullptr, nullptr, &report);
    ASSERT_FALSE(chosen.has_error()) << chosen.geterror();
    EXPECT_NE(report.schedule.find("levels kept over"), std::string::npos) << report.schedule;
    ASSERT_TRUE(report.levels == 3 || report.levels == 4) << report.levels;
    OIIO::ImageBuf given[2];
    double error[2];
    for (int i = 0; i < 2; ++i) {
        PatchOptions opt = options(256, 256);
        opt.levels = 3 + i;
        PatchReport as_given;
        given[i] = patch_synthesize(sample, opt, nullptr, nullptr, &as_given);
        ASSERT_FALSE(given[i].has_error()) << given[i].geterror();
        EXPECT_EQ(as_given.schedule, std::to_string(3 + i) + " levels, as given");
        error[i] = test::arrangement_error(given[i], sample, 16);
    }
    const int kept = report.levels - 3;
    EXPECT_EQ(pixel_hash(chosen), pixel_hash(given[kept]));
    EXPECT_LE(error[kept], 1.1 * error[1 - kept])
        << error[0] << " (3 levels), " << error[1] << " (4)";

    PatchReport bricks;
    ASSERT_FALSE(
        patch_synthesize(linear_sample("bricks.png"), options(256, 256), nullptr, nullptr, &bricks)
            .has_error());
    EXPECT_EQ(bricks.schedule.find("kept over"), std::string::npos) << bricks.schedule;
}

TEST(PatchSynthesize, ASampleAtTheLeastLevelsTriesOneMoreAndKeepsTheOneThatDoesNotRepeat)
{
    // 256-pixel samples at 512²: the trial is the output itself, so the two level counts'
    // outputs are the trial's. 3 levels are the least; 4 lay the sample out from a coarser
    // level, nearer its arrangement, but on some samples copy blocks that recur.
    bool repetition_decided = false;
    for (const char* name : { "grass.png", "pebbles.png", "flowers.png" }) {
        SCOPED_TRACE(name);
        const OIIO::ImageBuf sample = linear_sample(name);
        const PlanarImage planes = planes_of(sample);
        const double feature = estimate_feature_scale(planes, 1).size;
        PatchReport report;
        const OIIO::ImageBuf chosen
            = patch_synthesize(sample, options(512, 512), nullptr, nullptr, &report);
        ASSERT_FALSE(chosen.has_error()) << chosen.geterror();
        ASSERT_NE(report.schedule.find("levels kept over"), std::string::npos) << report.schedule;
        ASSERT_TRUE(report.levels == 3 || report.levels == 4) << report.schedule;
        double distance[2], repetition[2];
        std::string hash[2];
        for (int i = 0; i < 2; ++i) {
            PatchOptions opt = options(512, 512);
            opt.levels = 3 + i;
            const OIIO::ImageBuf given = patch_synthesize(sample, opt);
            ASSERT_FALSE(given.has_error()) << given.geterror();
            hash[i] = pixel_hash(given);
            distance[i] = detail::structure_distance(planes_of(given), planes, feature, 1);
            repetition[i] = detail::repetition_excess(planes_of(given), planes, 1);
        }
        const int kept = report.levels - 3, other = 1 - kept;
        EXPECT_EQ(pixel_hash(chosen), hash[kept]);
        // The deeper schedule is tried first; where it repeats itself, the shallower one is
        // kept without a trial of its own, and -v names the repetition that decided it.
        if (repetition[1] > std::max(0.1, feature / 512.0))
            EXPECT_NE(report.schedule.find("3 levels kept over 4, which repeats itself on a "
                                           "512x512 trial (repetition"),
                std::string::npos)
                << report.schedule;
        if (std::max(repetition[0], repetition[1]) > 0.1) {
            repetition_decided = true;
            EXPECT_LT(repetition[kept], repetition[other]) << report.schedule;
            EXPECT_NE(report.schedule.find("which repeats itself"), std::string::npos);
        } else {
            EXPECT_LE(distance[kept], distance[other]) << report.schedule;
        }
    }
    // At least one of the three is one where the deeper schedule repeats (grass does).
    EXPECT_TRUE(repetition_decided);
}

namespace {

// The normalised autocorrelation of an image's luminance at every shift within `r`
// (circular for a synthesized torus, over the overlap for a sample): the arrangement of its
// features — brick courses, tile grid, weave, grain — as one vector.
std::vector<double> autocorrelation(const OIIO::ImageBuf& image, int r, bool circular)
{
    const PlanarImage p = planes_of(image);
    const int w = p.width(), h = p.height();
    Plane l(w, h);
    for (const Plane& c : p.channels)
        for (size_t i = 0; i < l.size(); ++i)
            l.data()[i] += c.data()[i] / float(p.nchannels());
    double m = 0.0, v = 0.0;
    detail::plane_moments(l, m, v);
    std::vector<double> out;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            double s = 0.0;
            size_t n = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    int x2 = x + dx, y2 = y + dy;
                    if (circular) {
                        x2 = (x2 + w) % w;
                        y2 = (y2 + h) % h;
                    } else if (x2 < 0 || x2 >= w || y2 < 0 || y2 >= h) {
                        continue;
                    }
                    s += (l(x, y) - m) * (l(x2, y2) - m);
                    ++n;
                }
            out.push_back(s / double(n) / v);
        }
    return out;
}

double rms_difference(const std::vector<double>& a, const std::vector<double>& b)
{
    double s = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        s += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(s / double(a.size()));
}

} // namespace

// The quality bar: on structured samples the patch method keeps the sample's
// arrangement (its luminance autocorrelation within 24 pixels: the period of courses, the
// tile grid, the weave, the grain's direction) better than the neighbourhood method does.
class PatchQuality : public ::testing::TestWithParam<const char*> { };

TEST_P(PatchQuality, KeepsStructureBetterThanTheNeighbourhoodMethod)
{
    const OIIO::ImageBuf sample = linear_sample(GetParam());
    // Shifts up to the sample's feature size and a quarter more: its period (bricks,
    // tiles) or the size of its blobs, where the arrangement shows.
    const PlanarImage planes = planes_of(sample);
    const int side = 256;
    const int r = int(std::min(estimate_feature_scale(planes).size, planes.width() / 4.0) * 5 / 4);
    const std::vector<double> target = autocorrelation(sample, r, false);

    const OIIO::ImageBuf patch = patch_synthesize(sample, options(side, side));
    ASSERT_FALSE(patch.has_error()) << patch.geterror();
    NeighborhoodOptions nopt;
    nopt.width = nopt.height = side;
    nopt.seed = 5;
    const OIIO::ImageBuf neighborhood = neighborhood_synthesize(sample, nopt);
    ASSERT_FALSE(neighborhood.has_error()) << neighborhood.geterror();

    const double by_patch = rms_difference(autocorrelation(patch, r, true), target);
    const double by_neighborhood = rms_difference(autocorrelation(neighborhood, r, true), target);
    RecordProperty("patch", std::to_string(by_patch));
    RecordProperty("neighborhood", std::to_string(by_neighborhood));
    EXPECT_LT(by_patch, by_neighborhood) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Structured, PatchQuality,
    ::testing::Values(
        "bricks.png", "tiles_green.png", "weave_green.png", "wood_grain.png", "flowers.png"),
    [](const auto& info) {
        std::string name = info.param;
        return name.substr(0, name.find('.'));
    });
