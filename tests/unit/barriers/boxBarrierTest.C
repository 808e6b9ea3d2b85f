/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    boxBarrier, from (0.42 0.3 0.2) to (0.58 0.9 0.8), on a grid of
    0.1 x 0.15 x 0.2 m cells:
    - signed distance: inside, minus the distance to the nearest face, with
      that face's outward normal; outside a face, the distance to it; by an
      edge or a corner, the distance to it, normal from it to the point;
    - the particles' guard: a particle entering through a face is put back
      on that face, with its velocity into it removed (slip); and a wall
      thinner than the grid's nodes (no node inside, 4 cm between the node
      planes 0.5 and 0.6) holds by the guard alone.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

const std::string wall
(
    "type box; min (0.42 0.3 0.2); max (0.58 0.9 0.8); contact slip;"
);

//- Round-off of a few coordinates' differences
constexpr double tol = 1e-15;

} // End anonymous namespace


TEST(boxBarrier, SignedDistanceToTheNearestFaceEdgeOrCorner)
{
    barrierProbe probe(wall);
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
        EXPECT_NEAR(probe.distance(c.x, normal), c.phi, tol) << c.x;
        EXPECT_LT(mag(normal - c.n), 1e-13) << c.x;
    }
}


TEST(boxBarrier, EnteringParticleStopsOnTheFaceItCrossed)
{
    barrierProbe probe(wall);
    const point x0(0.38, 0.6, 0.5), x1(0.45, 0.62, 0.51);
    point x = x1;
    vector u(2, 0.5, 0.1), F;
    EXPECT_TRUE(probe.entry(x0, x, u, 0.01, 1e-3, F));
    // Bisection to 2^-30 of the move
    EXPECT_LT(mag(x - point(0.42, 0.62, 0.51)), 1e-9*mag(x1 - x0));
    EXPECT_GE(probe.distance(x), 0);
    EXPECT_EQ(u, vector(0, 0.5, 0.1));
    EXPECT_LT(mag(F - vector(0.01*2/1e-3, 0, 0)), 1e-12);
}


TEST(boxBarrier, WallThinnerThanTheNodesHoldsByTheGuard)
{
    barrierProbe probe
    (
        "type box; min (0.52 0.3 0.2); max (0.56 0.9 0.8); contact slip;"
    );
    // No node inside: no node contact, no pressure
    vector F;
    scalar p;
    const vector v(-1, 0, 0);
    for (const label i : {5, 6})
    {
        EXPECT_EQ(probe.contact(i, 4, 2, 1, v, 1e-3, F, p), v);
        EXPECT_EQ(p, 0);
    }
    const point x0(0.58, 0.6, 0.5), x1(0.54, 0.6, 0.5);
    point x = x1;
    vector u(-3, 0, 0.2);
    EXPECT_TRUE(probe.entry(x0, x, u, 0.01, 1e-3, F));
    EXPECT_LT(mag(x - point(0.56, 0.6, 0.5)), 1e-9*mag(x1 - x0));
    EXPECT_EQ(u, vector(0, 0, 0.2));
}


// ************************************************************************* //
