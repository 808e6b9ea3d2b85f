/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    triSurfaceGeometry, the closed STL surface of the box from
    (0.375 0.375 0.25) to (0.625 0.75 0.875) (exact in the STL's single
    precision, surfaceCase.H), built alone; the same when the file's
    triangles face inwards (flipped): signed distance, negative inside, to
    the nearest face, edge or corner, with the nearest triangle's outward
    normal; inside as the distance says; bounded by the box.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include "surfaceCase.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;


TEST(triSurfaceGeometry, SignedDistanceAndOutwardNormalOfAClosedSurface)
{
    const surfaceCase surfaces;
    // Round-off of the search
    constexpr double tol = 1e-14;
    for (const word file : {"box.stl", "inverted.stl"})
    {
        const autoPtr<barrierGeometry> surface
        (
            readGeometry("type triSurface; file " + file + ";", surfaces.dir())
        );
        EXPECT_EQ
        (
            surface->bounds(),
            boundBox(point(0.375, 0.375, 0.25), point(0.625, 0.75, 0.875))
        ) << file;
        const struct { point x; scalar phi; vector n; } cases[] =
        {
            {point(0.4, 0.55, 0.55), -0.025, vector(-1, 0, 0)},
            {point(0.5, 0.7, 0.55), -0.05, vector(0, 1, 0)},
            {point(0.5, 0.55, 0.86), -0.015, vector(0, 0, 1)},
            {point(0.5, 0.55, 0.1), 0.15, vector(0, 0, -1)},
            {point(0.8, 0.55, 0.55), 0.175, vector(1, 0, 0)},
            {point(0.655, 0.55, 0.915), 0.05, vector::max}
        };
        boolList in;
        pointField points(6);
        for (label i = 0; i < 6; ++i)
        {
            points[i] = cases[i].x;
        }
        surface->inside(points, in);
        for (label i = 0; i < 6; ++i)
        {
            const auto& c = cases[i];
            vector normal;
            EXPECT_NEAR(distanceAt(*surface, c.x, normal), c.phi, tol)
                << file << " " << c.x;
            // By the edge: either face's normal
            if (c.n != vector::max)
            {
                EXPECT_LT(mag(normal - c.n), tol) << file << " " << c.x;
            }
            EXPECT_EQ(bool(in[i]), c.phi < 0) << file << " " << c.x;
        }
    }
}


// ************************************************************************* //
