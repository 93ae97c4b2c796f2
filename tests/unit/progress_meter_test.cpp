// SPDX-License-Identifier: Apache-2.0
// The tool's progress lines (oiiotool-ext/progress_meter.h): modes, the interval, ETA and
// duration formatting, driven by a fake clock.
#include "progress_meter.h"

#include <gtest/gtest.h>

using namespace texsyn::cli;

TEST(ProgressMeter, ModeFollowsTheTerminalAndVerbose)
{
    EXPECT_EQ(progress_mode(false, true), ProgressMode::Live);
    EXPECT_EQ(progress_mode(true, true), ProgressMode::Live);
    EXPECT_EQ(progress_mode(true, false), ProgressMode::Lines);
    EXPECT_EQ(progress_mode(false, false), ProgressMode::Off);
}

TEST(ProgressMeter, IntervalComesFromTheEnvironment)
{
    double s = 0;
    std::string error;
    ASSERT_TRUE(progress_interval(nullptr, s, error));
    EXPECT_EQ(s, 5.0);
    ASSERT_TRUE(progress_interval("0.25", s, error));
    EXPECT_EQ(s, 0.25);
    for (const char* bad : { "", "soon", "0", "-1", "5s", "7200" }) {
        EXPECT_FALSE(progress_interval(bad, s, error)) << bad;
        EXPECT_EQ(error,
            std::string("TEXSYN_PROGRESS_INTERVAL=") + bad
                + " : expected seconds between progress lines, 0.01..3600");
    }
}

TEST(ProgressMeter, DurationsAreMinutesOrHours)
{
    EXPECT_EQ(format_duration(0), "0:00");
    EXPECT_EQ(format_duration(12.9), "0:12");
    EXPECT_EQ(format_duration(61), "1:01");
    EXPECT_EQ(format_duration(3599.5), "59:59");
    EXPECT_EQ(format_duration(3600 * 26 + 62), "26:01:02");
    EXPECT_EQ(format_duration(-3), "0:00");
}

// Lines mode: nothing at the start, a line once `interval` seconds have passed since the
// last one, the 100% line once, and finish() adds it only if it is missing.
TEST(ProgressMeter, LinesComeEveryIntervalAndAtTheEnd)
{
    ProgressMeter m("--pyramid", ProgressMode::Lines, 5.0);
    EXPECT_EQ(m.start(), "");
    EXPECT_EQ(m.update(0.1f, 1.0), "");
    EXPECT_EQ(m.update(0.2f, 4.9), "");
    // 42% after 12 s: 12 x 58 / 42 = 16.6 s left.
    EXPECT_EQ(m.update(0.42f, 12.0), "texsyn: --pyramid  42% elapsed 0:12 eta 0:16\n");
    EXPECT_EQ(m.update(0.5f, 16.9), "");
    EXPECT_EQ(m.update(0.6f, 17.0), "texsyn: --pyramid  60% elapsed 0:17 eta 0:11\n");
    EXPECT_EQ(m.update(1.0f, 18.0), "texsyn: --pyramid 100% elapsed 0:18 eta 0:00\n");
    EXPECT_EQ(m.update(1.0f, 30.0), "");
    EXPECT_EQ(m.finish(true, 30.5), "");

    ProgressMeter quick("--cascade", ProgressMode::Lines, 5.0);
    EXPECT_EQ(quick.update(0.99f, 0.5), "");
    EXPECT_EQ(quick.finish(true, 0.6), "texsyn: --cascade 100% elapsed 0:00 eta 0:00\n");
    ProgressMeter failed("--cascade", ProgressMode::Lines, 5.0);
    EXPECT_EQ(failed.finish(false, 0.6), "");
}

// Live mode: a line at once (0%, no estimate yet), rewritten at every update, blanked to
// the longest so far, and ended by a newline.
TEST(ProgressMeter, LiveLineStartsAtOnceAndShowsTheEstimate)
{
    ProgressMeter m("--choosy", ProgressMode::Live, 5.0);
    EXPECT_EQ(m.start(), "\rtexsyn: --choosy   0% elapsed 0:00 eta -:--");
    EXPECT_EQ(m.update(0.01f, 40.0), "\rtexsyn: --choosy   1% elapsed 0:40 eta 1:06:00");
    EXPECT_EQ(m.update(0.5f, 60.0), "\rtexsyn: --choosy  50% elapsed 1:00 eta 1:00   ");
    EXPECT_EQ(m.finish(true, 120.0), "\rtexsyn: --choosy 100% elapsed 2:00 eta 0:00   \n");
    ProgressMeter failed("--choosy", ProgressMode::Live, 5.0);
    EXPECT_EQ(failed.finish(false, 1.0), "\n");
}
