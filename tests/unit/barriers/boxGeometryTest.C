/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    boxGeometry, from (0.42 0.3 0.2) to (0.58 0.9 0.8), built alone (as
    the run-out's hand-off builds it), signed distance: inside, minus the
    distance to the nearest face, with that face's outward normal; outside
    a face, the distance to it; by an edge or a corner, the distance to it,
    normal from it to the point. The box bounds itself; its distance is
    exact.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

const std::string wall("type box; min (0.42 0.3 0.2); max (0.58 0.9 0.8);");

//- Round-off of a few coordinates' differences
constexpr double tol = 1e-15;

} // End anonymous namespace


TEST(boxGeometry, SignedDistanceToTheNearestFaceEdgeOrCorner)
{
    const autoPtr<barrierGeometry> box(readGeometry(wall));
    EXPECT_EQ
    (
        box->bounds(),
        boundBox(point(0.42, 0.3, 0.2), point(0.58, 0.9, 0.8))
    );
    EXPECT_TRUE(box->exactDistance());
    const struct { point x; scalar phi; vector n; } cases[] =
    {
        // Inside: the nearest face
        {point(0.45, 0.6, 0.5), -0.03, vector(-1, 0, 0)},
        {point(0.5, 0.35, 0.5), -0.05, vector(0, -1, 0)},
        {point(0.5, 0.6, 0.78), -0.02, vector(0, 0, 1)},
        // Outside a face
        {point(0.7, 0.6, 0.5), 0.12, vector(1, 0, 0)},
        {point(0.5, 0.6, 0.1), 0.1, vector(0, 0, -1)},
        // By the edge x = 0.58, z = 0.8; by the corner (0.42 0.3 0.2)
        {point(0.61, 0.5, 0.84), 0.05, vector(0.6, 0, 0.8)},
        {point(0.40, 0.28, 0.19), 0.03, vector(-2, -2, -1)/3}
    };
    for (const auto& c : cases)
    {
        vector normal;
        EXPECT_NEAR(distanceAt(*box, c.x, normal), c.phi, tol) << c.x;
        EXPECT_LT(mag(normal - c.n), 1e-13) << c.x;
    }
}


// ************************************************************************* //
