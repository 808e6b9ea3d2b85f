/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    planeGeometry, an inclined half-space (normal (1 -2 2), of any length),
    built alone: signed distance (x - o).n and normal n, n the unit normal;
    inside where the distance is negative; unbounded.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

const point o(0.43, 0.61, 0.55);
const vector n = vector(1, -2, 2)/3;

const std::string inclinedPlane
(
    "type plane; point (0.43 0.61 0.55); normal (1 -2 2);"
);

} // End anonymous namespace


TEST(planeGeometry, SignedDistanceAlongTheUnitNormal)
{
    const autoPtr<barrierGeometry> plane(readGeometry(inclinedPlane));
    constexpr double tol = 1e-15; // round-off of a dot product
    const pointField points
    ({
        point(0, 0, 0), point(0.9, 0.1, 1.1), point(0.43, 0.61, 0.55),
        o - 0.01*n
    });
    boolList in;
    plane->inside(points, in);
    forAll(points, i)
    {
        const point& x = points[i];
        vector normal;
        EXPECT_NEAR(distanceAt(*plane, x, normal), (x - o) & n, tol) << x;
        EXPECT_LT(mag(normal - n), tol) << x;
        EXPECT_EQ(bool(in[i]), ((x - o) & n) < 0) << x;
    }
    EXPECT_EQ(plane->bounds(), boundBox::greatBox);
}


// ************************************************************************* //
