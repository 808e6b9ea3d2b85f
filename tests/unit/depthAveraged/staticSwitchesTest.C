/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    staticSwitches: each combination of the run-time switches calls the
    instantiation of its own compile-time constants, in the order given.

\*---------------------------------------------------------------------------*/

#include "staticSwitches.H"
#include <gtest/gtest.h>

using namespace Foam;


TEST(staticSwitches, EveryCombinationCallsItsOwnInstantiation)
{
    for (int bits = 0; bits < 8; ++bits)
    {
        int called = -1;
        staticSwitches
        (
            [&](auto a, auto b, auto c)
            {
                // Constants: usable as template arguments
                constexpr int code = 4*a() + 2*b() + c();
                called = std::integral_constant<int, code>::value;
            },
            bool(bits & 4), bool(bits & 2), bool(bits & 1)
        );
        EXPECT_EQ(called, bits);
    }
}


// ************************************************************************* //
