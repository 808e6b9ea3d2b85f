/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    particleGuard, the particles' last guard (stopEntries), at each
    geometry on a grid of 0.1 x 0.15 x 0.2 m cells (barrierProbe.H):
    - box from (0.42 0.3 0.2) to (0.58 0.9 0.8): a particle entering
      through a face is put back on that face, with its velocity into it
      removed (slip); a wall thinner than the grid's nodes (no node
      inside, 4 cm between the node planes 0.5 and 0.6) holds by the guard
      alone; and particles lying against a face, outside, are cleared by
      the screen (none tested exactly);
    - inclined plane (normal (1 -2 2)): a particle that enters in a step is
      put back on the plane, at its end point projected along n (to 2^-30
      of its move: the bisection), and loses its velocity into the plane by
      the contact condition (slip, Coulomb); the force is the momentum
      taken, m (u - u_new)/dt. Particles that start inside, or end
      outside, are left alone;
    - terrain: the guard acts half a cell (of the smallest cell size) below
      the surface: a particle that dips less deep is left to the node
      contact, one that goes deeper is put back at that depth, along the
      normal, and loses its velocity into the terrain;
    - terrains screened by their highest elevation over each column of
      cells (a raster, a flat and an expression terrain, the last by its
      interval bounds; a column without a bound tested exactly): particles
      lying just above are not tested, and of 20,000 random moves every
      entry the exact test finds is stopped, the others left alone; on
      the four parts of a decomposed grid, the same stops bit for bit and
      the same screen; a raster terrain's exact test (one evaluation of
      the raster a point) is the topography's formula bit for bit;
    - triSurface (the box of surfaceCase.H): a particle entering through
      the top face is put back on it and loses its velocity into it (slip;
      Coulomb with mu = 0.1 halves its 0.2 m/s along the face against
      1 m/s into it); and 40,000 particles moved at random by up to a
      cell, in and around it: every one that entered is put back, not
      inside, the others are left alone, and two threads
      give what one gives, bit for bit (the screen by the cells' corners
      and the octree queried from both threads); a path through the first
      of two cubes into the second stops at the first face it met (the
      octree's first crossing of the path, where a bisection would stop at
      the second).

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include "surfaceCase.H"
#include "threadCount.H"
#include "scratchDir.H"
#include "terrainGeometry.H"
#include "OSspecific.H"
#include "DynamicField.H"
#include <gtest/gtest.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>

using namespace Foam;

namespace
{

const std::string boxWall
(
    "type box; min (0.42 0.3 0.2); max (0.58 0.9 0.8); contact slip;"
);

//- The inclined plane: a point, its unit normal and a unit vector along it
const point o(0.43, 0.61, 0.55);
const vector np = vector(1, -2, 2)/3;
const vector t = vector(2, 2, 1)/3;

std::string inclinedPlane(const std::string& contact)
{
    return "type plane; point (0.43 0.61 0.55); normal (1 -2 2); contact "
      + contact + ";";
}

//- The terrain Z = 0.3 + 0.2 x - 0.1 y and its unit normal
std::string terrain(const std::string& Z)
{
    return "type terrain; topography expression; expressionCoeffs { Z \""
      + Z + "\"; } contact slip;";
}

const double norm = std::sqrt(1 + 0.04 + 0.01);
const vector nt = vector(-0.2, 0.1, 1)/norm;


//- n particles within 0.1 m of the box of surfaceCase.H, (0.375 0.375
//  0.25)-(0.625 0.75 0.875), moved by up to about a cell in a step of
//  1 ms: start x0, end x1, velocity v0 (random, from seed)
void movesAroundTheBox
(
    const label n,
    const unsigned seed,
    pointField& x0,
    pointField& x1,
    vectorField& v0
)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    x0.setSize(n);
    x1.setSize(n);
    v0.setSize(n);
    for (label i = 0; i < n; ++i)
    {
        x0[i] = point
        (
            0.5 + 0.225*u(rng), 0.5625 + 0.2875*u(rng), 0.5625 + 0.4125*u(rng)
        );
        const vector move(0.06*u(rng), 0.09*u(rng), 0.12*u(rng));
        x1[i] = x0[i] + move;
        v0[i] = move/1e-3;
    }
}

} // End anonymous namespace


TEST(particleGuard, EnteringParticleStopsOnTheBoxFaceItCrossed)
{
    barrierProbe probe(boxWall);
    const point x0(0.38, 0.6, 0.5), x1(0.45, 0.62, 0.51);
    point x = x1;
    vector u(2, 0.5, 0.1), F;
    EXPECT_TRUE(probe.entry(x0, x, u, 0.01, 1e-3, F));
    // Bisection to 2^-30 of the move
    EXPECT_LT(mag(x - point(0.42, 0.62, 0.51)), 1e-9*mag(x1 - x0));
    EXPECT_GE(probe.distance(x), 0);
    EXPECT_EQ(u, vector(0, 0.5, 0.1));
    EXPECT_LT(mag(F - vector(0.01*2/1e-3, 0, 0)), 1e-12);
}


TEST(particleGuard, WallThinnerThanTheNodesHoldsByTheGuard)
{
    barrierProbe probe
    (
        "type box; min (0.52 0.3 0.2); max (0.56 0.9 0.8); contact slip;"
    );
    // No node inside: no node contact, no pressure
    vector F;
    scalar p;
    const vector v(-1, 0, 0);
    for (const label i : {5, 6})
    {
        EXPECT_EQ(probe.contact(i, 4, 2, 1, v, 1e-3, F, p), v);
        EXPECT_EQ(p, 0);
    }
    const point x0(0.58, 0.6, 0.5), x1(0.54, 0.6, 0.5);
    point x = x1;
    vector u(-3, 0, 0.2);
    EXPECT_TRUE(probe.entry(x0, x, u, 0.01, 1e-3, F));
    EXPECT_LT(mag(x - point(0.56, 0.6, 0.5)), 1e-9*mag(x1 - x0));
    EXPECT_EQ(u, vector(0, 0, 0.2));
}


TEST(particleGuard, EnteringParticleStopsOnThePlane)
{
    const scalar m = 0.01, dt = 1e-3;
    const point x0 = o + 0.02*np - 0.03*t;
    const point x1 = o - 0.03*np + 0.01*t;
    const vector u = -2*np + t;
    // Bisection to 2^-30 of the move
    const scalar tol = 1e-9*mag(x1 - x0);

    for (const auto& c : {std::make_pair(word("slip"), 0.0),
         std::make_pair(word("Coulomb"), 0.2)})
    {
        barrierProbe probe
        (
            inclinedPlane(c.first + "; frictionCoefficient 0.2")
        );
        point x = x1;
        vector v = u, F;
        EXPECT_TRUE(probe.entry(x0, x, v, m, dt, F)) << c.first;
        EXPECT_LT(mag(x - (x1 + 0.03*np)), tol) << c.first;
        EXPECT_GE(probe.distance(x), 0) << c.first;
        const vector expected = contactVelocity(u, np, c.first, c.second);
        EXPECT_LT(mag(v - expected), 1e-15) << c.first;
        EXPECT_LT(mag(F - m*(u - expected)/dt), 1e-12) << c.first;
    }
    // Coulomb's worked value: 1 m/s along, 2 m/s into it, mu 0.2
    EXPECT_LT(mag(contactVelocity(u, np, "Coulomb", 0.2) - 0.6*t), 1e-15);
}


TEST(particleGuard, ParticlesThatDoNotEnterAreLeftAlone)
{
    barrierProbe probe(inclinedPlane("noSlip"));
    const vector u = -2*np + t;
    // Inside at the start; outside at the end
    const std::pair<point, point> moves[] =
    {
        {o - 0.01*np, o - 0.04*np + 0.01*t},
        {o + 0.05*np, o + 0.01*np + 0.01*t}
    };
    for (const auto& move : moves)
    {
        point x = move.second;
        vector v = u, F;
        EXPECT_FALSE(probe.entry(move.first, x, v, 0.01, 1e-3, F));
        EXPECT_EQ(x, move.second);
        EXPECT_EQ(v, u);
        EXPECT_EQ(F, vector(Zero));
    }
}


// The screen: particles lying 0.03 m above the box's top face (a node
// plane, z = 0.8; cells 0.2 m high) and sliding along it are cleared by the
// corners of their cell 0.2 m above the face, none tested exactly (their
// nearest node, on the face, would clear none); the same particles 0.03 m
// below the face, inside, are all tested
TEST(particleGuard, ScreenClearsParticlesLyingAgainstAFace)
{
    barrierProbe probe(boxWall);
    constexpr label n = 400;
    for (const scalar dz : {0.03, -0.03})
    {
        pointField x0(n), x(n);
        vectorField u(n, vector(5, 0, 0));
        for (label i = 0; i < n; ++i)
        {
            x0[i] = point
            (
                0.43 + 0.13*(i%20)/19, 0.31 + 0.58*(i/20)/19, 0.8 + dz
            );
            x[i] = x0[i] + vector(0.005, 0, 0);
        }
        vector F;
        EXPECT_EQ(probe.entries(x0, x, u, 0.01, 1e-3, F), 0) << dz;
        EXPECT_EQ(probe.wall().guard().nTested(), dz > 0 ? 0 : n) << dz;
    }
}


TEST(particleGuard, TerrainGuardStopsParticlesHalfACellBelowTheSurface)
{
    barrierProbe probe(terrain("0.3 + 0.2*x - 0.1*y"));
    const scalar depth = 0.5*probe.grid().hMin();
    const point s(0.5, 0.6, 0.3 + 0.2*0.5 - 0.1*0.6);
    const vector along(0.1, 0, 0.02);
    const vector u = -nt + vector(0.5, 0, 0.1);

    // Half as deep: not stopped
    point x = s - 0.5*depth*nt + along;
    vector v = u, F;
    EXPECT_FALSE(probe.entry(s + 0.01*nt, x, v, 0.01, 1e-3, F));
    EXPECT_EQ(v, u);

    // Twice as deep: back at the guard's depth, along n
    const point x0 = s + 0.01*nt, x1 = s - 2*depth*nt + along;
    x = x1;
    EXPECT_TRUE(probe.entry(x0, x, v, 0.01, 1e-3, F));
    // Bisection to 2^-30 of the move, and the terrain's round-off
    const scalar tol = 1e-9*mag(x1 - x0) + 1e-12;
    EXPECT_LT(mag(x - (x1 + depth*nt)), tol);
    EXPECT_NEAR(probe.distance(x), -depth, tol);
    EXPECT_LT(mag(v - contactVelocity(u, nt, "slip")), 1e-12);
}


namespace
{

// A terrain's guard screened by columns: 400 particles lying dz above the
// terrain and sliding along it, none entering; how many were tested
// exactly
label testedLyingAt
(
    barrierProbe& probe,
    const topographyModel& terrain,
    const scalar dz
)
{
    constexpr label n = 400;
    pointField x0(n), x(n);
    vectorField u(n, vector(0.5, 0, 0));
    for (label i = 0; i < n; ++i)
    {
        const scalar px = 0.02 + 0.9*(i%20)/19, py = 0.02 + 1.1*(i/20)/19;
        x0[i] = point(px, py, terrain.Z(px, py) + dz);
        x[i] = point(px + 0.005, py, terrain.Z(px + 0.005, py) + dz);
    }
    vector F;
    EXPECT_EQ(probe.entries(x0, x, u, 0.01, 1e-3, F), 0) << dz;
    return probe.wall().guard().nTested();
}


//- What randomEntries found
struct randomEntriesResult
{
    label tested;
    label offGrid;
};


// 20,000 particles within 0.1 m of the terrain moved at random by up to a
// cell (some beyond the grid's sides): every one that ends deeper than the
// guard's depth from a start that is not (the exact test, deeperThan) is
// stopped, more than 1000 of them, and the others are left alone
randomEntriesResult randomEntries
(
    barrierProbe& probe,
    const topographyModel& terrain,
    const unsigned seed
)
{
    constexpr label n = 20000;
    const scalar depth = 0.5*probe.grid().hMin();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    pointField x0(n), x1(n);
    vectorField v0(n);
    label offGrid = 0;
    for (label i = 0; i < n; ++i)
    {
        const scalar px = 0.5 + 0.48*u(rng), py = 0.6 + 0.58*u(rng);
        x0[i] = point(px, py, terrain.Z(px, py) + 0.1*u(rng));
        const vector move(0.1*u(rng), 0.15*u(rng), 0.2*u(rng));
        x1[i] = x0[i] + move;
        v0[i] = move/1e-3;
        offGrid += x1[i].x() < 0 || x1[i].x() > 1 || x1[i].y() < 0
            || x1[i].y() > 1.2;
    }
    boolList deep0, deep1;
    probe.geometry().deeperThan(x0, depth, deep0);
    probe.geometry().deeperThan(x1, depth, deep1);
    label nEntered = 0;
    forAll(x0, i)
    {
        nEntered += !deep0[i] && deep1[i];
    }
    pointField x(x1);
    vectorField v(v0);
    vector F;
    EXPECT_EQ(probe.entries(x0, x, v, 0.01, 1e-3, F), nEntered);
    EXPECT_GT(nEntered, 1000);
    forAll(x, i)
    {
        EXPECT_EQ(x[i] != x1[i], !deep0[i] && deep1[i]) << i;
    }
    return {probe.wall().guard().nTested(), offGrid};
}


//- dir/name: a raster of Z(x, y) sampled every 0.05 m from (-0.025
//  -0.025), 22 x 26 samples over the probes' grid (local coordinates the
//  map's)
template<class Function>
void writeRaster(const fileName& dir, const word& name, const Function& Z)
{
    mkDir(dir);
    std::ofstream os(dir/name);
    os.precision(17);
    os  << "ncols 22\nnrows 26\nxllcorner -0.05\nyllcorner -0.05\n"
        << "cellsize 0.05\n";
    for (int j = 25; j >= 0; --j)
    {
        for (int i = 0; i < 22; ++i)
        {
            os  << (i ? " " : "") << Z(-0.025 + 0.05*i, -0.025 + 0.05*j);
        }
        os  << "\n";
    }
}


//- The terrain of a probe's terrain barrier
const topographyModel& terrainOf(const barrierProbe& probe)
{
    return dynamic_cast<const barrierGeometries::terrainGeometry&>
    (
        probe.geometry()
    ).topography();
}

} // End anonymous namespace


// A raster terrain, screened by the highest elevation of each column of
// cells: particles lying 0.01 m above its gentle slope are cleared without
// an exact test, those 0.07 m below (deeper than the guard's 0.05 m) all
// tested; and of 20,000 random moves about the surface (randomEntries;
// some beyond the grid's sides, where the terrain rises past the edge
// columns' tops: tested exactly) every entry is stopped, the screen
// clearing some of them
TEST(particleGuard, RasterTerrainScreenedByColumnsStopsEveryEntry)
{
    const auto Zexact = [](const double x, const double y)
    {
        return 0.5 + 0.1*x - 0.05*y + 0.01*std::sin(7*x)*std::cos(5*y);
    };
    const fileName dir(scratchDir("particleGuardRaster"));
    writeRaster(dir, "gentle.asc", Zexact);
    barrierProbe probe
    (
        "type terrain; topography raster; rasterCoeffs { file gentle.asc;"
        " offset (0 0); } contact slip;",
        dir
    );
    const topographyModel& terrain = terrainOf(probe);
    EXPECT_EQ(testedLyingAt(probe, terrain, 0.01), 0);
    EXPECT_EQ(testedLyingAt(probe, terrain, -0.07), 400);
    EXPECT_LT(randomEntries(probe, terrain, 23).tested, 20000);
}


// A raster terrain's deeperThan (one evaluation of the raster a point)
// answers as the topography's Z() and gradient() do, bit for bit: deeper
// than d where z - Z < -d and (z - Z)/sqrt(1 + |grad Z|^2) < -d. On a
// steep slope many points are deeper than d vertically and not along the
// normal; points within 1e-12 m of either threshold, beyond each side of
// the raster and with coordinates that are not finite are tested
TEST(particleGuard, RasterTerrainDeeperThanIsTheTopographysFormula)
{
    const fileName dir(scratchDir("particleGuardDeeper"));
    writeRaster
    (
        dir, "steep.asc",
        [](const double x, const double y)
        {
            return 0.2 + 1.5*x - 0.8*y + 0.05*std::sin(13*x)*std::cos(9*y);
        }
    );
    const autoPtr<barrierGeometry> geometry
    (
        readGeometry
        (
            "type terrain; topography raster; rasterCoeffs { file steep.asc;"
            " offset (0 0); }",
            dir
        )
    );
    const topographyModel& Z =
        dynamic_cast<const barrierGeometries::terrainGeometry&>(*geometry)
       .topography();
    ASSERT_TRUE(Z.raster());

    // The topography's sqrt(1 + |grad Z|^2)
    const auto norm = [&](const scalar x, const scalar y)
    {
        const vector2D grad = Z.gradient(x, y);
        return std::sqrt(1 + sqr(grad.x()) + sqr(grad.y()));
    };

    constexpr label n = 40000;
    const scalar depth = 0.02;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    DynamicField<point> points(n);
    for (label i = 0; i < n; ++i)
    {
        const scalar x = 1.05*u(rng) - 0.04, y = 1.25*u(rng) - 0.04;
        // Below the surface by up to twice the depth along the normal, a
        // quarter of them within 1e-12 m of a threshold
        scalar dz = -2*depth*norm(x, y)*u(rng);
        if (i % 4 == 1)
        {
            dz = -depth*norm(x, y) + 1e-12*(2*u(rng) - 1);
        }
        else if (i % 4 == 2)
        {
            dz = -depth + 1e-12*(2*u(rng) - 1);
        }
        points.append(point(x, y, Z.Z(x, y) + dz));
    }

    // Beyond every side of the raster (clamped), and not finite
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    const scalar inf = std::numeric_limits<scalar>::infinity();
    for
    (
        const point& x
      : {
            point(-0.5, 0.6, 0), point(1.7, 0.6, 0), point(0.5, -0.4, 0),
            point(0.5, 1.9, 0), point(2, 2, 0), point(nan, 0.6, 0),
            point(0.5, inf, 0), point(-inf, 0.6, 0), point(0.5, 0.6, nan)
        }
    )
    {
        for (const scalar dz : {-0.5, -0.01, 0.5})
        {
            points.append(point(x.x(), x.y(), x.z() + Z.Z(x.x(), x.y()) + dz));
        }
    }

    // The formula's answers
    boolList expected(points.size());
    label verticalOnly = 0, deeper = 0;
    forAll(points, i)
    {
        const point& p = points[i];
        const scalar vertical = p.z() - Z.Z(p.x(), p.y());
        expected[i] = vertical < -depth && vertical/norm(p.x(), p.y()) < -depth;
        verticalOnly += vertical < -depth && !expected[i];
        deeper += expected[i];
    }
    EXPECT_GT(verticalOnly, n/20);
    EXPECT_GT(deeper, n/5);

    boolList in;
    geometry->deeperThan(points, depth, in);
    ASSERT_EQ(in.size(), points.size());
    label differing = 0;
    forAll(points, i)
    {
        differing += in[i] != expected[i];
    }
    EXPECT_EQ(differing, 0);
}


// A flat terrain at z = 0.4, screened by its columns (the same height
// everywhere): particles 0.01 m above it are cleared, 0.07 m below all
// tested; of 20,000 random moves (randomEntries), more than 100 ending
// beyond the grid's sides (no column: tested exactly), every entry is
// stopped
TEST(particleGuard, FlatTerrainScreenedByColumnsAlsoOffTheGrid)
{
    barrierProbe probe
    (
        "type terrain; topography flat; flatCoeffs { Z0 0.4; } contact slip;"
    );
    const topographyModel& terrain = terrainOf(probe);
    EXPECT_EQ(testedLyingAt(probe, terrain, 0.01), 0);
    EXPECT_EQ(testedLyingAt(probe, terrain, -0.07), 400);
    EXPECT_GT(randomEntries(probe, terrain, 29).offGrid, 100);
}


// An expression terrain, screened by its bounds over each column (interval
// arithmetic, scalarExpression::bounds): a kinked, wavy slope clears
// particles 0.01 m above it and tests all those 0.07 m below, and of
// 20,000 random moves (randomEntries) every entry is stopped. With a
// square root whose domain a column straddles (no bound there: that
// column's particles tested, the others cleared), the same
TEST(particleGuard, ExpressionTerrainScreenedByItsBounds)
{
    const std::string wave(" + 0.01*sin(9*x)*cos(7*y)");
    barrierProbe kinked
    (
        terrain
        (
            "x <= 0.5 ? 0.3 + 0.2*x - 0.1*y" + wave
          + " : 0.35 + 0.1*x - 0.1*y" + wave
        )
    );
    EXPECT_EQ(testedLyingAt(kinked, terrainOf(kinked), 0.01), 0);
    EXPECT_EQ(testedLyingAt(kinked, terrainOf(kinked), -0.07), 400);
    EXPECT_LT(randomEntries(kinked, terrainOf(kinked), 31).tested, 20000);

    barrierProbe rooted
    (
        terrain("x < 0.43 ? 0.4 - 0.1*y : 0.4 - 0.1*y + 0.1*sqrt(x - 0.43)")
    );
    const label tested = testedLyingAt(rooted, terrainOf(rooted), 0.01);
    EXPECT_GT(tested, 0);
    EXPECT_LT(tested, 100);
    EXPECT_LT(randomEntries(rooted, terrainOf(rooted), 37).tested, 20000);
}


// A terrain's guard on the four parts of a decomposed grid (2 x 2 x 1
// processors, gridGeometry's offset as mpmGrid sets it): each part's
// particles (those that start in its cells) of 20,000 random moves end
// where the whole grid puts them, bit for bit, and those whose move stays
// in their part's columns are tested exactly as often as on the whole
// grid (the same column screen; a move leaving the part's columns is
// tested exactly), for a raster, a flat and an expression terrain
TEST(particleGuard, TerrainScreenOnAProcessorsPartIsTheWholeGrids)
{
    const fileName dir(scratchDir("particleGuardParts"));
    writeRaster
    (
        dir, "wavy.asc",
        [](const double x, const double y)
        {
            return 0.5 + 0.1*x - 0.05*y + 0.02*std::sin(11*x + 3*y);
        }
    );
    const gridGeometry whole(probeGrid());
    const gridGeometry parts[4] =
    {
        partOf(whole, {0, 0}, {4, 5}), partOf(whole, {4, 0}, {6, 5}),
        partOf(whole, {0, 5}, {4, 3}), partOf(whole, {4, 5}, {6, 3})
    };
    // The part whose cells hold a point's column, -1 off the grid
    const auto owner = [&](const point& x)
    {
        const double xi = whole.local(0, x.x()), eta = whole.local(1, x.y());
        for (int k = 0; k < 4; ++k)
        {
            const gridGeometry& g = parts[k];
            if
            (
                xi >= g.offset[0] && xi < g.offset[0] + g.nCells[0]
             && eta >= g.offset[1] && eta < g.offset[1] + g.nCells[1]
            )
            {
                return k;
            }
        }
        return -1;
    };

    for
    (
        const std::string& text
      : {
            std::string
            (
                "type terrain; topography raster; rasterCoeffs { file wavy.asc;"
                " offset (0 0); } contact slip;"
            ),
            std::string
            (
                "type terrain; topography flat; flatCoeffs { Z0 0.4; }"
                " contact slip;"
            ),
            terrain("x <= 0.5 ? 0.3 + 0.2*x - 0.1*y : 0.35 + 0.1*x - 0.1*y")
        }
    )
    {
        barrierProbe all(text, dir, noWalls, whole);
        const topographyModel& Z = terrainOf(all);
        constexpr label n = 20000;
        std::mt19937_64 rng(43);
        std::uniform_real_distribution<double> u(-1, 1);
        pointField x0(n), x1(n);
        vectorField v0(n);
        for (label i = 0; i < n; ++i)
        {
            const scalar px = 0.5 + 0.48*u(rng), py = 0.6 + 0.58*u(rng);
            x0[i] = point(px, py, Z.Z(px, py) + 0.1*u(rng));
            x1[i] = x0[i] + vector(0.1*u(rng), 0.15*u(rng), 0.2*u(rng));
            v0[i] = (x1[i] - x0[i])/1e-3;
        }
        pointField x(x1);
        vectorField v(v0);
        vector F;
        const label nEntered = all.entries(x0, x, v, 0.01, 1e-3, F);
        EXPECT_GT(nEntered, 1000) << text;

        // Whole and parts, every move and the moves that stay
        labelList staying;
        forAll(x0, i)
        {
            if (owner(x1[i]) == owner(x0[i]))
            {
                staying.append(i);
            }
        }
        EXPECT_GT(staying.size(), n/2) << text;
        {
            pointField sx(x1, staying);
            vectorField sv(v0, staying);
            all.entries(pointField(x0, staying), sx, sv, 0.01, 1e-3, F);
        }
        const label stayingTested = all.wall().guard().nTested();

        label partsEntered = 0, partsTested = 0, nChecked = 0;
        for (int k = 0; k < 4; ++k)
        {
            barrierProbe part(text, dir, noWalls, parts[k]);
            labelList mine, mineStaying;
            forAll(x0, i)
            {
                if (owner(x0[i]) == k)
                {
                    mine.append(i);
                    if (owner(x1[i]) == k)
                    {
                        mineStaying.append(i);
                    }
                }
            }
            pointField px(x1, mine);
            vectorField pv(v0, mine);
            partsEntered +=
                part.entries(pointField(x0, mine), px, pv, 0.01, 1e-3, F);
            forAll(mine, m)
            {
                EXPECT_TRUE(px[m] == x[mine[m]] && pv[m] == v[mine[m]])
                    << text << " " << mine[m];
            }
            nChecked += mine.size();

            pointField sx(x1, mineStaying);
            vectorField sv(v0, mineStaying);
            part.entries(pointField(x0, mineStaying), sx, sv, 0.01, 1e-3, F);
            partsTested += part.wall().guard().nTested();
        }
        EXPECT_EQ(nChecked, n) << text;
        EXPECT_EQ(partsEntered, nEntered) << text;
        EXPECT_EQ(partsTested, stayingTested) << text;
        EXPECT_LT(stayingTested, staying.size()) << text;
    }
}


TEST(particleGuard, EnteringParticleStopsOnTheSurfaceFaceItCrossed)
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
        // The entry, to 2^-30 of the move
        EXPECT_LT(mag(x - point(0.5, 0.57, 0.875)), 1e-9*mag(x1 - x0))
            << c.first;
        EXPECT_LT(mag(v - c.second), 1e-15) << c.first;
        EXPECT_LT(mag(F - 0.01*(u - c.second)/1e-3), 1e-12) << c.first;
    }
}


TEST(particleGuard, PathThroughTwoPartsStopsAtTheFirstItEntered)
{
    // Through the first cube of twoBoxes.stl (in by its face x = 0.25 at
    // a tenth of the path, out), across the gap, into the second: put
    // back on the first face met, its end point projected on that face's
    // plane, and its velocity along x removed (slip). (A bisection's
    // first midpoint lies in the gap, outside: it would stop the particle
    // at the second cube)
    const surfaceCase surfaces;
    barrierProbe probe
    (
        "type triSurface; file twoBoxes.stl; contact slip;", surfaces.dir()
    );
    const point x0(0.2, 0.3, 0.29), x1(0.7, 0.65, 0.65);
    ASSERT_GT(probe.distance(x0), 0);
    ASSERT_LT(probe.distance(x1), 0);
    ASSERT_GT(probe.distance(0.5*(x0 + x1)), 0);
    point x = x1;
    vector v = (x1 - x0)/1e-3, F;
    EXPECT_TRUE(probe.entry(x0, x, v, 0.01, 1e-3, F));
    EXPECT_LT(mag(x - point(0.25, 0.65, 0.65)), 1e-9*mag(x1 - x0));
    EXPECT_LT(mag(v - vector(0, 350, 360)), 1e-9);
}


TEST(particleGuard, PathLeavingOnePartIntoAnotherStopsAtTheOther)
{
    // From just outside the first cube of twoBoxes.stl (one ulp beyond its
    // face x = 0.4375, which the path leaves) into the second, entered by
    // its face y = 0.5625: the crossing next to the start is an exit, not
    // an entry, so the particle is put back on the second cube's face
    const surfaceCase surfaces;
    barrierProbe probe
    (
        "type triSurface; file twoBoxes.stl; contact slip;", surfaces.dir()
    );
    const point x0(std::nextafter(0.4375, 1.0), 0.3, 0.3), x1(0.7, 0.65, 0.7);
    ASSERT_GT(probe.distance(x0), 0);
    ASSERT_LT(probe.distance(x1), 0);
    point x = x1;
    vector v = (x1 - x0)/1e-3, F;
    EXPECT_TRUE(probe.entry(x0, x, v, 0.01, 1e-3, F));
    EXPECT_LT(mag(x - point(0.7, 0.5625, 0.7)), 1e-9*mag(x1 - x0));
    EXPECT_GE(probe.distance(x), 0);
    EXPECT_LT(mag(v - vector((x1 - x0).x(), 0, (x1 - x0).z())/1e-3), 1e-9);
}


TEST(particleGuard, PathFromJustOutsideAFaceStopsAtItsStart)
{
    // 1e-12 m above the box's top face (less than 2^-30 of the move from
    // it) and into it: the start is the entry, and the end point is
    // projected on the face's plane there
    const surfaceCase surfaces;
    barrierProbe probe
    (
        "type triSurface; file box.stl; contact slip;", surfaces.dir()
    );
    const point x0(0.5, 0.55, 0.875 + 1e-12), x1(0.5, 0.57, 0.8);
    point x = x1;
    vector v(0, 20, -75), F;
    EXPECT_TRUE(probe.entry(x0, x, v, 0.01, 1e-3, F));
    EXPECT_EQ(x, point(0.5, 0.57, x0.z()));
    EXPECT_GE(probe.distance(x), 0);
    EXPECT_EQ(v, vector(0, 20, 0));
}


TEST(particleGuard, ManyParticlesEnteringASurfaceOnTwoThreadsAsOnOne)
{
    const surfaceCase surfaces;
    constexpr label n = 40000;
    pointField x0, x1;
    vectorField v0;
    movesAroundTheBox(n, 11, x0, x1, v0);

    pointField x[2] = {x1, x1};
    vectorField v[2] = {v0, v0};
    vector F[2];
    label stopped[2];
    for (int t = 0; t < 2; ++t)
    {
        barrierProbe probe
        (
            "type triSurface; file box.stl; contact slip;", surfaces.dir()
        );
        {
            const threadCount threads(t + 1);
            stopped[t] = probe.entries(x0, x[t], v[t], 0.01, 1e-3, F[t]);
        }

        label nEntered = 0;
        for (label i = 0; i < n; ++i)
        {
            const scalar phi0 = probe.distance(x0[i]);
            const scalar phi1 = probe.distance(x1[i]);
            if (phi0 > 0 && phi1 < 0)
            {
                // Put back: on the face it entered (its end point
                // projected on the face's plane, outside by less than the
                // move by an edge), or at the entry point (to 2^-30 of the
                // move); its velocity into the face removed
                ++nEntered;
                const scalar moved = mag(x1[i] - x0[i]);
                const scalar phi = probe.distance(x[t][i]);
                EXPECT_GE(phi, -1e-9*moved) << x0[i] << " -> " << x1[i];
                EXPECT_LE(phi, moved) << x0[i] << " -> " << x1[i];
                EXPECT_LT(mag(v[t][i]), mag(v0[i])) << x0[i];
            }
            else
            {
                EXPECT_EQ(x[t][i], x1[i]) << x0[i] << " -> " << x1[i];
                EXPECT_EQ(v[t][i], v0[i]) << x0[i];
            }
        }
        EXPECT_EQ(stopped[t], nEntered);
        // More than a chunk of the bisection's (1,024)
        EXPECT_GT(nEntered, 2048);
    }
    EXPECT_EQ(stopped[1], stopped[0]);
    EXPECT_EQ(F[1], F[0]);
    for (label i = 0; i < n; ++i)
    {
        EXPECT_EQ(x[1][i], x[0][i]) << i;
        EXPECT_EQ(v[1][i], v[0][i]) << i;
    }
}


TEST(particleGuardBenchmark, EntriesThroughASurfacePerSecond)
{
    // The guard's cost per particle put back, at a triSurface barrier
    // (the box of surfaceCase.H, 12 triangles): 40,000 particles within
    // a cell of it moved by up to a cell, one thread, best of 5
    const surfaceCase surfaces;
    constexpr label n = 40000;
    pointField x0, x1;
    vectorField v0;
    movesAroundTheBox(n, 5, x0, x1, v0);
    barrierProbe probe
    (
        "type triSurface; file box.stl; contact slip;", surfaces.dir()
    );
    const threadCount threads(1);
    double best = GREAT;
    label stopped = 0;
    for (int run = 0; run < 5; ++run)
    {
        pointField x(x1);
        vectorField v(v0);
        vector F;
        const auto t0 = std::chrono::steady_clock::now();
        stopped = probe.entries(x0, x, v, 0.01, 1e-3, F);
        const auto t1 = std::chrono::steady_clock::now();
        best = min(best, std::chrono::duration<double>(t1 - t0).count());
        // No particle that started outside ends inside
        for (label i = 0; i < n; ++i)
        {
            if (probe.distance(x0[i]) > 0)
            {
                EXPECT_GE(probe.distance(x[i]), -1e-9*mag(x1[i] - x0[i]))
                    << i;
            }
        }
    }
    EXPECT_GT(stopped, 2048);
    std::printf
    (
        "particleGuard, triSurface: %d of %d particles put back in %.4f s"
        " (best of 5, 1 thread): %.0f ns a particle put back\n",
        int(stopped), int(n), best, 1e9*best/stopped
    );
}


// ************************************************************************* //
