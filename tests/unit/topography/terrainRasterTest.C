/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    terrainRaster: ESRI ASCII grids in both header forms (spaces, tabs,
    CRLF) read with the north row first; a planar terrain interpolated
    exactly with its exact gradient; local coordinates and clamping; ASCII
    and GeoTIFF round trips, an ASCII grid written on 1 and 2 threads the
    same text (each value's shortest text), the two formats of one raster
    read alike, and GDAL's ESRI driver agreeing on valid grids but accepting
    bad ones (why the ESRI reader is our own); the NODATA policies; every
    malformed file refused with an error that names the file and the
    keyword; values that are not decimal numbers (hex, trailing characters),
    out of range or beyond the caller's bound refused with their line, under
    the solvers' floating-point traps; NaN as NODATA in both formats, a
    GeoTIFF's read under the traps; NODATA as zero keeping a block's volume;
    the real hillsideKot600m.asc.

\*---------------------------------------------------------------------------*/

#include "scratchDir.H"
#include "terrainRaster.H"
#include "fpTrapsHeld.H"
#include "OSspecific.H"
#include "testCase.H"
#include "threadCount.H"
#include "fileContents.H"
#include <gtest/gtest.h>
#include <ogr_srs_api.h>
#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal.h>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

using namespace Foam;

namespace
{

// Round-off of bilinear sums of O(|Z|) samples
constexpr double relTol = 1e-12;

// Map coordinates of the test rasters' lower-left corner: large, as real
constexpr double X0 = 1.5e6;
constexpr double Y0 = 5.2e6;

const double notANumber = std::numeric_limits<double>::quiet_NaN();

//- Planar terrain in map coordinates
double planar(const double X, const double Y)
{
    return 1200 + 0.3*(X - X0) - 0.45*(Y - Y0);
}


//- Folder for the test files, beside the test meshes in the build folder
fileName testDir()
{
    const fileName dir(scratchDir("terrainRaster"));
    mkDir(dir);
    return dir;
}


//- Write text as is (CRLF kept) and return the file name
fileName writeText(const word& name, const std::string& text)
{
    const fileName file(testDir()/name);
    std::ofstream(file, std::ios::binary) << text;
    return file;
}


//- An ESRI ASCII grid: header lines (key, value) then rows north to south
//  of z(i, j), j = 0 south, separated by sep, lines ended by eol
template<class Fn>
std::string ascText
(
    const std::vector<std::pair<std::string, std::string>>& header,
    const int nx,
    const int ny,
    Fn&& z,
    const std::string& sep = " ",
    const std::string& eol = "\n"
)
{
    std::ostringstream os;
    os.precision(17);
    for (const auto& kv : header)
    {
        os  << kv.first << sep << kv.second << eol;
    }
    for (int j = ny - 1; j >= 0; --j)
    {
        for (int i = 0; i < nx; ++i)
        {
            os  << (i ? sep : "") << z(i, j);
        }
        os  << eol;
    }
    return os.str();
}


//- n samples uniform in [lo, hi), reproducible by the seed
scalarList uniformSamples
(
    const label n,
    const unsigned seed,
    const double lo,
    const double hi
)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    scalarList values(n);
    for (scalar& v : values)
    {
        v = u(gen);
    }
    return values;
}


//- The header after ncols and the rows of a 3 x 2 raster
const std::string rows2x3 =
    "nrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 5 6\n";


//- 3 x 2 raster, north row 1 2 3, south row 4 5 6
std::string smallText(const std::string& xKey, const std::string& yKey)
{
    return "ncols 3\nnrows 2\n" + xKey + " 10\n" + yKey + " 20\n"
        "cellsize 2\n1 2 3\n4 5 6\n";
}

} // End anonymous namespace


TEST(terrainRaster, PlanarTerrainIsInterpolatedExactlyWithExactGradient)
{
    const int nx = 7;
    const int ny = 5;
    const double h = 2.5;
    // Tabs and CRLF; the sample (i, j) is at the cell centre
    const fileName file = writeText
    (
        "planar.asc",
        ascText
        (
            {
                {"ncols", "7"}, {"nrows", "5"}, {"xllcorner", "1500000"},
                {"yllcorner", "5200000"}, {"cellsize", "2.5"},
                {"NODATA_value", "-9999"}
            },
            nx, ny,
            [&](int i, int j)
            {
                return planar(X0 + (i + 0.5)*h, Y0 + (j + 0.5)*h);
            },
            "\t", "\r\n"
        )
    );

    terrainRaster terrain(file);
    terrain.setOffset(terrain.mapLowerLeft());
    ASSERT_EQ(terrain.nx(), nx);
    ASSERT_EQ(terrain.ny(), ny);
    EXPECT_EQ(terrain.dx(), h);
    EXPECT_EQ(terrain.dy(), h);
    EXPECT_EQ(terrain.nNoData(), 0);
    EXPECT_FALSE(terrain.hasProjection());

    // Differences of O(|Z|) samples over h
    const double Zmax = std::abs(terrain.maxValue());
    const double gradTol = relTol*Zmax/h;

    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0, 1);
    const boundBox bb(terrain.bounds());
    for (int k = 0; k < 1000; ++k)
    {
        const double x = bb.min().x() + u(gen)*bb.span().x();
        const double y = bb.min().y() + u(gen)*bb.span().y();
        scalar Z, dZdx, dZdy;
        terrain.evaluate(x, y, Z, dZdx, dZdy);
        const double exact =
            planar(x + terrain.offset().x(), y + terrain.offset().y());
        EXPECT_NEAR(Z, exact, relTol*Zmax) << x << ' ' << y;
        EXPECT_NEAR(dZdx, 0.3, gradTol);
        EXPECT_NEAR(dZdy, -0.45, gradTol);
    }
}


// highestOver, the particles' guard's bound of a column: on a random raster
// no value in the rectangle (inside the hull or beyond it, where Z is
// clamped) exceeds it; on a planar raster it is the highest corner (Z is
// bilinear, so its maximum over a rectangle is at a corner of a piece)
TEST(terrainRaster, HighestOverARectangleBoundsItsValues)
{
    const int nx = 9;
    const int ny = 7;
    const scalarList values(uniformSamples(nx*ny, 3, 100, 140));
    const std::vector<std::pair<std::string, std::string>> header =
    {
        {"ncols", std::to_string(nx)}, {"nrows", std::to_string(ny)},
        {"xllcorner", "1500000"}, {"yllcorner", "5200000"},
        {"cellsize", "2.5"}
    };
    terrainRaster random
    (
        writeText
        (
            "highest.asc",
            ascText(header, nx, ny, [&](int i, int j)
            {
                return values[i + nx*j];
            })
        )
    );
    random.setOffset(random.mapLowerLeft());
    terrainRaster plane
    (
        writeText
        (
            "highestPlanar.asc",
            ascText(header, nx, ny, [&](int i, int j)
            {
                return planar(X0 + 1.25 + 2.5*i, Y0 + 1.25 + 2.5*j);
            })
        )
    );
    plane.setOffset(plane.mapLowerLeft());

    std::mt19937 gen(17);
    std::uniform_real_distribution<double> corner(-4, 26), size(0, 6), u(0, 1);
    for (int r = 0; r < 400; ++r)
    {
        // Every fourth rectangle a sliver of zero width
        const double x0 = corner(gen), y0 = corner(gen);
        const double x1 = x0 + (r % 4 ? size(gen) : 0), y1 = y0 + size(gen);
        const double top = random.highestOver(x0, x1, y0, y1);
        EXPECT_LE(top, 140*(1 + 1e-12));
        for (int k = 0; k < 200; ++k)
        {
            const double x = k < 2 ? (k ? x1 : x0) : x0 + (x1 - x0)*u(gen);
            const double y = k < 2 ? (k ? y1 : y0) : y0 + (y1 - y0)*u(gen);
            ASSERT_LE(random.Z(x, y), top)
                << "(" << x << " " << y << ") in " << x0 << " " << x1 << " "
                << y0 << " " << y1;
        }

        // Inside the hull, a plane's highest corner
        const double a = 1.25 + 0.5*(x0 + 4), b = 1.25 + 0.4*(y0 + 4);
        const double c = a + 0.5*size(gen), d = b + 0.5*size(gen);
        double highest = -GREAT;
        for (const double x : {a, c})
        {
            for (const double y : {b, d})
            {
                highest = std::max(highest, plane.Z(x, y));
            }
        }
        const double planeTop = plane.highestOver(a, c, b, d);
        EXPECT_GE(planeTop, highest);
        EXPECT_LT(planeTop - highest, 1e-7) << a << " " << c << " " << b;
    }
}


// highestOver in map coordinates (local = map, offset zero), a cliff rising
// 20 m per m east of sample line 4 from a floor at Z = 0: points stepped by
// one ulp across the sample line, in slivers a few ulps wide, stay below
// the bound (a bound found from the line's position in metres, not in
// sample units, falls short there by the slope times an ulp of x)
TEST(terrainRaster, HighestOverHoldsAtMapCoordinatesAcrossACliff)
{
    const int nx = 9;
    const int ny = 3;
    terrainRaster cliff
    (
        writeText
        (
            "cliff.asc",
            ascText
            (
                {
                    {"ncols", std::to_string(nx)},
                    {"nrows", std::to_string(ny)},
                    {"xllcorner", "1500000"}, {"yllcorner", "5200000"},
                    {"cellsize", "2.5"}
                },
                nx, ny,
                [](int i, int) { return i > 4 ? 50.0*(i - 4) : 0.0; }
            )
        )
    );
    // The sample line x = X0 + 1.25 + 4*2.5 (map = local)
    const double line = X0 + 11.25;
    const double y = Y0 + 2.5;
    for (int w = 1; w <= 64; w *= 2)
    {
        double a = line;
        for (int k = 0; k < w; ++k)
        {
            a = std::nextafter(a, 0.0);
        }
        double b = line;
        for (int k = 0; k < w; ++k)
        {
            b = std::nextafter(b, 2*line);
        }
        const double top = cliff.highestOver(a, b, y, y);
        for (double x = a; x <= b; x = std::nextafter(x, 2*line))
        {
            ASSERT_LE(cliff.Z(x, y), top) << w << " " << x - line;
        }
    }
}


TEST(terrainRaster, AsciiWriteOfManyRowsIsOneThreadsText)
{
    // Two batches of blocks of rows formatted in parallel and a part of one
    // (a batch: 1,170 blocks of 8 rows of 7 values)
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-1, 1);
    const label nx = 7;
    const label ny = 2*1170*8 + 5;
    scalarList values(nx*ny);
    for (scalar& v : values)
    {
        const scalar r = u(gen);
        v = r < 0 ? 0 : 100*r;
    }
    values[3*nx + 4] = notANumber;
    const terrainRaster nodes
    (
        vector2D(0, 0), 0.5, 0.5, nx, ny, values, vector2D(0, 0)
    );

    std::string text[2];
    for (const int nThreads : {1, 2})
    {
        const threadCount threads(nThreads);
        const fileName file(testDir()/"manyRows.asc");
        nodes.writeAsc(file);
        text[nThreads - 1] = contents(file);
    }
    EXPECT_EQ(text[1], text[0]);

    terrainRaster back
    (
        testDir()/"manyRows.asc", terrainRaster::noDataPolicy::fill
    );
    ASSERT_EQ(back.ny(), ny);
    label same = 0;
    for (label k = 0; k < values.size(); ++k)
    {
        same += k == 3*nx + 4 || back.values()[k] == values[k];
    }
    EXPECT_EQ(same, values.size());
}


TEST(terrainRaster, AsciiWriteIsTheShortestTextOfEachValue)
{
    const scalar inf = std::numeric_limits<scalar>::infinity();
    const scalarList values({0, -0.0, 1.5, notANumber, inf, 0.1});
    const terrainRaster nodes
    (
        vector2D(0, 0), 1, 1, 3, 2, values, vector2D(0, 0)
    );
    const fileName file(testDir()/"text.asc");
    nodes.writeAsc(file);
    const std::string text = contents(file);
    const std::string rows("-9999 -9999 0.1\n0 -0 1.5\n");
    ASSERT_GE(text.size(), rows.size());
    EXPECT_EQ(text.substr(text.size() - rows.size()), rows);
}


TEST(terrainRaster, NorthRowComesFirstInTheFile)
{
    const terrainRaster t
    (
        writeText("small.asc", smallText("xllcorner", "yllcorner"))
    );
    ASSERT_EQ(t.nx(), 3);
    ASSERT_EQ(t.ny(), 2);
    EXPECT_EQ(t.value(0, 1), 1);
    EXPECT_EQ(t.value(2, 1), 3);
    EXPECT_EQ(t.value(0, 0), 4);
    EXPECT_EQ(t.value(2, 0), 6);
    EXPECT_EQ(t.minValue(), 1);
    EXPECT_EQ(t.maxValue(), 6);

    // South-west sample at (11, 21); Z falls northwards by 3 over 2 m
    scalar Z, dZdx, dZdy;
    t.evaluate(11, 21, Z, dZdx, dZdy);
    EXPECT_EQ(Z, 4);
    EXPECT_EQ(dZdx, 0.5);
    EXPECT_EQ(dZdy, -1.5);
    EXPECT_EQ(t.Z(15, 23), 3);
}


TEST(terrainRaster, CornerAndCentreHeadersDifferByHalfACell)
{
    const terrainRaster corner
    (
        writeText("corner.asc", smallText("xllcorner", "yllcorner"))
    );
    // Same values, centre form, upper-case keys, tabs and CRLF
    const terrainRaster centre
    (
        writeText
        (
            "centre.asc",
            "NCOLS\t3\r\nNROWS\t2\r\nXLLCENTER\t10\r\nYLLCENTER\t20\r\n"
            "CELLSIZE\t2\r\n1\t2\t3\r\n4\t5\t6\r\n"
        )
    );
    EXPECT_EQ(corner.x(0), 11);
    EXPECT_EQ(corner.y(0), 21);
    EXPECT_EQ(centre.x(0), 10);
    EXPECT_EQ(centre.y(0), 20);
    EXPECT_EQ(corner.mapLowerLeft(), vector2D(10, 20));
    EXPECT_EQ(centre.mapLowerLeft(), vector2D(9, 19));
    EXPECT_EQ(corner.Z(11, 21), centre.Z(10, 20));

    // dx and dy instead of cellsize
    const terrainRaster dxdy
    (
        writeText
        (
            "dxdy.asc",
            "ncols 3\nnrows 2\nxllcorner 10\nyllcorner 20\ndx 2\ndy 4\n"
            "1 2 3\n4 5 6\n"
        )
    );
    EXPECT_EQ(dxdy.dx(), 2);
    EXPECT_EQ(dxdy.dy(), 4);
    EXPECT_EQ(dxdy.y(1), 26);
}


TEST(terrainRaster, LocalCoordinatesSubtractTheOffset)
{
    const double h = 5;
    const std::string text = ascText
    (
        {
            {"ncols", "4"}, {"nrows", "3"}, {"xllcenter", "1500000"},
            {"yllcenter", "5200000"}, {"cellsize", "5"}
        },
        4, 3,
        [&](int i, int j) { return planar(X0 + i*h, Y0 + j*h); }
    );
    const terrainRaster global(writeText("offset.asc", text));
    terrainRaster local(writeText("offset.asc", text));
    const vector2D offset(X0 - 100, Y0 + 50);
    local.setOffset(offset);

    EXPECT_EQ(global.offset(), vector2D::zero);
    EXPECT_EQ(local.offset(), offset);
    EXPECT_EQ(local.x(0), 100);
    EXPECT_EQ(local.y(0), -50);
    EXPECT_EQ(local.bounds().max(), point(115, -40, local.maxValue()));

    // Map coordinates resolve 1e-10 m at 5e6 m: Z to 1e-9 m
    constexpr double mapTol = 1e-9;
    EXPECT_NEAR(local.Z(107, -43), global.Z(X0 + 7, Y0 + 7), mapTol);
    EXPECT_NEAR(local.Z(107, -43), planar(X0 + 7, Y0 + 7), mapTol);
}


TEST(terrainRaster, ClampsToTheNearestSampleOutsideTheHull)
{
    const terrainRaster t
    (
        writeText("clamp.asc", smallText("xllcenter", "yllcenter"))
    );
    // Samples at x = 10, 12, 14 and y = 20, 22
    scalar Z, dZdx, dZdy;
    t.evaluate(100, 21, Z, dZdx, dZdy);
    EXPECT_EQ(Z, t.Z(14, 21));
    EXPECT_EQ(dZdx, 0);
    EXPECT_EQ(dZdy, -1.5);

    t.evaluate(-100, -100, Z, dZdx, dZdy);
    EXPECT_EQ(Z, 4);
    EXPECT_EQ(dZdx, 0);
    EXPECT_EQ(dZdy, 0);

    t.evaluate(100, 100, Z, dZdx, dZdy);
    EXPECT_EQ(Z, 3);
}


TEST(terrainRaster, AsciiWriteReadRoundTripIsExact)
{
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-1, 1);
    const label nx = 9;
    const label ny = 6;
    scalarList values(nx*ny);
    for (scalar& v : values)
    {
        v = 1000*u(gen);
    }
    values[nx + 2] = notANumber;
    const vector2D offset(1.234567e6, 5.4321e6);

    for (const scalar dy : {0.7, 1.3})
    {
        const terrainRaster nodes
        (
            vector2D(-3.5, 2.25), 0.7, dy, nx, ny, values, offset
        );
        EXPECT_EQ(nodes.nNoData(), 1);
        const fileName file(testDir()/"roundTrip.asc");
        nodes.writeAsc(file);

        terrainRaster back(file, terrainRaster::noDataPolicy::fill);
        back.setOffset(offset);
        ASSERT_EQ(back.nx(), nx);
        ASSERT_EQ(back.ny(), ny);
        EXPECT_EQ(back.dx(), 0.7);
        EXPECT_EQ(back.dy(), dy);
        EXPECT_EQ(back.nNoData(), 1);
        // Map coordinates round to 1e-9 m at 5e6 m
        EXPECT_NEAR(back.x(0), -3.5, 1e-9);
        EXPECT_NEAR(back.y(0), 2.25, 1e-9);
        for (label k = 0; k < values.size(); ++k)
        {
            if (k != nx + 2)
            {
                EXPECT_EQ(back.values()[k], values[k]) << k;
            }
        }
    }
}


TEST(terrainRaster, GeoTiffRoundTripKeepsGeoreferenceAndProjection)
{
    // MGI / Austria Lambert, as a WKT from PROJ's database
    OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
    ASSERT_EQ(OSRImportFromEPSG(srs, 31287), OGRERR_NONE);
    char* wktPtr = nullptr;
    OSRExportToWkt(srs, &wktPtr);
    const string wkt(wktPtr);
    CPLFree(wktPtr);
    OSRDestroySpatialReference(srs);

    const label nx = 8;
    const label ny = 5;
    scalarList values(uniformSamples(nx*ny, 5, 1000, 2000));
    values[3] = notANumber;
    const vector2D offset(X0, Y0);
    const terrainRaster nodes
    (
        vector2D(0, 0), 2.5, 2.5, nx, ny, values, offset, wkt
    );

    // Float32 rounds to 2^-24 relative
    constexpr double float32Tol = 6e-8;
    for (const auto type : {terrainRaster::sampleType::float64,
                            terrainRaster::sampleType::float32})
    {
        const fileName file(testDir()/"roundTrip.tif");
        nodes.writeGeoTiff(file, type);
        terrainRaster back(file, terrainRaster::noDataPolicy::fill);
        back.setOffset(offset);
        ASSERT_EQ(back.nx(), nx);
        ASSERT_EQ(back.ny(), ny);
        EXPECT_EQ(back.dx(), 2.5);
        EXPECT_EQ(back.dy(), 2.5);
        EXPECT_EQ(back.nNoData(), 1);
        EXPECT_NEAR(back.x(0), 0, 1e-9);
        EXPECT_NEAR(back.y(0), 0, 1e-9);
        ASSERT_TRUE(back.hasProjection());
        EXPECT_NE(back.projection().find("31287"), std::string::npos);
        const double tol =
            (type == terrainRaster::sampleType::float64) ? 0 : float32Tol;
        for (label k = 0; k < values.size(); ++k)
        {
            if (k != 3)
            {
                EXPECT_NEAR(back.values()[k], values[k], tol*values[k]);
            }
        }
    }
}


TEST(terrainRaster, AsciiGridAndGeoTiffOfOneRasterReadTheSame)
{
    // One raster written both ways (GeoTIFF as float64) reads back as the
    // same samples and georeference: the two readers share no code but
    // must agree
    const label nx = 7;
    const label ny = 4;
    const scalarList values(uniformSamples(nx*ny, 13, 1000, 2000));
    const vector2D offset(X0 + 0.123456789, Y0 + 0.987654321);
    const terrainRaster nodes
    (
        vector2D(0.25, -0.75), 1.3, 0.7, nx, ny, values, offset
    );
    const fileName asc(testDir()/"agree.asc");
    const fileName tif(testDir()/"agree.tif");
    nodes.writeAsc(asc);
    nodes.writeGeoTiff(tif, terrainRaster::sampleType::float64);

    const terrainRaster a(asc);
    const terrainRaster t(tif);
    ASSERT_EQ(a.nx(), t.nx());
    ASSERT_EQ(a.ny(), t.ny());
    EXPECT_EQ(a.dx(), t.dx());
    EXPECT_EQ(a.dy(), t.dy());
    for (label k = 0; k < values.size(); ++k)
    {
        EXPECT_EQ(a.values()[k], t.values()[k]) << k;
        EXPECT_EQ(a.values()[k], values[k]) << k;
    }
    // The GeoTIFF locates the north-west corner: its lower edge is that
    // minus ny*dy, a few ulps of the map coordinate off the ASCII one
    const double ulps = 4*std::numeric_limits<double>::epsilon();
    EXPECT_EQ(a.mapLowerLeft().x(), t.mapLowerLeft().x());
    EXPECT_NEAR(a.mapLowerLeft().y(), t.mapLowerLeft().y(), ulps*Y0);
}


TEST(terrainRaster, GdalAsciiDriverAgreesOnValidGridsButAcceptsBadOnes)
{
    // Why terrainRaster reads ESRI ASCII grids itself (doc/inputReaders.md):
    // GDAL's AAIGrid driver, asked for Float64, reads the same samples from
    // a valid grid (its default, Float32 once a decimal point is seen, does
    // not), but reads 'abc' as 0 and accepts a negative cell size, which
    // terrainRaster refuses naming the line
    GDALAllRegister();
    const char* const aaigrid[] = {"AAIGrid", nullptr};
    const auto gdalRead = [&](const fileName& file, const bool float64)
    {
        char** options =
            float64 ? CSLSetNameValue(nullptr, "DATATYPE", "Float64") : nullptr;
        GDALDatasetH ds = GDALOpenEx
        (
            file.c_str(), GDAL_OF_RASTER, aaigrid, options, nullptr
        );
        CSLDestroy(options);
        std::vector<double> v;
        if (ds)
        {
            const int nx = GDALGetRasterXSize(ds);
            const int ny = GDALGetRasterYSize(ds);
            v.resize(size_t(nx)*ny);
            if
            (
                GDALRasterIO
                (
                    GDALGetRasterBand(ds, 1), GF_Read, 0, 0, nx, ny, v.data(),
                    nx, ny, GDT_Float64, 0, 0
                ) != CE_None
            )
            {
                v.clear();
            }
            GDALClose(ds);
        }
        return v;
    };

    // Terrain-like decimals; GDAL gives the rows north first
    const int nx = 9;
    const int ny = 6;
    const scalarList z(uniformSamples(nx*ny, 17, 1000, 1300));
    const fileName file = writeText
    (
        "gdal.asc",
        ascText
        (
            {
                {"ncols", "9"}, {"nrows", "6"}, {"xllcorner", "177873.022002"},
                {"yllcorner", "377487.258603"}, {"cellsize", "4.997688906601"}
            },
            nx, ny, [&](int i, int j) { return z[i + nx*j]; }
        )
    );
    const terrainRaster ours(file);
    const std::vector<double> gdal64 = gdalRead(file, true);
    const std::vector<double> gdal32 = gdalRead(file, false);
    ASSERT_EQ(gdal64.size(), size_t(z.size()));
    ASSERT_EQ(gdal32.size(), size_t(z.size()));
    label nFloat32Differ = 0;
    for (int r = 0; r < ny; ++r)
    {
        for (int i = 0; i < nx; ++i)
        {
            const double v = ours.value(i, ny - 1 - r);
            EXPECT_EQ(gdal64[i + nx*r], v) << i << ' ' << r;
            nFloat32Differ += (gdal32[i + nx*r] != v);
        }
    }
    EXPECT_GT(nFloat32Differ, 0);

    const std::string head =
        "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
    const fileName word = writeText("gdalWord.asc", head + "1 2\n3 abc\n");
    EXPECT_EQ(gdalRead(word, true), std::vector<double>({1, 2, 3, 0}));
    EXPECT_NE
    (
        foamIOErrorText([&]{ terrainRaster t(word); }).find("at line 7"),
        std::string::npos
    );
    const fileName negative = writeText
    (
        "gdalNegative.asc",
        "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize -1\n"
        "1 2\n3 4\n"
    );
    EXPECT_EQ(gdalRead(negative, true).size(), 4u);
    EXPECT_NE
    (
        foamIOErrorText([&]{ terrainRaster t(negative); })
            .find("'cellsize' = -1 is invalid"),
        std::string::npos
    );
}


TEST(terrainRaster, NoDataFailNamesFileCountAndFirstCell)
{
    const fileName file = writeText
    (
        "nodata.asc",
        "ncols 4\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 10\n"
        "NODATA_value -9999\n"
        "1 2 3 4\n5 6 -9999.0 8\n9 nan 11 12\n"
    );
    const std::string msg = foamIOErrorText([&]{ terrainRaster t(file); });
    EXPECT_NE(msg.find("file: " + file), std::string::npos) << msg;
    EXPECT_NE(msg.find("has 2 NODATA cells"), std::string::npos) << msg;
    EXPECT_NE(msg.find("row 2, column 3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("(25 15)"), std::string::npos) << msg;
}


TEST(terrainRaster, NoDataFillIsFiniteAndBoundedByNeighbours)
{
    // A hole of 2 x 3 cells touching the west edge and a single cell
    const label nx = 6;
    const label ny = 5;
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(0, 100);
    std::vector<double> z(nx*ny);
    for (double& v : z)
    {
        v = u(gen);
    }
    for (const label k : {nx, nx + 1, 2*nx, 2*nx + 1, 3*nx, 3*nx + 1, 9})
    {
        z[k] = -9999;
    }
    const fileName file = writeText
    (
        "fill.asc",
        ascText
        (
            {
                {"ncols", "6"}, {"nrows", "5"}, {"xllcorner", "0"},
                {"yllcorner", "0"}, {"cellsize", "1"}, {"NODATA_value", "-9999"}
            },
            nx, ny, [&](int i, int j) { return z[i + nx*j]; }
        )
    );
    const terrainRaster t(file, terrainRaster::noDataPolicy::fill);
    EXPECT_EQ(t.nNoData(), 7);

    double validMin = 1e300, validMax = -1e300;
    for (const double v : z)
    {
        if (v != -9999)
        {
            validMin = std::min(validMin, v);
            validMax = std::max(validMax, v);
        }
    }
    for (label j = 0; j < ny; ++j)
    {
        for (label i = 0; i < nx; ++i)
        {
            const double v = t.value(i, j);
            ASSERT_TRUE(std::isfinite(v));
            if (z[i + nx*j] != -9999)
            {
                EXPECT_EQ(v, z[i + nx*j]);
                continue;
            }
            // Within the range of the valid data, and of its own valid
            // neighbours when it has any
            EXPECT_GE(v, validMin);
            EXPECT_LE(v, validMax);
            double lo = 1e300, hi = -1e300;
            for (label jj = max(j - 1, 0); jj <= min(j + 1, ny - 1); ++jj)
            {
                for (label ii = max(i - 1, 0); ii <= min(i + 1, nx - 1); ++ii)
                {
                    const double w = z[ii + nx*jj];
                    if (w != -9999)
                    {
                        lo = std::min(lo, w);
                        hi = std::max(hi, w);
                    }
                }
            }
            if (lo <= hi)
            {
                EXPECT_GE(v, lo) << i << ' ' << j;
                EXPECT_LE(v, hi) << i << ' ' << j;
            }
        }
    }
}


TEST(terrainRaster, MalformedFilesAreRefusedNamingFileAndKey)
{
    const std::string head = "xllcorner 0\nyllcorner 0\ncellsize 1\n";
    const std::string rows = "1 2\n3 4\n";
    struct badFile
    {
        std::string name, text, expected;
    };
    const std::vector<badFile> cases =
    {
        {"noNcols.asc", "nrows 2\n" + head + rows, "header key 'ncols'"},
        {"noCellsize.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\n"
            + rows, "header key 'cellsize'"},
        {"noDy.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ndx 1\n"
            + rows, "header key 'dy'"},
        {"twoNrows.asc", "ncols 2\nnrows 2\nnrows 2\n" + head + rows,
            "duplicate header key 'nrows'"},
        {"cornerCentre.asc", "ncols 2\nnrows 2\n" + head
            + "xllcenter 0\n" + rows, "'xllcenter': 'xllcorner'"},
        {"cellsizeDx.asc", "ncols 2\nnrows 2\n" + head + "dx 1\n" + rows,
            "'dx': 'cellsize'"},
        {"mixed.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcenter 0\n"
            "cellsize 1\n" + rows, "'xllcorner' and 'yllcenter'"},
        {"unknown.asc", "ncols 2\nnrows 2\nfoo 1\n" + head + rows,
            "unknown header key 'foo'"},
        {"noValue.asc", "ncols\nnrows 2\n" + head + rows,
            "'ncols' needs one number"},
        {"zeroNcols.asc", "ncols 0\nnrows 2\n" + head + rows,
            "'ncols' = 0 is invalid"},
        {"negativeNrows.asc", "ncols 2\nnrows -2\n" + head + rows,
            "'nrows' = -2 is invalid"},
        {"fractionNcols.asc", "ncols 2.5\nnrows 2\n" + head + rows,
            "'ncols' = 2.5 is invalid"},
        {"zeroCellsize.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\n"
            "cellsize 0\n" + rows, "'cellsize' = 0 is invalid"},
        {"tooFew.asc", "ncols 2\nnrows 2\n" + head + "1 2\n3\n",
            "too few values: found 3, expected ncols x nrows"},
        {"tooMany.asc", "ncols 2\nnrows 2\n" + head + rows + "5\n",
            "too many values: '5' follows the last of ncols x nrows"},
        {"word.asc", "ncols 2\nnrows 2\n" + head + "1 2\n3 abc\n",
            "value 'abc' (row 2, column 2) is not a number; expected ncols"},
        {"empty.asc", "", "header key 'ncols'"},
        {"allNoData.asc", "ncols 2\nnrows 2\n" + head
            + "NODATA_value -1\n-1 -1\n-1 nan\n", "no valid value"},
        {"text.tif", "not a GeoTIFF\n", "GDAL cannot open the GeoTIFF"},
        {"grid.xyz", "1 2 3\n", "allowed: .asc"},
    };
    for (const badFile& c : cases)
    {
        const fileName file = writeText(c.name, c.text);
        const std::string msg = foamIOErrorText([&]{ terrainRaster t(file); });
        EXPECT_NE(msg.find(c.expected), std::string::npos)
            << c.name << ":\n" << msg;
        EXPECT_NE(msg.find("file: " + file), std::string::npos)
            << c.name << ":\n" << msg;
    }

    // The line of the offending key or value
    const std::string unknown = foamIOErrorText
    (
        [&]{ terrainRaster t(testDir()/"unknown.asc"); }
    );
    EXPECT_NE(unknown.find("at line 3"), std::string::npos) << unknown;
    const std::string word = foamIOErrorText
    (
        [&]{ terrainRaster t(testDir()/"word.asc"); }
    );
    EXPECT_NE(word.find("at line 7"), std::string::npos) << word;
    EXPECT_NE(unknown.find("cellsize (or dx and dy)"), std::string::npos)
        << unknown;

    const fileName missing(testDir()/"missing.asc");
    const std::string msg = foamIOErrorText([&]{ terrainRaster t(missing); });
    EXPECT_NE(msg.find("cannot find the raster file"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("file: " + missing), std::string::npos) << msg;
}


TEST(terrainRaster, ValuesThatAreNotDecimalNumbersAreRefusedWithTheLine)
{
    // strtod read 0x423 as 1059 and 1e400 as inf (a SIGFPE under the
    // solvers' traps): each is refused with its line, row and column
    const solverFpTraps traps;
    const std::string head =
        "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
        "NODATA_value -9999\n";
    struct badValue
    {
        std::string token, expected;
    };
    const std::vector<badValue> cases =
    {
        {"0x423", "is not a number"},
        {"0x1p3", "is not a number"},
        {"12abc", "is not a number"},
        {"1.5.2", "is not a number"},
        {"--1", "is not a number"},
        {"1e400", "is out of range"},
        {"-1e400", "is out of range"},
        {"1e-400", "is out of range"},
        {"inf", "is out of range"},
        {"-Infinity", "is out of range"},
    };
    for (const badValue& c : cases)
    {
        const fileName file =
            writeText("bad.asc", head + "1 2 3\n4 " + c.token + " 6\n");
        const std::string msg =
            foamIOErrorText([&]{ terrainRaster t(file); });
        EXPECT_NE
        (
            msg.find("value '" + c.token + "' (row 2, column 2) "
              + c.expected),
            std::string::npos
        ) << msg;
        EXPECT_NE(msg.find("file: " + file + " at line 8"), std::string::npos)
            << msg;
    }

    // Header values likewise
    const std::string msg = foamIOErrorText
    (
        [&]
        {
            terrainRaster t(writeText("badHead.asc", "ncols 0x3\n" + rows2x3));
        }
    );
    EXPECT_NE(msg.find("'ncols' needs one number"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no hexadecimal"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at line 1"), std::string::npos) << msg;
}


TEST(terrainRaster, DecimalFormsAndNaNAreRead)
{
    // A leading + and the short forms are numbers; nan is NODATA whether
    // or not the header declares it (GIS exports write NaN for NODATA)
    const solverFpTraps traps;
    const std::string head =
        "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
    const terrainRaster forms
    (
        writeText("forms.asc", head + "+5 .5 5.\n-.5e1 1E2 -0\n")
    );
    EXPECT_EQ(forms.value(0, 1), 5);
    EXPECT_EQ(forms.value(1, 1), 0.5);
    EXPECT_EQ(forms.value(2, 1), 5);
    EXPECT_EQ(forms.value(0, 0), -5);
    EXPECT_EQ(forms.value(1, 0), 100);
    EXPECT_EQ(forms.value(2, 0), 0);

    for (const std::string noData : {"", "NODATA_value nan\n"})
    {
        const terrainRaster t
        (
            writeText("nan.asc", head + noData + "1 nan 3\n-nan NaN 6\n"),
            terrainRaster::noDataPolicy::fill
        );
        EXPECT_EQ(t.nNoData(), 3) << noData;
        // Filled from its valid neighbours 1, 3 and 6
        EXPECT_DOUBLE_EQ(t.value(1, 1), 10.0/3) << noData;
    }
}


TEST(terrainRaster, ValuesBeyondTheCallersBoundAreRefused)
{
    const solverFpTraps traps;
    const fileName file = writeText
    (
        "huge.asc",
        "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n"
        "NODATA_value -3.4e38\n1 -3.4e38\n1e300 4\n"
    );

    // No bound by default: any finite number is a value
    EXPECT_EQ
    (
        terrainRaster(file, terrainRaster::noDataPolicy::fill).maxValue(),
        1e300
    );

    // The topography's bound: refused with the line; the NODATA value,
    // beyond the bound too, is still NODATA
    const std::string msg = foamIOErrorText
    (
        [&]{ terrainRaster t(file, terrainRaster::noDataPolicy::fill, 1e6); }
    );
    EXPECT_NE(msg.find("value '1e300' (row 2, column 1) is out of range;"
        " allowed: a finite number with |value| <= 1000000"), std::string::npos)
        << msg;
    EXPECT_NE(msg.find("NODATA_value (-3.4e+38)"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at line 8"), std::string::npos) << msg;
}


TEST(terrainRaster, GeoTiffWithNaNNoDataIsReadUnderTheSolversTraps)
{
    // A float32 GeoTIFF with NODATA NaN, as GIS exports write them, and a
    // NaN cell: a SIGFPE inside GDAL before, with the traps on
    const solverFpTraps traps;
    const label nx = 4;
    const label ny = 3;
    const fileName file(testDir()/"nanNoData.tif");
    {
        // Written through GDAL with the traps masked: the writer is not
        // under test
        fpTrapsHeld masked;
        GDALAllRegister();
        GDALDatasetH ds = GDALCreate
        (
            GDALGetDriverByName("GTiff"), file.c_str(), nx, ny, 1,
            GDT_Float32, nullptr
        );
        ASSERT_TRUE(ds);
        double gt[6] = {X0, 2, 0, Y0 + 2*ny, 0, -2};
        GDALSetGeoTransform(ds, gt);
        GDALRasterBandH band = GDALGetRasterBand(ds, 1);
        GDALSetRasterNoDataValue(band, notANumber);
        // Rows north to south; NaN at row 2, column 3
        float v[nx*ny] = {1, 2, 3, 4, 5, 6, 0, 8, 9, 10, 11, 12};
        v[nx + 2] = std::numeric_limits<float>::quiet_NaN();
        EXPECT_EQ
        (
            GDALRasterIO
            (
                band, GF_Write, 0, 0, nx, ny, v, nx, ny, GDT_Float32, 0, 0
            ),
            CE_None
        );
        GDALClose(ds);
    }

    const std::string msg = foamIOErrorText([&]{ terrainRaster t(file); });
    EXPECT_NE(msg.find("has 1 NODATA cells"), std::string::npos) << msg;
    EXPECT_NE(msg.find("row 2, column 3"), std::string::npos) << msg;
    EXPECT_NE(msg.find("file: " + file), std::string::npos) << msg;

    const terrainRaster filled(file, terrainRaster::noDataPolicy::fill);
    EXPECT_EQ(filled.nNoData(), 1);
    // The average of its 8 neighbours 2 3 4 6 8 10 11 12
    EXPECT_EQ(filled.value(2, 1), 7);

    const terrainRaster zero(file, terrainRaster::noDataPolicy::zero);
    EXPECT_EQ(zero.value(2, 1), 0);
    EXPECT_EQ(zero.minValue(), 0);
    EXPECT_EQ(zero.value(3, 1), 8);
}


TEST(terrainRaster, NoDataReadAsZeroKeepsTheBlockVolume)
{
    // A release drawn as a 2 m block in NODATA: sum(h) dx dy, and the
    // bilinear interpolant integrates to it (midpoint sums on a lattice
    // whose cells lie between the samples are exact)
    const solverFpTraps traps;
    const fileName file = writeText
    (
        "block.asc",
        ascText
        (
            {
                {"ncols", "8"}, {"nrows", "6"}, {"xllcorner", "0"},
                {"yllcorner", "0"}, {"cellsize", "1"}, {"NODATA_value", "-9999"}
            },
            8, 6,
            [](int i, int j)
            {
                return (i >= 2 && i < 5 && j >= 1 && j < 4) ? 2.0 : -9999.0;
            }
        )
    );
    const terrainRaster t(file, terrainRaster::noDataPolicy::zero);
    EXPECT_EQ(t.nNoData(), 48 - 9);
    double volume = 0;
    const label n = 4;
    for (label j = 0; j < 6*n; ++j)
    {
        for (label i = 0; i < 8*n; ++i)
        {
            volume += t.Z((i + 0.5)/n, (j + 0.5)/n)/(n*n);
        }
    }
    EXPECT_EQ(volume, 2.0*9);
}


TEST(terrainRaster, RealHillsideKotHasNoNoData)
{
    const fileName file("/work/shared/data/terrain/hillsideKot600m.asc");
    if (!isFile(file))
    {
        GTEST_SKIP() << file << " not found";
    }
    terrainRaster t(file);
    t.setOffset(t.mapLowerLeft());
    EXPECT_EQ(t.nx(), 120);
    EXPECT_EQ(t.ny(), 120);
    EXPECT_EQ(t.dx(), 4.997688906601);
    EXPECT_EQ(t.nNoData(), 0);
    EXPECT_NEAR(t.mapLowerLeft().x(), 177873.022002, 1e-9);
    EXPECT_NEAR(t.mapLowerLeft().y(), 377487.258603, 1e-9);
    // README: about 1066 m to 1290 m
    EXPECT_GT(t.minValue(), 1000);
    EXPECT_LT(t.maxValue(), 1350);
    // A north-facing slope: lower in the north
    EXPECT_LT(t.Z(300, 550), t.Z(300, 150));
}


// ************************************************************************* //
