/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    topographyModel::sampleNodes, under the solvers' floating-point traps:
    an expression that is not finite or beyond |Z| <= 1e6 m at a node is
    refused naming the node and the expression (a SIGFPE before); a raster
    must cover the grid to half a raster cell; on a 2D grid the terrain must
    lie within the mesh's z-range, and the default flat bed says it is the
    default; a 3D grid leaves that to the terrain barrier; meshRange finds
    the lowest and highest node of the mesh, ghosts excluded; every model's
    gradient is exact (flat, an expression against its closed form, a
    raster's bilinear interpolant of a plane).

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "topographyModel.H"
#include "OSspecific.H"
#include "testCase.H"
#include <gtest/gtest.h>
#include <array>
#include <fstream>
#include <vector>

using namespace Foam;

namespace
{

//- A grid of 20 x 10 cells of 1 m from (0 0), z from 1 m to 11 m
gridGeometry grid(const int dim = 2)
{
    gridGeometry g;
    g.dim = dim;
    g.origin[2] = 1;
    g.dx[2] = (dim == 2) ? 10 : 1;
    g.nCells[0] = 20;
    g.nCells[1] = 10;
    g.nCells[2] = (dim == 2) ? 1 : 10;
    g.finalise();
    return g;
}


//- The topography dictionary of an expression Z(x, y)
dictionary expressionDict(const std::string& Z)
{
    dictionary coeffs;
    coeffs.add("Z", string(Z));
    dictionary dict;
    dict.name() = "constant/dampmProperties";
    dict.add("topography", word("expression"));
    dict.add("expressionCoeffs", coeffs);
    return dict;
}


//- The error text of sampling the topography of dict on g ("" if none)
std::string sampled(const dictionary& dict, const gridGeometry& g)
{
    return foamIOErrorText
    (
        [&]
        {
            autoPtr<topographyModel> topo =
                topographyModel::New(dict, fileName(DAMPM_TEST_MESHES));
            std::vector<double> Z(g.nNodes());
            topo->sampleNodes(g, Z.data());
        }
    );
}

} // End anonymous namespace


TEST(topographyModel, NonFiniteAndHugeElevationsAreRefusedNamingTheNode)
{
    const solverFpTraps traps;
    const gridGeometry g(grid());
    // {expression, Z shown, node}
    const std::vector<std::array<std::string, 3>> cases =
    {
        {"1/(x-x)", "gives Z = inf m", "(x y) = (-1 -1) (a ghost node"},
        {"x < 5 ? 6 : sqrt(5 - x)", "nan m", "(x y) = (6 -1)"},
        {"y < 3 ? 6 : 6 + log(y - 3)", "gives Z = -inf m", "(x y) = (-1 3)"},
        {"6 + exp(1000*(x - 4))", "gives Z = inf m", "(x y) = (5 -1)"},
        {"1e300", "gives Z = 1e+300 m", "(x y) = (-1 -1)"},
        {"6 - 2e5*x", "gives Z = -1199994 m", "(x y) = (6 -1)"},
    };
    for (const auto& c : cases)
    {
        const std::string msg = sampled(expressionDict(c[0]), g);
        EXPECT_NE(msg.find("the topography expression (Z = \"" + c[0] + "\")"),
            std::string::npos) << msg;
        EXPECT_NE(msg.find(c[1]), std::string::npos) << msg;
        EXPECT_NE(msg.find("at the grid node " + c[2]), std::string::npos)
            << msg;
        EXPECT_NE(msg.find("allowed: a finite Z with |Z| <= 1000000 m"),
            std::string::npos) << msg;
        EXPECT_NE(msg.find("file: constant/dampmProperties.expressionCoeffs"),
            std::string::npos) << msg;
    }

    // At the bound (on the ghost nodes x = 21) is fine
    EXPECT_EQ(sampled(expressionDict("x > 20.5 ? -1e6 : 6"), g), "");
}


TEST(topographyModel, TerrainMustLieInTheMeshZRangeOfA2DGrid)
{
    const solverFpTraps traps;
    const gridGeometry g(grid());

    // From the bottom to the top of the mesh exactly: fine; ghost nodes
    // (x = -1, 21) beyond it do not count
    EXPECT_EQ(sampled(expressionDict("1 + 0.5*x"), g), "");

    const std::string above = sampled(expressionDict("1.5 + 0.5*x"), g);
    EXPECT_NE(above.find("ranges from Z = 1.5 m at (x y) = (0 0) to Z = 11.5 m"
        " at (x y) = (20 0) over the mesh's nodes, outside the mesh's z-range"
        " 1 to 11 m"), std::string::npos) << above;
    EXPECT_NE(above.find("allowed: 1 <= Z <= 11 m at every node of the mesh"),
        std::string::npos) << above;

    // No keyword topography: the flat bed at 0, said to be the default
    dictionary none;
    none.name() = "constant/dampmProperties";
    const std::string byDefault = sampled(none, g);
    EXPECT_NE(byDefault.find("topography flat (Z0 = 0 m) (the default: no"
        " keyword topography)"), std::string::npos) << byDefault;
    EXPECT_NE(byDefault.find("file: constant/dampmProperties"),
        std::string::npos) << byDefault;

    // A 3D grid: the terrain barrier decides (wholly above or below)
    EXPECT_EQ(sampled(expressionDict("100"), grid(3)), "");
}


TEST(topographyModel, MeshRangeSkipsTheGhostNodes)
{
    const gridGeometry g(grid());
    std::vector<double> Z(g.nNodes(), 5.0);
    Z[0] = -100;
    Z[g.nNodes() - 1] = 100;
    const label low = g.nodeIndex(3, 4, 0);
    const label high = g.nodeIndex(20, 10, 0);
    Z[low] = 2;
    Z[high] = 9;
    label lowest, highest;
    topographyModel::meshRange(g, Z.data(), lowest, highest);
    EXPECT_EQ(lowest, low);
    EXPECT_EQ(highest, high);
}


TEST(topographyModel, RasterMustCoverTheGridToHalfARasterCell)
{
    const solverFpTraps traps;
    const gridGeometry g(grid());
    const fileName dir(scratchDir("topographyModel"));
    mkDir(dir);

    // 2 m cells from map (1000 5000); local origin at the lower-left corner
    const auto raster = [&](const word& name, int nx, double cell)
    {
        std::ofstream os(dir/name);
        os  << "ncols " << nx << "\nnrows 6\nxllcorner 1000\nyllcorner 5000\n"
            << "cellsize " << cell << '\n';
        for (int j = 0; j < 6; ++j)
        {
            for (int i = 0; i < nx; ++i)
            {
                os  << (i ? " " : "") << 6;
            }
            os  << '\n';
        }
        dictionary coeffs;
        coeffs.add("file", dir/name);
        dictionary dict;
        dict.name() = "constant/dampmProperties";
        dict.add("topography", word("raster"));
        dict.add("rasterCoeffs", coeffs);
        return dict;
    };

    // 20 m by 12 m: covers the 20 m x 10 m grid
    EXPECT_EQ(sampled(raster("covers.asc", 10, 2), g), "");
    // 19.6 m: 0.4 m short, a fifth of a cell: accepted (and logged)
    EXPECT_EQ(sampled(raster("sliver.asc", 10, 1.96), g), "");
    // 18 m: a whole cell short
    const std::string msg = sampled(raster("short.asc", 9, 2), g);
    EXPECT_NE(msg.find("does not cover the mesh: its cells span x 0 to 18,"
        " y 0 to 12 m"), std::string::npos) << msg;
    EXPECT_NE(msg.find("the mesh (system/blockMeshDict) x 0 to 20, y 0 to 10 m,"
        " beyond the raster by east 2 m"), std::string::npos) << msg;
    EXPECT_NE(msg.find("allowed: a mesh within the raster's cells, give or"
        " take half a raster cell (1 x 1 m)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("file: constant/dampmProperties.rasterCoeffs"),
        std::string::npos) << msg;
}


TEST(topographyModel, GradientIsExactForEachModel)
{
    const solverFpTraps traps;
    const fileName caseDir(DAMPM_TEST_MESHES);

    // Flat
    dictionary flat;
    flat.add("topography", word("flat"));
    const autoPtr<topographyModel> Zflat =
        topographyModel::New(flat, caseDir);
    EXPECT_EQ(Zflat->gradient(3.7, -2.1), vector2D::zero);

    // An expression: a tilted plane with a ridge along x
    const autoPtr<topographyModel> Zexpr = topographyModel::New
    (
        expressionDict("2 + 0.3*x - 0.1*y + 0.5*sin(0.7*x)*cos(0.2*y)"),
        caseDir
    );
    const vector2D points[] =
        {vector2D(0, 0), vector2D(3.3, 7.1), vector2D(17, 2)};
    for (const vector2D& p : points)
    {
        const double x = p.x(), y = p.y();
        const vector2D exact
        (
            0.3 + 0.35*std::cos(0.7*x)*std::cos(0.2*y),
            -0.1 - 0.1*std::sin(0.7*x)*std::sin(0.2*y)
        );
        const vector2D grad = Zexpr->gradient(x, y);
        EXPECT_NEAR(grad.x(), exact.x(), 1e-15) << p.x() << ' ' << p.y();
        EXPECT_NEAR(grad.y(), exact.y(), 1e-15) << p.x() << ' ' << p.y();
    }

    // A raster of the plane Z = 1 + 0.5 x + 0.25 y (local; 2 m cells from
    // map (1000 5000)): its bilinear interpolant is the plane inside, and
    // constant across the edge outside it
    const fileName dir(scratchDir("topographyModel"));
    mkDir(dir);
    {
        std::ofstream os(dir/"plane.asc");
        os  << "ncols 8\nnrows 6\nxllcorner 1000\nyllcorner 5000\n"
            << "cellsize 2\n";
        os.precision(17);
        for (int j = 5; j >= 0; --j)
        {
            for (int i = 0; i < 8; ++i)
            {
                os  << (i ? " " : "") << 1 + 0.5*(2*i + 1) + 0.25*(2*j + 1);
            }
            os  << '\n';
        }
    }
    dictionary coeffs;
    coeffs.add("file", dir/"plane.asc");
    dictionary raster;
    raster.add("topography", word("raster"));
    raster.add("rasterCoeffs", coeffs);
    const autoPtr<topographyModel> Zraster =
        topographyModel::New(raster, caseDir);
    const vector2D inside[] =
        {vector2D(3.3, 7.1), vector2D(9, 4), vector2D(1, 1)};
    for (const vector2D& p : inside)
    {
        const vector2D grad = Zraster->gradient(p.x(), p.y());
        EXPECT_NEAR(grad.x(), 0.5, 1e-12) << p.x() << ' ' << p.y();
        EXPECT_NEAR(grad.y(), 0.25, 1e-12) << p.x() << ' ' << p.y();
    }
    EXPECT_NEAR(Zraster->gradient(0.5, 5).x(), 0, 1e-15)
        << "west of the first sample, Z is constant across the edge";
    EXPECT_NEAR(Zraster->gradient(0.5, 5).y(), 0.25, 1e-12);
}


// ************************************************************************* //
