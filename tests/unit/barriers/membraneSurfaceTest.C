/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    membraneSurface, the flexible barrier's surface for the flow's contact:
    - the nearest point of a skewed triangle in space to 2,000 random
      points, in every Voronoi region (vertex, edge, face), is on the
      triangle (weights >= 0 summing to 1) and no point of a fine sampling
      of the triangle is nearer (to 1e-12 m), and no nearer than the
      sampling's spacing allows; phi is the distance along the normal and
      phi^2 + lateral^2 the squared distance;
    - of two triangles sharing an edge, a point above either gets that
      one, beside the rim a lateral distance;
    - an impulse J at a point (kick) changes the free nodes' momentum by
      exactly the free weights' share of J and puts the rest on the
      anchored node; settleKicks returns the kinetic energy it added,
      J.(v + dv/2) per node, to round-off.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "membraneSurface.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

//- A grid around the unit cube, every cell within reach of the triangles
gridGeometry cubeGrid()
{
    return uniformGrid(3, {-2, -2, -2}, {0.5, 0.5, 0.5}, {8, 8, 8});
}

//- Nodes from points, each of mass 1
structureNodes nodesAt(std::initializer_list<point> points)
{
    structureNodes n;
    for (const point& p : points)
    {
        const label i = n.append(p);
        n.mass[i] = 1;
    }
    return n;
}

double distance(const membraneSurface::nearPoint& q)
{
    return std::sqrt(q.phi*q.phi + q.lateral2);
}

} // End anonymous namespace


TEST(membraneSurface, NearestPointOfASkewedTriangleAgreesWithFineSampling)
{
    const point a(-0.6, -0.3, 0.1), b(0.7, -0.4, -0.2), c(0.1, 0.8, 0.4);
    structureNodes nodes(nodesAt({a, b, c}));
    const std::vector<label> tri({0, 1, 2});
    membraneSurface surface(nodes, tri);
    const gridGeometry g = cubeGrid();
    surface.update(g, 4, 0.5);

    // Fine sampling of the triangle
    const int n = 400;
    std::vector<point> samples;
    for (int i = 0; i <= n; ++i)
    {
        for (int j = 0; j <= n - i; ++j)
        {
            const double u = double(i)/n, v = double(j)/n;
            samples.push_back((1 - u - v)*a + u*b + v*c);
        }
    }
    const double spacing = max(max(mag(b - a), mag(c - b)), mag(a - c))/n;

    std::mt19937 rng(12);
    std::uniform_real_distribution<double> U(-1.4, 1.4);
    const vector nrm = normalised((b - a) ^ (c - a));
    for (int k = 0; k < 2000; ++k)
    {
        const double p[3] = {U(rng), U(rng), U(rng)};
        const point pt(p[0], p[1], p[2]);
        membraneSurface::nearPoint q;
        ASSERT_TRUE(surface.nearest(g, p, q));
        ASSERT_EQ(q.tri, 0);
        EXPECT_GE(min(min(q.w[0], q.w[1]), q.w[2]), 0);
        EXPECT_NEAR(q.w[0] + q.w[1] + q.w[2], 1, 1e-14);
        const point c0 = q.w[0]*a + q.w[1]*b + q.w[2]*c;
        EXPECT_NEAR(distance(q), mag(pt - c0), 1e-12);
        EXPECT_NEAR(q.phi, (pt - c0) & nrm, 1e-12);
        double best = GREAT;
        for (const point& s : samples)
        {
            best = min(best, mag(pt - s));
        }
        EXPECT_LE(distance(q), best + 1e-12);
        EXPECT_GE(distance(q), best - spacing);
    }
}


TEST(membraneSurface, TwoTrianglesGiveTheOneAboveAndBesideTheRimALateralDistance)
{
    // The unit square in z = 0, cut along its diagonal
    structureNodes nodes
    (
        nodesAt({point(0, 0, 0), point(1, 0, 0), point(1, 1, 0), point(0, 1, 0)})
    );
    const std::vector<label> tris({0, 1, 2, 0, 2, 3});
    membraneSurface surface(nodes, tris);
    const gridGeometry g = cubeGrid();
    surface.update(g, 4, 0.5);

    membraneSurface::nearPoint q;
    const double below[3] = {0.8, 0.2, -0.3};
    ASSERT_TRUE(surface.nearest(g, below, q));
    EXPECT_EQ(q.tri, 0);
    EXPECT_NEAR(q.phi, -0.3, 1e-15);
    EXPECT_NEAR(q.lateral2, 0, 1e-15);

    const double above[3] = {0.2, 0.8, 0.25};
    ASSERT_TRUE(surface.nearest(g, above, q));
    EXPECT_EQ(q.tri, 1);
    EXPECT_NEAR(q.phi, 0.25, 1e-15);

    // Beside the edge x = 1: 0.3 beyond it, 0.4 above
    const double beside[3] = {1.3, 0.5, 0.4};
    ASSERT_TRUE(surface.nearest(g, beside, q));
    EXPECT_NEAR(q.phi, 0.4, 1e-15);
    EXPECT_NEAR(q.lateral2, 0.09, 1e-15);
}


TEST(membraneSurface, KickConservesMomentumAndSettlesItsEnergy)
{
    structureNodes nodes
    (
        nodesAt({point(0, 0, 0), point(1, 0, 0), point(0, 1, 0)})
    );
    nodes.mass = {2.0, 3.0, 5.0};
    nodes.fixed[2] = 1;
    nodes.vx = {0.5, -1.0, 0.0};
    nodes.vz = {0.2, 0.1, 0.0};
    const std::vector<label> tri({0, 1, 2});
    membraneSurface surface(nodes, tri);
    const gridGeometry g = cubeGrid();
    surface.update(g, 4, 0.5);

    const double p[3] = {0.3, 0.2, 0.1};
    membraneSurface::nearPoint q;
    ASSERT_TRUE(surface.nearest(g, p, q));
    EXPECT_NEAR(q.w[0], 0.5, 1e-15);
    EXPECT_NEAR(q.w[1], 0.3, 1e-15);
    EXPECT_NEAR(q.w[2], 0.2, 1e-15);
    EXPECT_NEAR
    (
        surface.inverseMass(q), 0.5*0.5/2 + 0.3*0.3/3, 1e-15
    );

    auto momentum = [&](const std::vector<double>& v)
    {
        return nodes.mass[0]*v[0] + nodes.mass[1]*v[1];
    };
    auto kinetic = [&]()
    {
        double e = 0;
        for (label i = 0; i < 2; ++i)
        {
            e += 0.5*nodes.mass[i]
               *(sqr(nodes.vx[i]) + sqr(nodes.vy[i]) + sqr(nodes.vz[i]));
        }
        return e;
    };
    const double Px0 = momentum(nodes.vx), Pz0 = momentum(nodes.vz);
    const double E0 = kinetic();
    std::vector<double> anchored[3];
    for (int d = 0; d < 3; ++d)
    {
        anchored[d].assign(3, 0.0);
    }
    const double J[3] = {1.5, 0, -0.7};
    surface.kick(q, J, anchored);
    const double J2[3] = {-0.4, 0, 0.9};
    surface.kick(q, J2, anchored);

    // The free nodes take 0.8 of each impulse, the anchor 0.2
    EXPECT_NEAR(momentum(nodes.vx) - Px0, 0.8*(J[0] + J2[0]), 1e-14);
    EXPECT_NEAR(momentum(nodes.vz) - Pz0, 0.8*(J[2] + J2[2]), 1e-14);
    EXPECT_NEAR(anchored[0][2], 0.2*(J[0] + J2[0]), 1e-15);
    EXPECT_NEAR(anchored[2][2], 0.2*(J[2] + J2[2]), 1e-15);
    EXPECT_EQ(nodes.vx[2], 0);

    // Without a step in between, the work is the kinetic energy added
    EXPECT_NEAR(surface.settleKicks(), kinetic() - E0, 1e-14);
    EXPECT_EQ(surface.settleKicks(), 0);
}


// ************************************************************************* //
