/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    releaseModel::sampleColumns and volumeOutside on a 20 m x 20 m grid of
    1 m cells with 2 x 2 columns per cell, under the solvers' floating-point
    traps: a raster release drawn as a block in NODATA releases the block's
    volume exactly; a box reaching beyond the mesh keeps and loses exactly
    its areas' volumes, also when the lattice outside is coarsened; an
    expression's NaN or inf is refused naming the column (not clamped to
    zero); a release wholly outside the mesh, or with nothing inside it, is
    refused naming both extents. thicknessScale scales the kept and lost
    volumes and must be positive. A polygon (non-convex, either
    orientation) releases its area times the thickness exactly, or fills
    to its surface level over a sloping bed.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "uniformGrid.H"
#include "releaseModel.H"
#include "OSspecific.H"
#include "testCase.H"
#include "IStringStream.H"
#include <gtest/gtest.h>
#include <array>
#include <fstream>
#include <numeric>
#include <vector>

using namespace Foam;

namespace
{

//- Columns per cell and axis
constexpr label nPerCell = 2;

//- Density [kg/m^3]
constexpr scalar rho = 1000;

//- A 2D grid of 20 x 20 cells of 1 m from (0 0)
gridGeometry grid()
{
    return uniformGrid(2, {0, 0, 0}, {1, 1, 1}, {20, 20, 1});
}


//- The release of the dictionary text, on a flat bed
class testRelease
{
    autoPtr<topographyModel> flat_;
    autoPtr<releaseModel> release_;

public:

    //- On the bed of topographyDict (flat when empty)
    explicit testRelease
    (
        const std::string& text,
        const dictionary& topographyDict = dictionary()
    )
    {
        flat_ = topographyModel::New
        (
            topographyDict, fileName(DAMPM_TEST_MESHES)
        );
        IStringStream is(text);
        dictionary dict(is);
        dict.name() = "constant/dampmProperties.release";
        release_ = releaseModel::New(dict, *flat_, fileName(DAMPM_TEST_MESHES));
    }

    const releaseModel& operator()() const
    {
        return *release_;
    }
};


//- Volume of the sampled columns [m^3]
scalar keptVolume
(
    const std::string& text,
    label& nColumns,
    const dictionary& topographyDict = dictionary()
)
{
    const gridGeometry g(grid());
    std::vector<double> x, y, h;
    testRelease(text, topographyDict)().sampleColumns
    (
        g, nPerCell, rho, x, y, h
    );
    nColumns = label(h.size());
    return std::accumulate(h.begin(), h.end(), 0.0)/(nPerCell*nPerCell);
}


//- The error text of sampling the release of text ("" when none)
std::string refusal(const std::string& text)
{
    return foamIOErrorText
    (
        [&]
        {
            label n;
            keptVolume(text, n);
        }
    );
}

} // End anonymous namespace


TEST(releaseModel, RasterBlockInNoDataReleasesTheBlockVolumeExactly)
{
    const solverFpTraps traps;
    const fileName dir(scratchDir("releaseModel"));
    mkDir(dir);
    // 12 x 12 cells of 1 m from (0 0): a 2 m block of 4 x 3 cells, NODATA
    // and NaN around it; the raster covers part of the mesh
    {
        std::ofstream os(dir/"block.asc");
        os  << "ncols 12\nnrows 12\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
            << "NODATA_value -9999\n";
        for (int r = 0; r < 12; ++r)
        {
            const int j = 11 - r;
            for (int i = 0; i < 12; ++i)
            {
                const bool in = i >= 3 && i < 7 && j >= 5 && j < 8;
                os  << (i ? " " : "")
                    << (in ? "2" : (i + j) % 5 ? "-9999" : "nan");
            }
            os  << '\n';
        }
    }
    label nColumns;
    const scalar V = keptVolume
    (
        "type raster; file \"" + (dir/"block.asc") + "\";", nColumns
    );
    EXPECT_EQ(V, 2.0*12);
    // Columns with h > 0: over the block and the half cell around it
    EXPECT_EQ(nColumns, (4 + 1)*2*(3 + 1)*2);
}


TEST(releaseModel, BoxBeyondTheMeshKeepsAndLosesItsAreasVolumes)
{
    const solverFpTraps traps;
    const gridGeometry g(grid());
    const std::string box =
        "type box; min (15 -5); max (25 10); thickness 2;";
    label nColumns;
    EXPECT_EQ(keptVolume(box, nColumns), 2.0*5*10);
    EXPECT_EQ(nColumns, 10*20);

    label stride, nNotFinite;
    EXPECT_EQ
    (
        testRelease(box)().volumeOutside(g, nPerCell, stride, nNotFinite),
        2.0*(10*15 - 5*10)
    );
    EXPECT_EQ(stride, 1);
    EXPECT_EQ(nNotFinite, 0);

    // 2 km square: a lattice of 4000 x 4000 coarsened to blocks of 2 x 2,
    // whose centres still fall between the mesh's edges: exact here
    const std::string large =
        "type box; min (-1000 -1000); max (1000 1000); thickness 1;";
    EXPECT_EQ
    (
        testRelease(large)().volumeOutside(g, nPerCell, stride, nNotFinite),
        2000.0*2000 - 20*20
    );
    EXPECT_EQ(stride, 2);

    // Unknown extent: an expression
    EXPECT_EQ
    (
        testRelease("type expression; height \"1\";")().volumeOutside
        (
            g, nPerCell, stride, nNotFinite
        ),
        -1
    );
}


TEST(releaseModel, ThicknessScaleScalesKeptAndLostVolumesExactly)
{
    const solverFpTraps traps;
    const gridGeometry g(grid());
    const std::string box =
        "type box; min (15 -5); max (25 10); thickness 2;";
    label nColumns, nScaled;
    const scalar scaled =
        keptVolume(box + " thicknessScale 0.75;", nScaled);
    EXPECT_EQ(scaled, 0.75*keptVolume(box, nColumns));
    EXPECT_EQ(nScaled, nColumns);

    label stride, nNotFinite;
    EXPECT_EQ
    (
        testRelease(box + " thicknessScale 0.75;")().volumeOutside
        (
            g, nPerCell, stride, nNotFinite
        ),
        0.75*2.0*(10*15 - 5*10)
    );

    const std::string refused = refusal(box + " thicknessScale 0;");
    EXPECT_NE(refused.find("thicknessScale = 0 is invalid"), std::string::npos)
        << refused;
    EXPECT_NE(refused.find("thicknessScale > 0"), std::string::npos)
        << refused;
}


TEST(releaseModel, NonFiniteThicknessIsRefusedNotClampedToZero)
{
    const solverFpTraps traps;
    // max(NaN, 0) is 0: a log of a negative released nothing there
    const std::vector<std::array<std::string, 3>> cases =
    {
        {"x < 10 ? 1 : log(x - 10.25)", "h = -inf m", "(x y) = (10.25 0.25)"},
        {"x < 10 ? 1 : sqrt(10 - x)", "nan m", "(x y) = (10.25 0.25)"},
        {"1/(y - 0.25)", "h = inf m", "(x y) = (0.25 0.25)"},
        {"1e7", "h = 10000000 m", "(x y) = (0.25 0.25)"},
    };
    for (const auto& c : cases)
    {
        const std::string msg =
            refusal("type expression; height \"" + c[0] + "\";");
        EXPECT_NE(msg.find("expression (height = \"" + c[0] + "\""),
            std::string::npos) << msg;
        EXPECT_NE(msg.find(c[1] + " at the column " + c[2]), std::string::npos)
            << msg;
        EXPECT_NE(msg.find("allowed: a finite thickness 0 <= h <= 1000000 m"),
            std::string::npos) << msg;
        EXPECT_NE(msg.find("file: constant/dampmProperties.release"),
            std::string::npos) << msg;
    }

    // A negative thickness is no release
    label nColumns;
    EXPECT_EQ(keptVolume("type expression; height \"x - 19\";", nColumns),
        0.25*(0.25 + 0.75)*40);
}


TEST(releaseModel, ReleaseOutsideTheMeshIsRefusedNamingBothExtents)
{
    const solverFpTraps traps;
    const std::string away =
        refusal("type box; min (20 5); max (30 10); thickness 1;");
    EXPECT_NE(away.find("lies wholly outside the mesh: it spans x 20 to 30,"
        " y 5 to 10 m, the mesh (system/blockMeshDict) x 0 to 20, y 0 to 20 m"),
        std::string::npos) << away;
    EXPECT_NE(away.find("allowed: a release that overlaps the mesh"),
        std::string::npos) << away;

    const std::string nothing = refusal("type expression; height \"-1\";");
    EXPECT_NE(nothing.find("puts no mass inside the mesh: the thickness is 0"
        " at all 40 x 40 columns"), std::string::npos) << nothing;
    EXPECT_NE(nothing.find("allowed: a release with thickness h > 0 somewhere"
        " inside the mesh"), std::string::npos) << nothing;
}



TEST(polygonRelease, NonConvexPolygonReleasesItsAreaTimesItsDepth)
{
    const solverFpTraps traps;
    // An L of 10 x 4 and 4 x 6 m, vertices on cell lines: 64 m^2, 256
    // columns whose centres are all clear of its edges
    const std::string L = "((2 2) (12 2) (12 6) (6 6) (6 12) (2 12))";
    const std::string reversed = "((2 12) (6 12) (6 6) (12 6) (12 2) (2 2))";
    for (const std::string& vertices : {L, reversed})
    {
        label nColumns;
        EXPECT_EQ
        (
            keptVolume
            (
                "type polygon; vertices " + vertices + "; thickness 1.5;",
                nColumns
            ),
            1.5*64
        );
        EXPECT_EQ(nColumns, 64*nPerCell*nPerCell);
    }

    // Filled to 2 m over Z = 0.1 x: V = 2 A - 0.1 int x dA, with
    // int x dA = 40*7 + 24*4 (each column's midpoint value is exact for a
    // depth linear in x)
    dictionary coeffs;
    coeffs.add("Z", string("0.1*x"));
    dictionary sloping;
    sloping.name() = "constant/dampmProperties";
    sloping.add("topography", word("expression"));
    sloping.add("expressionCoeffs", coeffs);
    label nColumns;
    const scalar V = keptVolume
    (
        "type polygon; vertices " + L + "; surfaceLevel 2;", nColumns, sloping
    );
    EXPECT_NEAR(V, 2.0*64 - 0.1*(40*7 + 24*4), 1e-12*V);
    EXPECT_EQ(nColumns, 64*nPerCell*nPerCell);
}


// ************************************************************************* //
