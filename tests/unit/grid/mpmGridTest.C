/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    mpmGrid from blockMesh meshes: 2D/3D detection, spacing and origin, the
    node <-> mesh point map, index-arithmetic cell lookup against OpenFOAM's
    own cell search, and refusal of graded and skewed meshes.

\*---------------------------------------------------------------------------*/

#include "mpmGrid.H"
#include "testCase.H"
#include "pointIOField.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

constexpr double geomTol = 1e-12;  // coordinates of order 10 m

void checkFindCellAgainstMesh(const mpmGrid& grid, const int nPoints)
{
    const fvMesh& mesh = grid.mesh();
    const boundBox bb(mesh.points(), false);
    std::mt19937 gen(2026);
    std::uniform_real_distribution<double> u(-0.05, 1.05);
    int nInside = 0;
    for (int i = 0; i < nPoints; ++i)
    {
        const point p
        (
            bb.min().x() + u(gen)*bb.span().x(),
            bb.min().y() + u(gen)*bb.span().y(),
            bb.min().z() + u(gen)*bb.span().z()
        );
        const label expected = mesh.findCell(p);
        EXPECT_EQ(grid.findCell(p), expected)
            << "point " << p.x() << ' ' << p.y() << ' ' << p.z();
        nInside += (expected >= 0);
    }
    // The sample must exercise both inside and outside points
    EXPECT_GT(nInside, nPoints/2);
    EXPECT_LT(nInside, nPoints);
}

void checkNodesAtMeshPoints(const mpmGrid& grid)
{
    const pointField& pts = grid.mesh().points();
    forAll(pts, pointi)
    {
        const point np = grid.nodePosition(grid.pointNode()[pointi]);
        EXPECT_NEAR(np.x(), pts[pointi].x(), geomTol);
        EXPECT_NEAR(np.y(), pts[pointi].y(), geomTol);
        if (!grid.is2D())
        {
            EXPECT_NEAR(np.z(), pts[pointi].z(), geomTol);
        }
    }
}

//- A copy of a test mesh whose points are moved by fn, written at 17
//  digits (the test meshes' writePrecision): the same doubles read back
template<class Fn>
fileName movedMesh(const std::string& name, const word& mesh, Fn&& fn)
{
    const fileName dir = testCase::scratchCopy(name, mesh);
    testCase tc(dir);
    pointIOField pts
    (
        IOobject
        (
            "points", tc.mesh().pointsInstance(), polyMesh::meshSubDir,
            tc.mesh(), IOobject::MUST_READ, IOobject::NO_WRITE, false
        )
    );
    forAll(pts, pointi)
    {
        pts[pointi] = fn(pts[pointi], pointi);
    }
    pts.write();
    return dir;
}

void expectSameLattice(const gridGeometry& a, const gridGeometry& b)
{
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_EQ(a.origin[d], b.origin[d]) << "axis " << d;
        EXPECT_EQ(a.dx[d], b.dx[d]) << "axis " << d;
        EXPECT_EQ(a.nCells[d], b.nCells[d]) << "axis " << d;
    }
}

} // End anonymous namespace


TEST(mpmGrid, TwoDimensionalBlockGivesBedPlaneGrid)
{
    testCase tc(testCase::meshDir("box2D"));
    const mpmGrid grid(tc.mesh());
    const gridGeometry& g = grid.geometry();
    EXPECT_TRUE(grid.is2D());
    EXPECT_EQ(g.nCells[0], 20);
    EXPECT_EQ(g.nCells[1], 10);
    EXPECT_EQ(g.nCells[2], 1);
    EXPECT_NEAR(g.dx[0], 0.5, geomTol);
    EXPECT_NEAR(g.dx[1], 0.5, geomTol);
    EXPECT_EQ(grid.nNodes(), (21 + 2)*(11 + 2));
    checkNodesAtMeshPoints(grid);
}


TEST(mpmGrid, ThreeDimensionalBlockKeepsOriginAndSpacing)
{
    testCase tc(testCase::meshDir("box3D"));
    const mpmGrid grid(tc.mesh());
    const gridGeometry& g = grid.geometry();
    EXPECT_FALSE(grid.is2D());
    EXPECT_EQ(g.nCellsTotal(), 8*6*5);
    EXPECT_NEAR(g.origin[0], 1.0, geomTol);
    EXPECT_NEAR(g.origin[1], -2.0, geomTol);
    EXPECT_NEAR(g.origin[2], 0.5, geomTol);
    for (int d = 0; d < 3; ++d)
    {
        EXPECT_NEAR(g.dx[d], 0.5, geomTol);
    }
    EXPECT_EQ(grid.nNodes(), 11*9*8);
    checkNodesAtMeshPoints(grid);

    // The whole domain's box: the blockMeshDict's corners, to the bit
    const point lo(1, -2, 0.5), hi(5, 1, 3);
    for (direction d = 0; d < 3; ++d)
    {
        EXPECT_EQ(grid.bounds().min()[d], lo[d]);
        EXPECT_EQ(grid.bounds().max()[d], hi[d]);
    }
}


TEST(mpmGrid, CellCentresAndVolumesFromFacesAreOpenFOAMs)
{
    for (const word mesh : {"box2D", "box3D"})
    {
        testCase tc(testCase::meshDir(mesh));
        const mpmGrid grid(tc.mesh());
        vectorField C;
        scalarField V;
        grid.cellCentresAndVolumes(C, V);
        const gridGeometry& g = grid.geometry();
        const point o(g.origin[0], g.origin[1], g.origin[2]);
        ASSERT_EQ(C.size(), tc.mesh().nCells());
        forAll(C, celli)
        {
            const point c = tc.mesh().cellCentres()[celli] - o;
            for (direction d = 0; d < 3; ++d)
            {
                EXPECT_NEAR(C[celli][d], c[d], 1e-12) << mesh << " cell " << celli;
            }
            EXPECT_NEAR(V[celli], tc.mesh().cellVolumes()[celli], 1e-13)
                << mesh << " cell " << celli;
        }
    }
}


TEST(mpmGrid, RoundOffInTheMeshLeavesTheLatticeAlone)
{
    // blockMesh's round-off in a binary mesh: every coordinate moved by
    // up to 3 units in the last place; the box is rounded back
    testCase exact(testCase::meshDir("box3D"));
    const mpmGrid reference(exact.mesh());
    std::mt19937 gen(7);
    std::uniform_int_distribution<int> ulps(-3, 3);
    const fileName dir = movedMesh
    (
        "mpmGridRoundOff", "box3D",
        [&](point p, label)
        {
            for (direction d = 0; d < 3; ++d)
            {
                for (int k = ulps(gen); k != 0; k += (k > 0 ? -1 : 1))
                {
                    p[d] = std::nextafter(p[d], k > 0 ? 1e300 : -1e300);
                }
            }
            return p;
        }
    );
    testCase noisy(dir);
    const boundBox noisyBox(noisy.mesh().points(), false);
    int moved = 0;
    for (direction d = 0; d < 3; ++d)
    {
        moved += noisyBox.min()[d] != reference.bounds().min()[d];
        moved += noisyBox.max()[d] != reference.bounds().max()[d];
    }
    EXPECT_GT(moved, 0) << "the noise moved no corner of the box";
    const mpmGrid grid(noisy.mesh());
    expectSameLattice(grid.geometry(), reference.geometry());
}


TEST(mpmGrid, CornersOfManyDigitsAreKept)
{
    // UTM-sized coordinates of 16 digits: rounding the box to 12 would
    // move it by 2e-6 m, off the 0.5 m lattice's tolerance; it is kept
    const vector shift(512345.678901234, 5123456.789012345, 1234.5);
    const fileName dir = movedMesh
    (
        "mpmGridUTM", "box3D", [&](const point& p, label){ return p + shift; }
    );
    testCase tc(dir);
    const boundBox meshBox(tc.mesh().points(), false);
    const mpmGrid grid(tc.mesh());
    for (direction d = 0; d < 3; ++d)
    {
        EXPECT_EQ(grid.bounds().min()[d], meshBox.min()[d]) << "axis " << d;
        EXPECT_EQ(grid.bounds().max()[d], meshBox.max()[d]) << "axis " << d;
        EXPECT_NEAR(grid.geometry().dx[d], 0.5, 1e-9);
    }
    EXPECT_EQ(grid.geometry().nCellsTotal(), 8*6*5);
}


TEST(mpmGrid, StructuredLookupAgreesWithMeshSearch3D)
{
    testCase tc(testCase::meshDir("box3D"));
    checkFindCellAgainstMesh(mpmGrid(tc.mesh()), 3000);
}


TEST(mpmGrid, StructuredLookupAgreesWithMeshSearch2D)
{
    testCase tc(testCase::meshDir("box2D"));
    checkFindCellAgainstMesh(mpmGrid(tc.mesh()), 3000);
}


TEST(mpmGrid, StructuredCellsMapOneToOneOnMeshCells)
{
    testCase tc(testCase::meshDir("box3D"));
    const mpmGrid grid(tc.mesh());
    labelList hits(tc.mesh().nCells(), 0);
    for (const label celli : grid.meshCell())
    {
        ASSERT_GE(celli, 0);
        ++hits[celli];
    }
    for (const label h : hits)
    {
        EXPECT_EQ(h, 1);
    }
}


TEST(mpmGrid, GradedMeshIsRefusedWithReason)
{
    testCase tc(testCase::meshDir("graded"));
    const std::string msg = foamErrorMessage([&]{ mpmGrid grid(tc.mesh()); });
    EXPECT_NE(msg.find("not a uniform, axis-aligned structured block"),
        std::string::npos) << msg;
    EXPECT_NE(msg.find("blockMeshDict"), std::string::npos) << msg;
}


TEST(mpmGrid, SkewedMeshIsRefusedWithReason)
{
    testCase tc(testCase::meshDir("skewed"));
    const std::string msg = foamErrorMessage([&]{ mpmGrid grid(tc.mesh()); });
    EXPECT_NE(msg.find("not a uniform, axis-aligned structured block"),
        std::string::npos) << msg;
}


// ************************************************************************* //
