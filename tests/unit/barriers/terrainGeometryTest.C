/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    terrainGeometry, from an expression topography:
    - on a plane Z = 0.3 + 0.2 x - 0.1 y the signed distance
      (z - Z)/sqrt(1 + |grad Z|^2) and the normal (-Zx, -Zy, 1)/sqrt(...)
      to round-off; on a parabola Z = 0.4 + x^2 the normal
      (-2 x, 0, 1)/sqrt(1 + 4 x^2) and the distance's first-order form
      (z - Z)/sqrt(1 + 4 x^2);
    - deeperThan: a point is deeper than d where that distance is below -d
      (the vertical depth screens first); the guard acts half a cell deep.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

std::string terrain(const std::string& Z)
{
    return "type terrain; topography expression; expressionCoeffs { Z \""
      + Z + "\"; }";
}

const double norm = std::sqrt(1 + 0.04 + 0.01);
const vector n = vector(-0.2, 0.1, 1)/norm;

} // End anonymous namespace


TEST(terrainGeometry, SignedDistanceAndNormalOfPlaneAndCurvedTerrain)
{
    // Round-off (of a central difference over 1 cm: 1e-15 m/1e-2 m)
    constexpr double tol = 1e-12;
    const autoPtr<barrierGeometry> plane
    (
        readGeometry(terrain("0.3 + 0.2*x - 0.1*y"))
    );
    for (const point& x :
        {point(0.1, 0.2, 0.5), point(0.7, 1.1, 0.2), point(0.55, 0.3, 0.35)})
    {
        vector normal;
        const scalar Z = 0.3 + 0.2*x.x() - 0.1*x.y();
        EXPECT_NEAR(distanceAt(*plane, x, normal), (x.z() - Z)/norm, tol)
            << x;
        EXPECT_LT(mag(normal - n), tol) << x;
    }

    const autoPtr<barrierGeometry> parabola
    (
        readGeometry(terrain("0.4 + x*x"))
    );
    for (const point& x : {point(0.1, 0.2, 0.5), point(0.7, 1.1, 0.6)})
    {
        vector normal;
        const scalar r = std::sqrt(1 + 4*sqr(x.x()));
        EXPECT_NEAR
        (
            distanceAt(*parabola, x, normal),
            (x.z() - 0.4 - sqr(x.x()))/r,
            tol
        ) << x;
        EXPECT_LT(mag(normal - vector(-2*x.x(), 0, 1)/r), tol) << x;
    }
}


TEST(terrainGeometry, DeeperThanByTheDistanceAlongTheNormal)
{
    const autoPtr<barrierGeometry> plane
    (
        readGeometry(terrain("0.3 + 0.2*x - 0.1*y"))
    );
    EXPECT_EQ(plane->guardDepthCells(), 0.5);
    const scalar depth = 0.05;
    const point s(0.5, 0.6, 0.3 + 0.2*0.5 - 0.1*0.6);
    // Along the normal: 0.9 and 1.1 times the depth; vertically 1.01 times
    // the depth is only 1.01/norm = 0.986 of it along the normal
    const pointField points
    ({
        s - 0.9*depth*n, s - 1.1*depth*n, s - vector(0, 0, 1.01*depth),
        s + 0.01*n
    });
    const bool expected[] = {false, true, false, false};
    boolList in;
    plane->deeperThan(points, depth, in);
    forAll(points, i)
    {
        EXPECT_EQ(bool(in[i]), expected[i]) << points[i];
    }
}


// ************************************************************************* //
