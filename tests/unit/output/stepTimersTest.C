/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The particle-updates per second of the step timers: the particles
    counted over the steps, over a given wall time.

\*---------------------------------------------------------------------------*/

#include "stepTimers.H"
#include <gtest/gtest.h>

using namespace Foam;

TEST(stepTimers, UpdatesPerSecondAreTheParticlesOfAllStepsOverTheWallTime)
{
    stepTimers timers;
    timers.countStep(1000);
    timers.countStep(3000);
    EXPECT_DOUBLE_EQ(timers.updatesPerSecond(2), 2000);
    // No wall time yet: no rate, rather than a division by zero
    EXPECT_EQ(timers.updatesPerSecond(0), 0);
}


// ************************************************************************* //
