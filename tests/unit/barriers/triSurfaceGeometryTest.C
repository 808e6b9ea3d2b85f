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
    normal; inside as the distance says; bounded by the box. Queried
    from four threads at once right after it is built (its search is
    built at construction): every point's distance is the box's own.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include "surfaceCase.H"
#include <gtest/gtest.h>
#include <omp.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

//- Signed distance to the box of surfaceCase.H (negative inside)
scalar boxDistance(const point& x)
{
    const point c(0.5, 0.5625, 0.5625);
    const vector h(0.125, 0.1875, 0.3125);
    vector q;
    for (direction d = 0; d < 3; ++d)
    {
        q[d] = mag(x[d] - c[d]) - h[d];
    }
    return mag(max(q, vector(Zero))) + min(cmptMax(q), scalar(0));
}

} // End anonymous namespace


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


TEST(triSurfaceGeometry, QueriesFromSeveralThreadsAtOnceAreTheBoxDistance)
{
    const surfaceCase surfaces;
    const autoPtr<barrierGeometry> surface
    (
        readGeometry("type triSurface; file box.stl;", surfaces.dir())
    );
    ASSERT_TRUE(surface->threadSafeDistance());

    // Points in and around the box, a chunk per thread; the first queries
    // of the geometry are these
    constexpr label nChunks = 8, chunk = 2000;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    List<pointField> points(nChunks, pointField(chunk));
    for (pointField& pts : points)
    {
        for (point& x : pts)
        {
            x = point(0.3 + 0.4*u(rng), 0.3 + 0.5*u(rng), 0.15 + 0.8*u(rng));
        }
    }
    List<scalarField> phi(nChunks);
    List<vectorField> normal(nChunks);
    List<boolList> in(nChunks);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(4);
    #pragma omp parallel for schedule(dynamic, 1)
    for (label c = 0; c < nChunks; ++c)
    {
        surface->distance(points[c], phi[c], normal[c]);
        surface->inside(points[c], in[c]);
    }
    omp_set_num_threads(threads);

    label nInside = 0;
    for (label c = 0; c < nChunks; ++c)
    {
        forAll(points[c], i)
        {
            const scalar exact = boxDistance(points[c][i]);
            EXPECT_NEAR(phi[c][i], exact, 1e-14) << points[c][i];
            EXPECT_NEAR(mag(normal[c][i]), 1, 1e-14) << points[c][i];
            if (mag(exact) > 1e-12)
            {
                EXPECT_EQ(bool(in[c][i]), exact < 0) << points[c][i];
            }
            nInside += in[c][i];
        }
    }
    // (A third of the points' box is inside the barrier)
    EXPECT_GT(nInside, nChunks*chunk/5);
}


// ************************************************************************* //
