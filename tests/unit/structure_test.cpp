// SPDX-License-Identifier: Apache-2.0
// Every copying method's result keeps its sample's structure (structure_metric.h): its
// arrangement and seam measures within absolute bounds, which the two controls — the
// sample's pixels shuffled, and the sample pasted with every other row of copies shifted by
// half — both fail. A quality test a pixel shuffle would pass is no quality test.
#include <texsyn/choosy.h>
#include <texsyn/fill.h>
#include <texsyn/neighborhood.h>
#include <texsyn/patch.h>

#include <cstdio>
#include <functional>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "structure_metric.h"
#include "test_metrics.h"
#include "test_samples.h"

using namespace texsyn;
using namespace texsyn::test;

namespace {

// Every method passes its bounds on every sample below (see each test's printout); each
// control fails at least one of them on every sample.
constexpr int kRadius = 12;

// The bounds. Syntheses (patch, neighborhood, choosy, tileable) at 192x192 from 128x128:
// arrangement measured 0.012 .. 0.087 (shuffled controls 0.141 ..), seams 0.075 .. 0.34
// (half-shifted controls 0.49 ..). A fill's hole with 6 pixels around it: arrangement 0.068
// .. 0.083 (controls 0.107 ..), seams 0.117 .. 0.248 (controls whose arrangement passes:
// 0.29 ..).
struct Bounds {
    double arrangement, seams;
};
constexpr Bounds kSynthesis { 0.12, 0.4 }, kFill { 0.095, 0.26 };

struct Measure {
    double arrangement, seams;
    bool passes(const Bounds& b) const { return arrangement <= b.arrangement && seams <= b.seams; }
};

Measure measure(const OIIO::ImageBuf& result, const OIIO::ImageBuf& sample)
{
    return { arrangement_error(result, sample, kRadius), seam_error(result, sample) };
}

const char* const kSamples[] = { "bricks.png", "flowers.png", "leaves_autumn.png", "pebbles.png" };

// The sample, 128x128 (bundled samples are 128 or 256 on a side: the top-left corner).
OIIO::ImageBuf sample_of(const char* name)
{
    return linear_crop(name, 128, 128);
}

// A method's result for a sample, checked against the bounds, and the controls at the
// result's size checked to fail them.
void expect_structure(const char* method,
    const std::function<OIIO::ImageBuf(const OIIO::ImageBuf&)>& synthesize,
    const std::function<OIIO::ImageBuf(const OIIO::ImageBuf&, const OIIO::ImageBuf&)>& control = {},
    const Bounds& bounds = kSynthesis)
{
    for (const char* name : kSamples) {
        SCOPED_TRACE(std::string(method) + " on " + name);
        const OIIO::ImageBuf sample = sample_of(name);
        const OIIO::ImageBuf result = synthesize(sample);
        ASSERT_FALSE(result.has_error()) << result.geterror();
        const int w = result.spec().width, h = result.spec().height;
        const Measure ours = measure(result, sample);
        const Measure shuffle = measure(
            control ? control(sample, shuffled(sample, w, h)) : shuffled(sample, w, h), sample);
        const Measure pasted = measure(control ? control(sample, half_shifted_tiling(sample, w, h))
                                               : half_shifted_tiling(sample, w, h),
            sample);
        const std::string key = std::string("structure.") + method + "." + name;
        for (const auto& [what, m] :
            { std::pair { "result", ours }, { "shuffled", shuffle }, { "shifted", pasted } }) {
            doc_number(key + "." + what + ".arrangement", m.arrangement, 3);
            doc_number(key + "." + what + ".seams", m.seams, 2);
        }
        std::printf("%-12s %-18s result %.3f %.3f | shuffled %.3f %.3f | half-shifted %.3f %.3f\n",
            method, name, ours.arrangement, ours.seams, shuffle.arrangement, shuffle.seams,
            pasted.arrangement, pasted.seams);
        EXPECT_TRUE(ours.passes(bounds)) << ours.arrangement << ", " << ours.seams;
        EXPECT_FALSE(shuffle.passes(bounds)) << shuffle.arrangement << ", " << shuffle.seams;
        EXPECT_FALSE(pasted.passes(bounds)) << pasted.arrangement << ", " << pasted.seams;
    }
}

// The fill's case: a 48x48 hole in the middle of the sample.
OIIO::ImageBuf hole_mask()
{
    OIIO::ImageBuf mask(OIIO::ImageSpec(128, 128, 1, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::fill(mask, { 1.0f }, OIIO::ROI(40, 88, 40, 88));
    return mask;
}

// The region measured of a fill: the hole and 6 pixels around it.
const OIIO::ROI kHoleRegion(34, 94, 34, 94);

// The region of `sample` with the fill's hole replaced by `content`'s pixels there,
// `content` first shifted by half its size (the half-shifted control's hole holds another
// part of the plate).
OIIO::ImageBuf pasted_into_hole(const OIIO::ImageBuf& sample, const OIIO::ImageBuf& content)
{
    OIIO::ImageBuf out = sample;
    const OIIO::ImageBuf moved = OIIO::ImageBufAlgo::circular_shift(content, 64, 64);
    OIIO::ImageBufAlgo::paste(
        out, 40, 40, 0, 0, OIIO::ImageBufAlgo::cut(moved, OIIO::ROI(40, 88, 40, 88)));
    return OIIO::ImageBufAlgo::cut(out, kHoleRegion);
}

} // namespace

TEST(Structure, Patch)
{
    expect_structure("patch", [](const OIIO::ImageBuf& s) {
        PatchOptions opt;
        opt.width = opt.height = 192;
        opt.seed = 1;
        return patch_synthesize(s, opt);
    });
}

TEST(Structure, Neighborhood)
{
    expect_structure("neighborhood", [](const OIIO::ImageBuf& s) {
        NeighborhoodOptions opt;
        opt.width = opt.height = 192;
        opt.seed = 1;
        return neighborhood_synthesize(s, opt);
    });
}

TEST(Structure, Choosy)
{
    expect_structure("choosy", [](const OIIO::ImageBuf& s) {
        ChoosyOptions opt;
        opt.width = opt.height = 192;
        opt.seed = 1;
        return choosy_synthesize(s, opt);
    });
}

// The filled plate against the plate; the controls fill the hole with shuffled pixels, or
// with the plate's own content shifted by half (whole features, seams at the outline).
TEST(Structure, Fill)
{
    expect_structure(
        "fill",
        [](const OIIO::ImageBuf& s) {
            FillOptions opt;
            opt.seed = 1;
            return OIIO::ImageBufAlgo::cut(texture_fill(s, hole_mask(), opt), kHoleRegion);
        },
        [](const OIIO::ImageBuf& s, const OIIO::ImageBuf& control) {
            return pasted_into_hole(s, control);
        },
        kFill);
}

// The tile pasted 2 x 2 (its seams inside the picture) against the sample; the controls
// are the shuffled sample and the sample itself pasted 2 x 2 with the half shift, wrap
// seams and all.
TEST(Structure, Tileable)
{
    expect_structure(
        "tileable",
        [](const OIIO::ImageBuf& s) {
            TileableOptions opt;
            opt.options.seed = 1;
            return tiled_twice(make_tileable(s, opt));
        },
        [](const OIIO::ImageBuf&, const OIIO::ImageBuf& control) { return control; });
}
