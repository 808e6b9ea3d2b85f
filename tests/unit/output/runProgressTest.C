/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The progress lines of the solvers' logs: the share of the span to
    endTime, the wall time left extrapolated from the simulated time per
    wall time over the run's last half, at least its last minute (since the
    start in the first minute), a line every progressInterval seconds of a
    made-up wall clock, and the progressInterval of the controlDict,
    checked.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "runProgress.H"
#include "mpmTimeControls.H"
#include "testCase.H"
#include "OSspecific.H"
#include <fstream>
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- A case folder with only system/controlDict: startTime 2, endTime 12,
//  and the extra entries given
fileName controlCase(const word& name, const std::string& entries)
{
    const fileName dir = scratchDir(name);
    rmDir(dir);
    mkDir(dir/"system");
    std::ofstream((dir/"system"/"controlDict").c_str())
        << "FoamFile { version 2.0; format ascii; class dictionary;"
        << " object controlDict; }\n"
        << "application none;\nstartFrom startTime;\nstartTime 2;\n"
        << "stopAt endTime;\nendTime 12;\ndeltaT 0.1;\n"
        << "writeControl timeStep;\nwriteInterval 10;\n" << entries;
    return dir;
}


//- The number of lines due on a made-up wall clock ticking dt from 0 to
//  end [s]
label linesDue(runProgress& progress, const double dt, const double end)
{
    label lines = 0;
    for (double wall = 0; wall <= end; wall += dt)
    {
        lines += progress.due(wall);
    }
    return lines;
}

//- Simulated time at wall time wall [s]: 0.1 s per second of wall time
//  until wall time change [s], half that after (the work per step doubled)
struct slowingRun
{
    double change;

    double operator()(const double wall) const
    {
        return
            wall <= change
          ? 0.1*wall
          : 0.1*change + 0.05*(wall - change);
    }
};


//- A run from t = 0 with a progress line every 5 s to wall time end [s]
runProgress recorded(const slowingRun& t, const double end)
{
    runProgress progress(0, 5);
    for (double wall = 5; wall <= end; wall += 5)
    {
        progress.record(wall, t(wall));
    }
    return progress;
}


//- The time left to endTime 30 s at wall time wall [s] is that at the
//  rate since the line of wall time wall0 [s]
void expectRateSince
(
    const runProgress& progress,
    const slowingRun& t,
    const double wall,
    const double wall0
)
{
    EXPECT_DOUBLE_EQ
    (
        progress.timeLeft(t(wall), 30, wall),
        (wall - wall0)*(30 - t(wall))/(t(wall) - t(wall0))
    );
}

} // End anonymous namespace


TEST(runProgress, PercentIsTheShareOfTheSpanFromTheStartTime)
{
    EXPECT_DOUBLE_EQ(runProgress(0, 5).percent(12.3, 30), 41);
    // A restart from t = 10: its own span, 10 to 30
    EXPECT_DOUBLE_EQ(runProgress(10, 5).percent(15, 30), 25);
    EXPECT_DOUBLE_EQ(runProgress(10, 5).percent(30, 30), 100);
}


TEST(runProgress, TimeLeftExtrapolatesTheSimulatedTimePerWallTime)
{
    // 10 s simulated in 100 s of wall time: 20 s to go take 200 s
    EXPECT_DOUBLE_EQ(runProgress(0, 5).timeLeft(10, 30, 100), 200);
    // Restarted at 10: 5 s in 50 s, 5 s to go
    EXPECT_DOUBLE_EQ(runProgress(10, 5).timeLeft(15, 20, 50), 50);
    EXPECT_DOUBLE_EQ(runProgress(10, 5).timeLeft(20, 20, 50), 0);
}


TEST(runProgress, TimeLeftTakesTheRateOfTheRunsLastHalf)
{
    // The rate halves at 150 s. At 240 s (t = 19.5): the rate since the
    // line of 120 s, neither that of the last minute nor that since the
    // start
    const slowingRun t{150};
    const runProgress progress = recorded(t, 240);
    expectRateSince(progress, t, 240, 120);
    // At a later wall time than the last line's the window reaches on,
    // to the line of 125 s at 250 s
    expectRateSince(progress, t, 250, 125);
}


TEST(runProgress, TimeLeftTakesTheRateOfAtLeastTheLastMinute)
{
    // The rate halves at 45 s. At 100 s half the run is 50 s, so the rate
    // is that since the line of 40 s, minRateWindow before
    const slowingRun t{45};
    expectRateSince(recorded(t, 100), t, 100, 40);
}


TEST(runProgress, TimeLeftTakesTheRateSinceTheStartInTheFirstMinute)
{
    // Lines at 5, 10, ..., 55 s of a run restarted at t = 2: no line is a
    // minute old, so the rate is that since the start (wall 0, t = 2)
    runProgress progress(2, 5);
    for (double wall = 5; wall < 60; wall += 5)
    {
        progress.record(wall, 2 + 0.1*wall*wall/55);
    }
    const double t = 2 + 0.1*55;
    EXPECT_DOUBLE_EQ(progress.timeLeft(t, 12, 55), 55*(12 - t)/(t - 2));
}


TEST(runProgress, TimeLeftIsUnknownWithNoSimulatedTimeInTheWindow)
{
    // Stuck at t = 3 from 10 s on: at 100 s the window (from 40 s) has no
    // simulated time, though the run since the start has
    runProgress progress(0, 5);
    for (double wall = 5; wall <= 100; wall += 5)
    {
        progress.record(wall, std::min(0.3*wall, 3.0));
    }
    EXPECT_LT(progress.timeLeft(3, 12, 100), 0);
}


TEST(runProgress, ALineEveryStepKeepsAHundredthOfTheWindowApart)
{
    // progressInterval 0 on steps of 1 ms for 1000 s: the lines kept are
    // a hundredth of the window (5 s at the end) apart, so the rate is
    // still that of the run's last half, to within a hundredth
    const solverFpTraps traps;
    const slowingRun t{500};
    runProgress progress(0, 0);
    for (int step = 1; step <= 1000000; ++step)
    {
        progress.record(1e-3*step, t(1e-3*step));
    }
    // Lines from 500 s on, 5 s apart at most: about 130 of 1e6
    EXPECT_LE(progress.nKept(), 200);
    // Since the line of 500 s (t = 50): 25 s simulated in 500 s
    EXPECT_NEAR(progress.timeLeft(75, 100, 1000), 500, 5);
}


TEST(runProgress, TimeLeftIsUnknownBeforeThereIsARate)
{
    const runProgress progress(2, 5);
    EXPECT_LT(progress.timeLeft(2, 12, 10), 0);     // no simulated time
    EXPECT_LT(progress.timeLeft(3, 12, 0), 0);      // no wall time
    EXPECT_EQ
    (
        progress.line(2, 12, 0, 0),
        "Progress: t = 2 s (0 %), 0 particle-updates/s, unknown left"
    );
}


TEST(runProgress, TimeLeftOfAFarEndTimeIsCappedNotOverflowing)
{
    // The solvers trap overflow. 1e300 s to go after 1e-300 s in 1 s:
    // capped; half of 2e300 s in 1e-9 s and 1 s of 1e300 s in 1e-300 s:
    // large ratios whose products are ordinary
    const solverFpTraps traps;
    const runProgress progress(0, 5);
    EXPECT_EQ(progress.timeLeft(1e-300, 1e300, 1), GREAT);
    EXPECT_EQ(progress.timeLeft(1e300, 2e300, 1e-9), 1e-9);
    EXPECT_DOUBLE_EQ(progress.timeLeft(1, 1e300, 1e-300), 1);
    EXPECT_EQ(progress.percent(1e-300, 1e300), 0);
}


TEST(runProgress, DurationInHoursMinutesAndSeconds)
{
    EXPECT_EQ(runProgress::duration(0), "0 s");
    EXPECT_EQ(runProgress::duration(44.6), "45 s");
    EXPECT_EQ(runProgress::duration(59.6), "1 min 0 s");
    EXPECT_EQ(runProgress::duration(200), "3 min 20 s");
    EXPECT_EQ(runProgress::duration(7530), "2 h 5 min");
    EXPECT_EQ(runProgress::duration(-1), "unknown");
}


TEST(runProgress, LineGivesTimePercentRateAndTimeLeft)
{
    // 12.3 s of 30 in 100 s: 17.7 s to go take 100*17.7/12.3 = 143.9 s
    EXPECT_EQ
    (
        runProgress(0, 5).line(12.3, 30, 100, 2.1e6),
        "Progress: t = 12.3 s (41 %), 2.1e+06 particle-updates/s,"
        " 2 min 24 s left"
    );
}


TEST(runProgress, ALineEveryIntervalOfWallTime)
{
    // Steps of 0.25 s for a minute: lines at 5, 10, ..., 60 s
    runProgress every5(0, 5);
    EXPECT_EQ(linesDue(every5, 0.25, 60), 12);

    // Steps longer than the interval: a line every step, none skipped
    runProgress every1(0, 1);
    EXPECT_EQ(linesDue(every1, 2.5, 60), 24);

    // The interval counts from the last line, not from the first
    runProgress fromLast(0, 5);
    EXPECT_FALSE(fromLast.due(4.9));
    EXPECT_TRUE(fromLast.due(6));
    EXPECT_FALSE(fromLast.due(10.9));
    EXPECT_TRUE(fromLast.due(11));
}


TEST(runProgress, ZeroIntervalGivesALineEveryStep)
{
    runProgress progress(0, 0);
    EXPECT_EQ(linesDue(progress, 0.25, 10), 41);
}


TEST(runProgress, StartTimeAndIntervalFromTheControlDict)
{
    const fileName dir =
        controlCase("runProgressInterval", "progressInterval 2;\n");
    Time runTime(Time::controlDictName, dir.path(), fileName(dir.name()));
    runProgress progress(runTime);
    EXPECT_DOUBLE_EQ(progress.percent(7, 12), 50);
    EXPECT_FALSE(progress.due(1.9));
    EXPECT_TRUE(progress.due(2));

    const fileName defaultDir = controlCase("runProgressDefault", "");
    Time defaults
    (
        Time::controlDictName,
        defaultDir.path(),
        fileName(defaultDir.name())
    );
    runProgress progressDefault(defaults);
    EXPECT_FALSE(progressDefault.due(runProgress::intervalDefault - 0.1));
    EXPECT_TRUE(progressDefault.due(runProgress::intervalDefault));
}


TEST(runProgress, BadIntervalIsRefusedNamingTheKeywordAndTheAllowed)
{
    const std::string negative = foamIOErrorText([]
    {
        mpmTimeControls::checkControlDict
        (
            controlCase("runProgressNegative", "progressInterval -1;\n")
        );
    });
    EXPECT_NE(negative.find("progressInterval = -1 is invalid"),
        std::string::npos) << negative;
    EXPECT_NE(negative.find("allowed: finite progressInterval >= 0 [s]"),
        std::string::npos) << negative;
    EXPECT_NE(negative.find("controlDict"), std::string::npos) << negative;

    const std::string word = foamIOErrorText([]
    {
        mpmTimeControls::checkControlDict
        (
            controlCase("runProgressWord", "progressInterval often;\n")
        );
    });
    EXPECT_NE(word.find("often) is not a number"), std::string::npos)
        << word;
    EXPECT_NE(word.find("allowed: finite progressInterval >= 0 [s]"),
        std::string::npos) << word;

    EXPECT_EQ
    (
        foamIOErrorText([]
        {
            mpmTimeControls::checkControlDict
            (
                controlCase("runProgressZero", "progressInterval 0;\n")
            );
        }),
        ""
    );
}


// ************************************************************************* //
