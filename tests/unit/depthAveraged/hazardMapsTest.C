/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    Hazard maps: the maxima over time at the grid nodes, exported at the
    end of the run (not with the point fields) in the terrain's map
    coordinates as ESRI ASCII and, for a GeoTIFF terrain, as a GeoTIFF that reads back with the
    same values and georeference. The maxima kept in a 3D stage's state
    (saveMaxima, made as tokens) print as the lists they are (the text of
    a scalarList entry, at exact precision) and load back bit for bit.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "hazardMaps.H"
#include "topographyModel.H"
#include "terrainRaster.H"
#include "testCase.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "IStringStream.H"
#include "exactPrecision.H"
#include "sameBits.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

// Values written as float32 GeoTIFF and full-precision ASCII
constexpr double tiffTol = 1e-6;   // relative, float32
constexpr double ascTol = 1e-12;

} // End anonymous namespace


TEST(hazardMaps, MaximaExportedInMapCoordinatesAsAscAndGeoTiff)
{
    const fileName dir = testCase::scratchCopy("hazardMapsCase");
    testCase tc(dir);
    tc.runTime().setTime(2.5, 1);
    const mpmGrid grid(tc.mesh());
    const gridGeometry& g = grid.geometry();

    // A planar terrain in map coordinates, written as a GeoTIFF: samples
    // every 0.25 m from (1000.125, 5000.125), i.e. lower-left corner
    // (1000, 5000), covering the 10 m x 5 m grid
    const label nx = 41, ny = 21;
    scalarList Z(nx*ny);
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            Z[i + nx*j] = 100 + 0.5*(0.125 + 0.25*i) - 0.2*(0.125 + 0.25*j);
        }
    }
    const terrainRaster source
    (
        vector2D(1000.125, 5000.125), 0.25, 0.25, nx, ny, Z, vector2D::zero
    );
    source.writeGeoTiff(dir/"constant"/"terrain.tif");

    dictionary dict;
    dict.add("topography", word("raster"));
    dictionary coeffs;
    coeffs.add("file", fileName("constant/terrain.tif"));
    dict.add("rasterCoeffs", coeffs);
    autoPtr<topographyModel> topo = topographyModel::New(dict, dir);
    EXPECT_NEAR(topo->mapOffset().x(), 1000, 1e-9);
    EXPECT_NEAR(topo->mapOffset().y(), 5000, 1e-9);

    // The shared box2D mesh is 1 m thick, under a terrain that rises 5 m
    // across it: sampled as on a mesh whose z-range spans the terrain, as
    // dampmFoam requires (not what this test is about)
    gridGeometry spanning(g);
    spanning.origin[2] = 90;
    spanning.dx[2] = 20;
    std::vector<double> Znodes(g.nNodes());
    topo->sampleNodes(spanning, Znodes.data());
    hazardMaps maps(grid, *topo, Znodes.data());

    // Two steps of a made-up node state: the maps keep the maxima
    shallowGrid nodes;
    nodes.resize(g.nNodes());
    for (int step = 0; step < 2; ++step)
    {
        for (label n = 0; n < g.nNodes(); ++n)
        {
            nodes.h[n] = step == 0 ? 0.01*n : 0.005*n;
            nodes.vx[n] = step == 0 ? 1.0 : 2.0;
            nodes.vy[n] = 0;
        }
        maps.update(nodes, g.allNodes());
    }
    // The point fields at write times, the rasters at the end
    maps.write();
    const fileName out = dir/"postProcessing"/"hazardMaps"/"2.5";
    ASSERT_FALSE(isDir(out));
    maps.writeRasters(grid.mesh().time());

    ASSERT_TRUE(isFile(out/"maxHeight.asc"));
    ASSERT_TRUE(isFile(out/"maxHeight.tif"))
        << "no GeoTIFF for a GeoTIFF terrain";

    for (const word ext : {"asc", "tif"})
    {
        terrainRaster maxH(out/("maxHeight." + ext));
        maxH.setOffset(vector2D(1000, 5000));
        ASSERT_EQ(maxH.nx(), g.nCells[0] + 1);
        ASSERT_EQ(maxH.ny(), g.nCells[1] + 1);
        const double tol = ext == "tif" ? tiffTol : ascTol;
        for (label j = 0; j <= g.nCells[1]; ++j)
        {
            for (label i = 0; i <= g.nCells[0]; ++i)
            {
                // Node (i, j) at local (i dx, j dy) = map (1000 + ..)
                EXPECT_NEAR(maxH.x(i), g.nodeCoord(0, i), 1e-9);
                EXPECT_NEAR(maxH.y(j), g.nodeCoord(1, j), 1e-9);
                const double expected = 0.01*g.nodeIndex(i, j, 0);
                EXPECT_NEAR(maxH.value(i, j), expected, tol*(1 + expected));
            }
        }
    }

    // Speed along the bed: |v| sqrt(1 + (dZ/dx)^2) with dZ/dx = 0.5
    terrainRaster maxU(out/"maxSpeed.asc");
    const label interior = g.nCells[0]/2 + (g.nCells[0] + 1)*(g.nCells[1]/2);
    EXPECT_NEAR(maxU.values()[interior], 2*std::sqrt(1.25), 1e-9);

    // The state of a 3D stage that continues the maps: the text of the
    // lists given as values, and the maxima back bit for bit
    const exactPrecision exact;
    dictionary state;
    maps.saveMaxima(state);
    dictionary asLists;
    for (const word& name : hazardMaps::names)
    {
        asLists.set(name, state.get<scalarList>(name));
    }
    OStringStream made, lists;
    made << state;
    lists << asLists;
    EXPECT_EQ(made.str(), lists.str());
    EXPECT_NE(made.str().find(" 0 "), std::string::npos);

    // (and the values those of the exported map, bit for bit: its text
    // is the shortest that reads back the same double)
    const scalarList savedH(state.get<scalarList>("maxHeight"));
    const terrainRaster ascH(out/"maxHeight.asc");
    for (label j = 0; j <= g.nCells[1]; ++j)
    {
        for (label i = 0; i <= g.nCells[0]; ++i)
        {
            EXPECT_TRUE
            (
                sameBits(savedH[g.nodeIndex(i, j, 0)], ascH.value(i, j))
            ) << i << " " << j;
        }
    }

    // Read back from the text (the state is written in ASCII whatever
    // writeFormat: OpenFOAM's token streams cannot read the lists back from
    // binary; tests/cases/coupled/layerAtRest restarts a binary 3D stage)
    IStringStream is(made.str());
    const dictionary read(is);
    hazardMaps loaded(grid, *topo, Znodes.data());
    loaded.loadMaxima(read);
    dictionary again;
    loaded.saveMaxima(again);
    for (const word& name : hazardMaps::names)
    {
        const scalarList a(state.get<scalarList>(name));
        const scalarList b(again.get<scalarList>(name));
        ASSERT_EQ(a.size(), b.size()) << name;
        label nonzero = 0;
        forAll(a, i)
        {
            EXPECT_TRUE(sameBits(a[i], b[i])) << name << " " << i;
            nonzero += a[i] != 0;
        }
        EXPECT_GT(nonzero, 0) << name;
    }
}


// ************************************************************************* //
