/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    depthAveragedDiagnostics: the totals of three columns against values
    worked by hand (mass, kinetic energy with the speed along the bed on a
    sloping bed and without it on a flat one, largest speeds, extent), and
    of 4101 columns (summed four at a time, the last three one by one), the
    same totals on 1 and 2 threads bit for bit, a column that is not finite
    found among the four-at-a-time and the last, and the non-finite field
    named.

\*---------------------------------------------------------------------------*/

#include "depthAveragedDiagnostics.H"
#include "depthAveragedParticles.H"
#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <random>
#ifdef _OPENMP
#include <omp.h>
#endif

using namespace Foam;

namespace
{

// Sums of three terms
constexpr double roundOff = 1e-15;

//- Add a column at (x, y) of mass m, velocity (u, v), bed gradient (gx, gy)
void add
(
    depthAveragedParticles& c,
    const double x, const double y, const double m,
    const double u, const double v, const double gx, const double gy
)
{
    const label i = c.p.append(1);
    c.at(particleArrays::X, i) = x;
    c.at(particleArrays::Y, i) = y;
    c.at(particleArrays::M, i) = m;
    c.at(particleArrays::UX, i) = u;
    c.at(particleArrays::UY, i) = v;
    c.at(c.f.gradZ(), i) = gx;
    c.at(c.f.gradZ() + 1, i) = gy;
    c.at(c.f.h(), i) = 1;
}

// Three columns worked by hand:
//   1: m 2, u (3, 4), grad Z (0.5, 0): w = 1.5, v^2 = 25 + 2.25
//   2: m 1, u (0, -1), grad Z (0, 2):  w = -2,  v^2 = 1 + 4
//   3: m 4, u (0, 0),  grad Z (1, 1):  w = 0,   v^2 = 0
depthAveragedParticles threeColumns()
{
    depthAveragedParticles c;
    add(c, 1, 2, 2, 3, 4, 0.5, 0);
    add(c, -3, 5, 1, 0, -1, 0, 2);
    add(c, 7, -1, 4, 0, 0, 1, 1);
    return c;
}

} // End anonymous namespace


TEST(depthAveragedDiagnostics, TotalsOfThreeColumnsMatchTheHandValues)
{
    const depthAveragedParticles c = threeColumns();

    const depthAveragedDiagnostics::totals t =
        depthAveragedDiagnostics::sum(c.p, c.f, true);
    EXPECT_EQ(t.mass, 7.0);
    EXPECT_NEAR(t.kineticEnergy, 0.5*2*27.25 + 0.5*1*5, roundOff*30);
    EXPECT_NEAR(t.maxSpeed, std::sqrt(27.25), roundOff*6);
    EXPECT_EQ(t.maxHorizontalSpeed, 5.0);
    EXPECT_EQ(t.extent.min(), point(-3, -1, 0));
    EXPECT_EQ(t.extent.max(), point(7, 5, 0));
    EXPECT_TRUE(t.finite);

    // A flat bed reads no gradient: the speed is the horizontal one
    const depthAveragedDiagnostics::totals flat =
        depthAveragedDiagnostics::sum(c.p, c.f, false);
    EXPECT_EQ(flat.mass, 7.0);
    EXPECT_EQ(flat.kineticEnergy, 0.5*2*25 + 0.5*1*1);
    EXPECT_EQ(flat.maxSpeed, 5.0);
    EXPECT_EQ(flat.maxHorizontalSpeed, 5.0);
}


TEST(depthAveragedDiagnostics, ManyColumnsSummedFourAtATimeMatchTheHandValues)
{
    // The three columns 1367 times (five blocks of 1024 columns, the last
    // of five: four in lanes and one alone), shifted so that each copy's
    // extent differs: sums of halves and quarters of small numbers, exact
    // in any order
    depthAveragedParticles c;
    const label nCopies = 1367;
    for (label k = 0; k < nCopies; ++k)
    {
        add(c, 1 + k, 2, 2, 3, 4, 0.5, 0);
        add(c, -3, 5 + k, 1, 0, -1, 0, 2);
        add(c, 7, -1 - k, 4, 0, 0, 1, 1);
    }
    const depthAveragedDiagnostics::totals t =
        depthAveragedDiagnostics::sum(c.p, c.f, true);
    EXPECT_EQ(t.mass, 7.0*nCopies);
    EXPECT_EQ(t.kineticEnergy, (0.5*2*27.25 + 0.5*1*5)*nCopies);
    EXPECT_EQ(t.maxSpeed, std::sqrt(27.25));
    EXPECT_EQ(t.maxHorizontalSpeed, 5.0);
    EXPECT_EQ(t.extent.min(), point(-3, -nCopies, 0));
    EXPECT_EQ(t.extent.max(), point(nCopies, 5 + nCopies - 1, 0));
    EXPECT_TRUE(t.finite);
    EXPECT_EQ(t.nColumns, 3*nCopies);

    // A column that is not finite, among the four-at-a-time and among the
    // last
    // Every column right of and above the origin: the maxima of -x and -y
    // are negative (lanes that started at 0 would give an extent from 0)
    double* x = c.p.component(particleArrays::X);
    double* y = c.p.component(particleArrays::Y);
    for (label i = 0; i < 3*nCopies; ++i)
    {
        x[i] += 10;
        y[i] += 10 + nCopies;
    }
    const depthAveragedDiagnostics::totals shifted =
        depthAveragedDiagnostics::sum(c.p, c.f, true);
    EXPECT_EQ(shifted.extent.min(), point(7, 10, 0));
    EXPECT_EQ(shifted.extent.max(), point(10 + nCopies, 15 + 2*nCopies - 1, 0));

    double* h = c.p.component(c.f.h());
    for (const label i : {label(2), label(3*nCopies - 1)})
    {
        h[i] = std::numeric_limits<double>::infinity();
        EXPECT_FALSE(depthAveragedDiagnostics::sum(c.p, c.f, true).finite)
            << "column " << i;
        h[i] = 1;
    }
}


TEST(depthAveragedDiagnostics, NoColumnsGiveZeroTotalsAndAPointExtent)
{
    const depthAveragedParticles c;
    const depthAveragedDiagnostics::totals t =
        depthAveragedDiagnostics::sum(c.p, c.f, true);
    EXPECT_EQ(t.mass, 0.0);
    EXPECT_EQ(t.kineticEnergy, 0.0);
    EXPECT_EQ(t.maxSpeed, 0.0);
    EXPECT_EQ(t.extent.min(), point::zero);
    EXPECT_EQ(t.extent.max(), point::zero);
    EXPECT_TRUE(t.finite);
}


TEST(depthAveragedDiagnostics, SameTotalsOnOneAndTwoThreads)
{
    depthAveragedParticles c;
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(-1, 1);
    for (label i = 0; i < 100001; ++i)
    {
        add(c, u(gen), u(gen), 1 + u(gen), u(gen), u(gen), u(gen), u(gen));
    }
#ifdef _OPENMP
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
#endif
    const depthAveragedDiagnostics::totals one =
        depthAveragedDiagnostics::sum(c.p, c.f, true);
#ifdef _OPENMP
    omp_set_num_threads(2);
#endif
    const depthAveragedDiagnostics::totals two =
        depthAveragedDiagnostics::sum(c.p, c.f, true);
#ifdef _OPENMP
    omp_set_num_threads(threads);
#endif
    EXPECT_EQ(one.mass, two.mass);
    EXPECT_EQ(one.kineticEnergy, two.kineticEnergy);
    EXPECT_EQ(one.maxSpeed, two.maxSpeed);
}


TEST(depthAveragedDiagnostics, NonFiniteFieldIsNamed)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    {
        const depthAveragedParticles c = threeColumns();
        EXPECT_EQ(depthAveragedDiagnostics::nonFiniteField(c.p, c.f), "");
    }
    {
        depthAveragedParticles c = threeColumns();
        c.p.component(c.f.h())[1] = nan;
        EXPECT_FALSE(depthAveragedDiagnostics::sum(c.p, c.f, true).finite);
        EXPECT_EQ(depthAveragedDiagnostics::nonFiniteField(c.p, c.f), "h");
    }
    {
        depthAveragedParticles c = threeColumns();
        c.p.component(particleArrays::UY)[2] = inf;
        EXPECT_FALSE(depthAveragedDiagnostics::sum(c.p, c.f, false).finite);
        EXPECT_EQ(depthAveragedDiagnostics::nonFiniteField(c.p, c.f), "U");
    }
    {
        depthAveragedParticles c = threeColumns();
        c.p.component(particleArrays::X)[0] = nan;
        c.p.component(c.f.h())[0] = nan;
        EXPECT_EQ
        (
            depthAveragedDiagnostics::nonFiniteField(c.p, c.f), "positions"
        );
    }
}


// ************************************************************************* //
