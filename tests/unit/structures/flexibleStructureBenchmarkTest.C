/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    Cost of a flexible structure's step (label benchmark, run on purpose:
    cd build && ctest -L benchmark -R flexibleStructureBenchmark): a
    100 x 100 panel (20000 triangles) with ropes, triangle updates per
    second on the threads OpenMP gives.

\*---------------------------------------------------------------------------*/

#include "structureTestTools.H"
#include <gtest/gtest.h>
#include <chrono>

using namespace Foam;
using namespace Foam::structureTest;

TEST(flexibleStructureBenchmark, TriangleUpdatesPerSecond)
{
    flexibleStructure s
    (
        dictionaryOf
        (
            "type membrane;"
            "geometry { type panel; corners ((0 0 0) (10 0 0) (10 0 5)"
            "    (0 0 5)); resolution (100 100); }"
            "thickness 0.002; E 2e9; nu 0.3; rho 1000; prestress 1e5;"
            "ropes { top { from (0 0 5); to (-2 -2 6); EA 1e7;"
            "    linearDensity 5; segments 10; } }"
            "anchors { sides { type boundary; max (10.01 1 4.99);"
            "    min (-0.01 -1 -0.01); } }"
            "damping { massProportional 1; stiffnessProportional 1e-6; }"
        ),
        "."
    );
    for (label nodei = 0; nodei < s.nodes().size(); ++nodei)
    {
        s.nodes().fExtY[nodei] = 1;
    }
    const label nSteps = 500;
    const auto start = std::chrono::steady_clock::now();
    for (label stepi = 0; stepi < nSteps; ++stepi)
    {
        s.step(s.stableTimeStep());
    }
    const double seconds = std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
    const double rate = double(s.membrane().size())*nSteps/seconds;
    std::cout
        << "    " << s.membrane().size() << " triangles, " << nSteps
        << " steps in " << seconds << " s: " << rate
        << " triangle updates/s" << std::endl;
    EXPECT_GT(s.maxDeflection(), 0);
}
