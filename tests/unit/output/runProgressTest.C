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
    wall time so far, a line every progressInterval seconds of a made-up
    wall clock, and the progressInterval of the controlDict, checked.

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
