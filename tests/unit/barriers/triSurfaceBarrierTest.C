/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    triSurfaceBarrier, the closed STL surface of the box from
    (0.375 0.375 0.25) to (0.625 0.75 0.875) (exact in the STL's single
    precision), on a grid of 0.1 x 0.15 x 0.2 m cells; the same when the
    file's triangles face inwards (flipped):
    - signed distance, negative inside, to the nearest face, edge or
      corner, with the nearest triangle's outward normal; inside as the
      distance says;
    - the particles' guard: a particle entering through the top face is put
      back on it and loses its velocity into it (slip; Coulomb with
      mu = 0.1 halves its 0.2 m/s along the face against 1 m/s into it).

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include "stlText.H"
#include "OSspecific.H"
#include <gtest/gtest.h>
#include <cmath>
#include <fstream>

using namespace Foam;

namespace
{

//- A case folder with the box's surface in constant/triSurface, facing
//  outwards (box.stl) and inwards (inverted.stl); one per process (CTest
//  runs tests in parallel), removed with the object
class surfaceCase
{
    fileName dir_;

public:

    surfaceCase()
    :
        dir_
        (
            fileName(DAMPM_TEST_MESHES).path()
           /("triSurfaceBarrier" + Foam::name(pid()))
        )
    {
        mkDir(dir_/"constant"/"triSurface");
        triangleList tris(box({0.375, 0.375, 0.25}, {0.625, 0.75, 0.875}));
        std::ofstream(dir_/"constant"/"triSurface"/"box.stl") << ascii(tris);
        for (auto& tri : tris)
        {
            std::swap(tri[1], tri[2]);
        }
        std::ofstream(dir_/"constant"/"triSurface"/"inverted.stl")
            << ascii(tris);
    }

    ~surfaceCase()
    {
        rmDir(dir_);
    }

    const fileName& dir() const
    {
        return dir_;
    }
};

} // End anonymous namespace


TEST(triSurfaceBarrier, SignedDistanceAndOutwardNormalOfAClosedSurface)
{
    const surfaceCase surfaces;
    // Round-off of the search
    constexpr double tol = 1e-14;
    for (const word file : {"box.stl", "inverted.stl"})
    {
        barrierProbe probe
        (
            "type triSurface; file " + file + "; contact slip;",
            surfaces.dir()
        );
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
        probe.barrier().inside(points, in);
        for (label i = 0; i < 6; ++i)
        {
            const auto& c = cases[i];
            vector normal;
            EXPECT_NEAR(probe.distance(c.x, normal), c.phi, tol)
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


TEST(triSurfaceBarrier, EnteringParticleStopsOnTheFaceItCrossed)
{
    const surfaceCase surfaces;
    const point x0(0.5, 0.55, 0.95), x1(0.5, 0.57, 0.85);
    const vector u(0, 0.2, -1);
    const std::pair<std::string, vector> contacts[] =
    {
        {"slip", vector(0, 0.2, 0)},
        {"Coulomb; frictionCoefficient 0.1", vector(0, 0.1, 0)}
    };
    for (const auto& c : contacts)
    {
        barrierProbe probe
        (
            "type triSurface; file box.stl; contact " + c.first + ";",
            surfaces.dir()
        );
        point x = x1;
        vector v = u, F;
        EXPECT_TRUE(probe.entry(x0, x, v, 0.01, 1e-3, F)) << c.first;
        // Bisection to 2^-30 of the move
        EXPECT_LT(mag(x - point(0.5, 0.57, 0.875)), 1e-9*mag(x1 - x0))
            << c.first;
        EXPECT_LT(mag(v - c.second), 1e-15) << c.first;
        EXPECT_LT(mag(F - 0.01*(u - c.second)/1e-3), 1e-12) << c.first;
    }
}


// ************************************************************************* //
