/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    depthAveragedSeeding: a box release on the seed lattice becomes
    columns holding exactly the box's volume (thickness times area), each
    with mass rho V, basal area and square footprint of a seed cell and the
    release's velocity; its projection onto the grid keeps the volume to
    round-off with every shape function.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "depthAveragedSeeding.H"
#include "depthAveragedParticles.H"
#include "depthAveragedKernels.H"
#include "visitShape.H"
#include "topographyModel.H"
#include "IStringStream.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

// Sums of ~1e3 terms of one sign, relative
constexpr double roundOff = 1e-13;

constexpr label nPerCell = 2;
constexpr scalar rho = 1500;

// 20 x 16 cells of 1 x 0.5 m from (0, 0)
gridGeometry makeGrid()
{
    return uniformGrid(2, {0, 0, 0}, {1, 0.5, 1}, {20, 16, 1});
}

dictionary fromText(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

// A box 5 m x 3.5 m, 2 m thick, on the lattice, moving at (1.5, -0.5) m/s
const std::string box =
    "type box; min (5 2); max (10 5.5); thickness 2; U (1.5 -0.5);";
const double boxVolume = 2*5*3.5;

struct seeded
:
    public depthAveragedParticles
{
    seeded(const std::string& shapeName, const bool projection)
    {
        const gridGeometry g = makeGrid();
        dictionary none;
        autoPtr<topographyModel> flat =
            topographyModel::New(none, fileName(DAMPM_TEST_MESHES));
        dictionary releaseDict = fromText(box);
        releaseDict.name() = "constant/dampmProperties.release";
        autoPtr<releaseModel> release = releaseModel::New
        (
            releaseDict, *flat, fileName(DAMPM_TEST_MESHES)
        );
        autoPtr<shapeFunction> shape = shapeFunction::New
        (
            fromText("shapeFunction " + shapeName + ";"), 0.5/nPerCell
        );
        std::vector<double> area(g.nNodes(), 0.0);
        visitShape
        (
            *shape,
            [&](const auto& kernel)
            {
                nodalAreas(g, kernel, nPerCell, area.data());
            }
        );
        depthAveragedSeeding(g, nPerCell, rho, 1e-4, projection).seed
        (
            *release, *shape, area.data(), p, f
        );
    }

    double volume() const
    {
        double V = 0;
        for (label i = 0; i < p.size(); ++i)
        {
            V += p.component(particleArrays::VOL)[i];
        }
        return V;
    }
};

} // End anonymous namespace


TEST(depthAveragedSeeding, BoxReleaseIsSeededWithItsVolumeExactly)
{
    const seeded s("quadraticBSpline", false);
    const gridGeometry g = makeGrid();
    const double a = depthAveragedSeeding::seedArea(g, nPerCell);
    EXPECT_EQ(a, 0.125);

    // 10 x 14 seed cells of 0.5 x 0.25 m
    ASSERT_EQ(s.p.size(), 10*14);
    EXPECT_EQ(s.volume(), boxVolume);
    for (label i = 0; i < s.p.size(); ++i)
    {
        const double V = s.p.component(particleArrays::VOL)[i];
        EXPECT_EQ(V, 2*a);
        EXPECT_EQ(s.p.component(particleArrays::M)[i], rho*V);
        EXPECT_EQ(s.p.component(s.f.h())[i], 2.0);
        EXPECT_EQ(s.p.component(s.f.A())[i], a);
        EXPECT_EQ(s.p.component(s.f.F())[i], 0.5);
        EXPECT_EQ(s.p.component(s.f.F() + 1)[i], 0.0);
        EXPECT_EQ(s.p.component(s.f.F() + 2)[i], 0.0);
        EXPECT_EQ(s.p.component(s.f.F() + 3)[i], 0.25);
        EXPECT_EQ(s.p.component(particleArrays::UX)[i], 1.5);
        EXPECT_EQ(s.p.component(particleArrays::UY)[i], -0.5);
        const double x = s.p.component(particleArrays::X)[i];
        const double y = s.p.component(particleArrays::Y)[i];
        EXPECT_GT(x, 5);
        EXPECT_LT(x, 10);
        EXPECT_GT(y, 2);
        EXPECT_LT(y, 5.5);
    }
}


TEST(depthAveragedSeeding, ProjectedReleaseKeepsTheVolumeToRoundOff)
{
    for (const word shape : {"linear", "GIMP", "quadraticBSpline"})
    {
        const seeded s(shape, true);
        EXPECT_GT(s.p.size(), 10*14) << shape;
        EXPECT_NEAR(s.volume(), boxVolume, roundOff*boxVolume) << shape;
        double m = 0;
        for (label i = 0; i < s.p.size(); ++i)
        {
            m += s.p.component(particleArrays::M)[i];
        }
        EXPECT_NEAR(m, rho*boxVolume, roundOff*rho*boxVolume) << shape;
    }
}


// ************************************************************************* //
