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
    built at construction), the box and two cubes apart (between which
    points are often nearest a corner): what one thread gives, bit for bit,
    and the shape's distance.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include "surfaceCase.H"
#include "threadCount.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

//- Signed distance to the box from lo to hi (negative inside)
scalar boxDistance(const point& x, const point& lo, const point& hi)
{
    vector q;
    for (direction d = 0; d < 3; ++d)
    {
        q[d] = mag(x[d] - 0.5*(lo[d] + hi[d])) - 0.5*(hi[d] - lo[d]);
    }
    return mag(max(q, vector(Zero))) + min(cmptMax(q), scalar(0));
}


//- Signed distance to the shapes of surfaceCase.H's box.stl and
//  twoBoxes.stl (the two cubes apart: the nearer one's)
scalar shapeDistance(const word& file, const point& x)
{
    if (file == "box.stl")
    {
        return boxDistance
        (
            x, point(0.375, 0.375, 0.25), point(0.625, 0.75, 0.875)
        );
    }
    return min
    (
        boxDistance(x, point::uniform(0.25), point::uniform(0.4375)),
        boxDistance(x, point::uniform(0.5625), point::uniform(0.75))
    );
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


TEST(triSurfaceGeometry, QueriesFromSeveralThreadsAtOnceAreThoseOfOne)
{
    const surfaceCase surfaces;

    // Points in and around each surface's box (the octree's box): between
    // the two cubes many are nearest a corner of one, by the box a face
    // or an edge. A chunk per thread; the first queries of the geometry
    constexpr label nChunks = 8, chunk = 2000;
    // Round-off of the search
    constexpr double tol = 1e-14;
    for (const word file : {"box.stl", "twoBoxes.stl"})
    {
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> u(0, 1);
        List<pointField> points(nChunks, pointField(chunk));
        for (pointField& pts : points)
        {
            for (point& x : pts)
            {
                x = point
                (
                    0.2 + 0.6*u(rng), 0.2 + 0.6*u(rng), 0.15 + 0.8*u(rng)
                );
            }
        }
        const std::string dict("type triSurface; file " + file + ";");
        const autoPtr<barrierGeometry> surface
        (
            readGeometry(dict, surfaces.dir())
        );
        ASSERT_TRUE(surface->threadSafeDistance());
        List<scalarField> phi(nChunks);
        List<vectorField> normal(nChunks);
        List<boolList> in(nChunks);
        {
            const threadCount threads(4);
            #pragma omp parallel for schedule(dynamic, 1)
            for (label k = 0; k < nChunks; ++k)
            {
                surface->inside(points[k], in[k]);
                surface->distance(points[k], phi[k], normal[k]);
            }
        }

        // One thread, another geometry: the same bit for bit; inside as
        // the analytic shape says
        const autoPtr<barrierGeometry> serial
        (
            readGeometry(dict, surfaces.dir())
        );
        label nInside = 0;
        for (label k = 0; k < nChunks; ++k)
        {
            scalarField phi1;
            vectorField normal1;
            boolList in1;
            serial->distance(points[k], phi1, normal1);
            serial->inside(points[k], in1);
            forAll(points[k], i)
            {
                const point& x = points[k][i];
                EXPECT_EQ(phi[k][i], phi1[i]) << file << " " << x;
                EXPECT_EQ(normal[k][i], normal1[i]) << file << " " << x;
                EXPECT_EQ(in[k][i], in1[i]) << file << " " << x;
                const scalar exact = shapeDistance(file, x);
                EXPECT_NEAR(phi[k][i], exact, tol) << file << " " << x;
                if (mag(exact) > 1e-12)
                {
                    EXPECT_EQ(bool(in[k][i]), exact < 0) << file << " " << x;
                }
                nInside += in[k][i];
            }
        }
        // (The box fills a fifth of the points' box, the cubes 1/22)
        EXPECT_GT(nInside, nChunks*chunk/(file == "box.stl" ? 6 : 30))
            << file;
    }
}


// ************************************************************************* //
