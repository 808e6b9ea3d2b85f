/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    fpTrapsHeld: under the solvers' floating-point traps, operations inside
    the scope give NaN and inf instead of SIGFPE, and on leaving it the
    traps and flags are those of before (nothing raised inside leaks out);
    scopes nest.

\*---------------------------------------------------------------------------*/

#include "fpTrapsHeld.H"
#include "testCase.H"
#include <gtest/gtest.h>
#include <cfenv>
#include <cmath>

using namespace Foam;

namespace
{

//- The traps FOAM_SIGFPE enables
constexpr int solverTraps = FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW;

} // End anonymous namespace


TEST(fpTrapsHeld, InvalidOperationsGiveNaNAndInfAndTheTrapsComeBack)
{
    const solverFpTraps traps;
    ASSERT_EQ(fegetexcept(), solverTraps);

    volatile double zero = 0;
    volatile double big = 1e300;
    double quotient, root, product;
    {
        fpTrapsHeld masked;
        EXPECT_EQ(fegetexcept(), 0);
        quotient = 1/zero;
        root = std::sqrt(-1 - zero);
        product = big*big;
        EXPECT_NE(fetestexcept(FE_DIVBYZERO | FE_INVALID), 0);

        {
            fpTrapsHeld inner;
            EXPECT_EQ(fetestexcept(FE_ALL_EXCEPT), 0);
        }
        EXPECT_EQ(fegetexcept(), 0);
        EXPECT_NE(fetestexcept(FE_DIVBYZERO), 0);
    }
    EXPECT_TRUE(std::isinf(quotient));
    EXPECT_TRUE(std::isnan(root));
    EXPECT_TRUE(std::isinf(product));

    // The traps are back and nothing raised inside is left flagged
    EXPECT_EQ(fegetexcept(), solverTraps);
    EXPECT_EQ(fetestexcept(FE_ALL_EXCEPT), 0);
}


TEST(fpTrapsHeld, WithoutTrapsNothingChanges)
{
    ASSERT_EQ(fegetexcept(), 0);
    feclearexcept(FE_ALL_EXCEPT);
    feraiseexcept(FE_INEXACT);
    volatile double zero = 0;
    {
        fpTrapsHeld masked;
        EXPECT_TRUE(std::isinf(1/zero));
    }
    EXPECT_EQ(fegetexcept(), 0);
    EXPECT_EQ(fetestexcept(FE_ALL_EXCEPT), FE_INEXACT);
}


// ************************************************************************* //
