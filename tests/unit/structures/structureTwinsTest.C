/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    A membrane strip across a plane slice (y = 0 to 0.1): its nodes in
    twins on the two faces.
    - pairAcross pairs each node with the one at the same x and z on the
      other face (within tol), puts the twin at its node's x and z, and
      makes the twins' masses equal with their sum kept;
    - tieTwins gives twins the mean of their forces in x and z and none
      across (y), so that they move together;
    - membraneSurface on the strip: an impulse at a point goes to the twin
      pairs of its triangle in equal halves (both twins change velocity
      alike), the momentum taken is the impulse to round-off, and the
      point's inverse mass is the sum over the pairs of w^2 over the pair's
      mass.

\*---------------------------------------------------------------------------*/

#include "structureTestTools.H"
#include "membraneSurface.H"
#include "uniformGrid.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- The strip x = 0 from z = 0 to 1: nodes 0, 1 at z = 0 on the faces
//  y = 0 and 0.1 (node 1 a little off in x), nodes 2, 3 at z = 1
structureNodes strip()
{
    structureNodes n;
    const point p[4] =
    {
        point(0, 0, 0), point(2e-9, 0.1, 0), point(0, 0, 1),
        point(0, 0.1, 1)
    };
    const double m[4] = {1, 3, 2, 2};
    for (int k = 0; k < 4; ++k)
    {
        n.mass[n.append(p[k])] = m[k];
    }
    return n;
}

} // End anonymous namespace


TEST(structureTwins, PairAcrossPairsAlignsAndSharesTheMass)
{
    structureNodes n(strip());
    n.pairAcross(0, 0.1, 1e-6, dictionary());
    EXPECT_EQ(n.twin, std::vector<label>({1, 0, 3, 2}));
    EXPECT_EQ(n.x[1], n.x[0]);
    EXPECT_EQ(n.x0[1], n.x0[0]);
    EXPECT_EQ(n.mass[0], 2);
    EXPECT_EQ(n.mass[1], 2);
    EXPECT_EQ(n.mass[2] + n.mass[3], 4);
}


TEST(structureTwins, TieTwinsSharesForcesAndNothingActsAcross)
{
    structureNodes n(strip());
    n.pairAcross(0, 0.1, 1e-6, dictionary());
    n.fx = {1, 3, -2, 4};
    n.fy = {5, -5, 1, 1};
    n.fz = {0.5, 1.5, 0, 0};
    n.fExtX = {0, 2, 0, 0};
    n.fExtY = {1, 1, 1, 1};
    n.fExtZ = {-1, -3, 7, 7};
    n.tieTwins();
    EXPECT_EQ(n.fx, std::vector<double>({2, 2, 1, 1}));
    EXPECT_EQ(n.fz, std::vector<double>({1, 1, 0, 0}));
    EXPECT_EQ(n.fExtX, std::vector<double>({1, 1, 0, 0}));
    EXPECT_EQ(n.fExtZ, std::vector<double>({-2, -2, 7, 7}));
    EXPECT_EQ(n.fy, std::vector<double>(4, 0.0));
    EXPECT_EQ(n.fExtY, std::vector<double>(4, 0.0));
}


TEST(structureTwins, ImpulseOnTheStripMovesTwinsAlike)
{
    structureNodes n(strip());
    n.pairAcross(0, 0.1, 1e-6, dictionary());
    n.mass = {2, 2, 1, 1};
    const std::vector<label> triangles({0, 1, 3, 0, 3, 2});
    membraneSurface surface(n, triangles);
    const gridGeometry g =
        uniformGrid(3, {-0.5, 0, -0.5}, {0.1, 0.1, 0.1}, {10, 1, 20});
    surface.update(g, 0.2, 0.05);

    // A point of the face y = 0, a quarter of the way up
    const double x[3] = {-0.05, 0, 0.25};
    membraneSurface::nearPoint q;
    ASSERT_TRUE(surface.nearest(g, x, q));
    EXPECT_NEAR(std::abs(q.phi), 0.05, 1e-15);
    // Pairs (0, 1) and (2, 3) take 3/4 and 1/4: 1/M = (3/4)^2/4 + (1/4)^2/2
    EXPECT_NEAR(surface.inverseMass(q), 0.5625/4 + 0.0625/2, 1e-15);

    std::vector<double> anchored[3];
    for (int d = 0; d < 3; ++d)
    {
        anchored[d].assign(4, 0.0);
    }
    const double J[3] = {2, 0, -1};
    surface.kick(q, J, anchored);
    EXPECT_EQ(n.vx[0], n.vx[1]);
    EXPECT_EQ(n.vx[2], n.vx[3]);
    EXPECT_EQ(n.vz[0], n.vz[1]);
    EXPECT_NEAR(n.vx[0], 0.75*2/4, 1e-15);
    EXPECT_NEAR(n.vx[2], 0.25*2/2, 1e-15);
    double px = 0, pz = 0;
    for (label i = 0; i < 4; ++i)
    {
        px += n.mass[i]*n.vx[i];
        pz += n.mass[i]*n.vz[i];
    }
    EXPECT_NEAR(px, J[0], 1e-15);
    EXPECT_NEAR(pz, J[2], 1e-15);
}


// ************************************************************************* //
