/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    terrainBarrier, from an expression topography, on a grid of
    0.1 x 0.15 x 0.2 m cells:
    - on a plane Z = 0.3 + 0.2 x - 0.1 y the signed distance
      (z - Z)/sqrt(1 + |grad Z|^2) and the normal (-Zx, -Zy, 1)/sqrt(...)
      to round-off; on a parabola Z = 0.4 + x^2 the normal
      (-2 x, 0, 1)/sqrt(1 + 4 x^2) and the distance's first-order form
      (z - Z)/sqrt(1 + 4 x^2);
    - the particles' guard acts half a cell (of the smallest cell size)
      below the surface: a particle that dips less deep is left to the node
      contact, one that goes deeper is put back at that depth, along the
      normal, and loses its velocity into the terrain.

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
      + Z + "\"; } contact slip;";
}

const double norm = std::sqrt(1 + 0.04 + 0.01);
const vector n = vector(-0.2, 0.1, 1)/norm;

} // End anonymous namespace


TEST(terrainBarrier, SignedDistanceAndNormalOfPlaneAndCurvedTerrain)
{
    // Round-off (of a central difference over 1 cm: 1e-15 m/1e-2 m)
    constexpr double tol = 1e-12;
    barrierProbe plane(terrain("0.3 + 0.2*x - 0.1*y"));
    for (const point& x :
        {point(0.1, 0.2, 0.5), point(0.7, 1.1, 0.2), point(0.55, 0.3, 0.35)})
    {
        vector normal;
        const scalar Z = 0.3 + 0.2*x.x() - 0.1*x.y();
        EXPECT_NEAR(plane.distance(x, normal), (x.z() - Z)/norm, tol) << x;
        EXPECT_LT(mag(normal - n), tol) << x;
    }

    barrierProbe parabola(terrain("0.4 + x*x"));
    for (const point& x : {point(0.1, 0.2, 0.5), point(0.7, 1.1, 0.6)})
    {
        vector normal;
        const scalar r = std::sqrt(1 + 4*sqr(x.x()));
        EXPECT_NEAR
        (
            parabola.distance(x, normal),
            (x.z() - 0.4 - sqr(x.x()))/r,
            tol
        ) << x;
        EXPECT_LT(mag(normal - vector(-2*x.x(), 0, 1)/r), tol) << x;
    }
}


TEST(terrainBarrier, GuardStopsParticlesHalfACellBelowTheSurface)
{
    barrierProbe probe(terrain("0.3 + 0.2*x - 0.1*y"));
    const scalar depth = 0.5*probe.grid().hMin();
    const point s(0.5, 0.6, 0.3 + 0.2*0.5 - 0.1*0.6);
    const vector t(0.1, 0, 0.02);
    const vector u = -n + vector(0.5, 0, 0.1);

    // Half as deep: not stopped
    point x = s - 0.5*depth*n + t;
    vector v = u, F;
    EXPECT_FALSE(probe.entry(s + 0.01*n, x, v, 0.01, 1e-3, F));
    EXPECT_EQ(v, u);

    // Twice as deep: back at the guard's depth, along n
    const point x0 = s + 0.01*n, x1 = s - 2*depth*n + t;
    x = x1;
    EXPECT_TRUE(probe.entry(x0, x, v, 0.01, 1e-3, F));
    // Bisection to 2^-30 of the move, and the terrain's round-off
    const scalar tol = 1e-9*mag(x1 - x0) + 1e-12;
    EXPECT_LT(mag(x - (x1 + depth*n)), tol);
    EXPECT_NEAR(probe.distance(x), -depth, tol);
    EXPECT_LT(mag(v - contactVelocity(u, n, "slip")), 1e-12);
}


// ************************************************************************* //
