/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    depthAveragedSplitting: random stretched, sheared columns with an affine
    velocity field split into halves that keep mass and basal area exactly
    and momentum, centre of mass and footprint area (each half |det F|/2)
    to round-off; columns below splitRatio seed areas, thinner than
    splitHMin or whose halves would leave the domain stay whole; the
    default split floor is 1 % of the thickest column, to three digits.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "depthAveragedSplitting.H"
#include "depthAveragedParticles.H"
#include "IStringStream.H"
#include "testCase.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

// Sums of a few hundred terms of one sign, relative
constexpr double roundOff = 1e-13;

const double rho = 1000;

// 40 x 30 cells of 0.5 x 0.25 m from (-2, 1); 2 x 2 seed columns per cell
gridGeometry makeGrid()
{
    return uniformGrid(2, {-2, 1, 0}, {0.5, 0.25, 1}, {40, 30, 1});
}

const label nPerCell = 2;
const double seedArea = 0.5*0.25/(nPerCell*nPerCell);

dictionary dampmProperties(const std::string& text)
{
    IStringStream is(text);
    return dictionary(is);
}

// n random columns well inside the grid, footprints stretched 1 to 3 seed
// areas, depths 0.1 to 1 m, affine velocity fields
depthAveragedParticles randomColumns(const label n, const unsigned seed)
{
    std::mt19937 gen(seed);
    std::uniform_real_distribution<double> u(0, 1);
    depthAveragedParticles c;
    c.p.append(n);
    for (label i = 0; i < n; ++i)
    {
        const double stretch = 1 + 2*u(gen);
        const double angle = 6.3*u(gen), shear = 0.4*(u(gen) - 0.5);
        const double a = std::sqrt(seedArea*stretch);
        const double cs = std::cos(angle), sn = std::sin(angle);
        // F = R(angle) [a shear*a; 0 a]
        c.at(c.f.F(), i) = cs*a;
        c.at(c.f.F() + 1, i) = cs*shear*a - sn*a;
        c.at(c.f.F() + 2, i) = sn*a;
        c.at(c.f.F() + 3, i) = sn*shear*a + cs*a;
        const double area = a*a;
        const double h = 0.1 + 0.9*u(gen);
        c.at(c.f.A(), i) = area;
        c.at(particleArrays::VOL, i) = area*h;
        c.at(particleArrays::M, i) = rho*area*h;
        c.at(particleArrays::X, i) = 2 + 14*u(gen);
        c.at(particleArrays::Y, i) = 3 + 4*u(gen);
        c.at(particleArrays::UX, i) = 10*(u(gen) - 0.5);
        c.at(particleArrays::UY, i) = 10*(u(gen) - 0.5);
        for (int k = 0; k < 4; ++k)
        {
            c.at(c.f.gradU() + k, i) = 2*(u(gen) - 0.5);
        }
    }
    return c;
}

struct sums
{
    double m = 0, A = 0, px = 0, py = 0, mx = 0, my = 0, area = 0;
};

sums total(const particleArrays& p, const depthAveragedFields& f)
{
    sums s;
    const label F = f.F();
    for (label i = 0; i < p.size(); ++i)
    {
        const double m = p.component(particleArrays::M)[i];
        s.m += m;
        s.A += p.component(f.A())[i];
        s.px += m*p.component(particleArrays::UX)[i];
        s.py += m*p.component(particleArrays::UY)[i];
        s.mx += m*p.component(particleArrays::X)[i];
        s.my += m*p.component(particleArrays::Y)[i];
        s.area += std::abs
        (
            p.component(F)[i]*p.component(F + 3)[i]
          - p.component(F + 1)[i]*p.component(F + 2)[i]
        );
    }
    return s;
}

double rel(const double a, const double b)
{
    return std::abs(a - b)/std::max(std::abs(b), 1e-300);
}

} // End anonymous namespace


TEST(depthAveragedSplitting, HalvesKeepMassAreaMomentumAndCentreOfMass)
{
    const gridGeometry g = makeGrid();
    depthAveragedSplitting split
    (
        dampmProperties("splitRatio 1.25; splitHMin 0;"), g, nPerCell, 1e-4
    );
    depthAveragedParticles c = randomColumns(400, 3);
    const particleArrays before(c.p);
    const sums s0 = total(c.p, c.f);

    label nAbove = 0;
    for (label i = 0; i < c.p.size(); ++i)
    {
        const double area = std::abs
        (
            c.at(c.f.F(), i)*c.at(c.f.F() + 3, i)
          - c.at(c.f.F() + 1, i)*c.at(c.f.F() + 2, i)
        );
        nAbove += area > 1.25*seedArea;
    }
    ASSERT_GT(nAbove, 100);

    const label nSplit = split.split(c.p, c.f, false);
    EXPECT_EQ(nSplit, nAbove);
    ASSERT_EQ(c.p.size(), before.size() + nSplit);

    const sums s1 = total(c.p, c.f);
    EXPECT_LT(rel(s1.m, s0.m), roundOff);
    EXPECT_LT(rel(s1.A, s0.A), roundOff);
    EXPECT_LT(rel(s1.area, s0.area), roundOff);
    EXPECT_NEAR(s1.px, s0.px, roundOff*s0.m*5);
    EXPECT_NEAR(s1.py, s0.py, roundOff*s0.m*5);
    EXPECT_LT(rel(s1.mx, s0.mx), roundOff);
    EXPECT_LT(rel(s1.my, s0.my), roundOff);

    // Parent and child: equal halves of mass, volume and area (exactly),
    // each footprint half the parent's, each fits the split rule no more
    const label n0 = before.size();
    label k = 0;
    for (label i = 0; i < n0; ++i)
    {
        const double m0 = before.component(particleArrays::M)[i];
        if (c.p.component(particleArrays::M)[i] == m0)
        {
            continue;
        }
        const label j = n0 + k++;
        EXPECT_EQ(c.p.component(particleArrays::M)[i], 0.5*m0);
        EXPECT_EQ(c.p.component(particleArrays::M)[j], 0.5*m0);
        EXPECT_EQ(c.p.component(c.f.A())[j], 0.5*before.component(c.f.A())[i]);
        EXPECT_EQ
        (
            c.p.component(particleArrays::VOL)[j],
            0.5*before.component(particleArrays::VOL)[i]
        );
        const label F = c.f.F();
        const double det0 =
            before.component(F)[i]*before.component(F + 3)[i]
          - before.component(F + 1)[i]*before.component(F + 2)[i];
        const double det1 =
            c.p.component(F)[j]*c.p.component(F + 3)[j]
          - c.p.component(F + 1)[j]*c.p.component(F + 2)[j];
        EXPECT_NEAR(det1, 0.5*det0, roundOff*std::abs(det0));
    }
    EXPECT_EQ(k, nSplit);
}


TEST(depthAveragedSplitting, SmallThinOrEdgeColumnsAndSplitRatioZeroStayWhole)
{
    const gridGeometry g = makeGrid();
    depthAveragedParticles c = randomColumns(1, 5);
    const double area = std::abs
    (
        c.at(c.f.F(), 0)*c.at(c.f.F() + 3, 0)
      - c.at(c.f.F() + 1, 0)*c.at(c.f.F() + 2, 0)
    );
    const double h = c.at(particleArrays::VOL, 0)/area;

    // Below splitRatio seed areas
    {
        depthAveragedParticles one(c);
        depthAveragedSplitting split
        (
            dampmProperties("splitRatio 4; splitHMin 0;"), g, nPerCell, 0
        );
        EXPECT_EQ(split.split(one.p, one.f, false), 0);
    }
    // Thinner than splitHMin
    {
        depthAveragedParticles one(c);
        const std::string text =
            "splitRatio 1; splitHMin " + std::to_string(1.01*h) + ";";
        depthAveragedSplitting split(dampmProperties(text), g, nPerCell, 0);
        EXPECT_EQ(split.split(one.p, one.f, false), 0);
    }
    // A half would leave the grid
    {
        depthAveragedParticles one(c);
        one.at(particleArrays::X, 0) = g.origin[0] + 1e-9;
        one.at(particleArrays::Y, 0) = g.origin[1] + 1e-9;
        depthAveragedSplitting split
        (
            dampmProperties("splitRatio 1; splitHMin 0;"), g, nPerCell, 0
        );
        EXPECT_EQ(split.split(one.p, one.f, false), 0);
    }
    // Off
    {
        depthAveragedParticles one(c);
        depthAveragedSplitting split
        (
            dampmProperties("splitRatio 0;"), g, nPerCell, 0
        );
        EXPECT_FALSE(split.active());
        EXPECT_EQ(split.split(one.p, one.f, false), 0);
    }
    // And it splits otherwise
    {
        depthAveragedParticles one(c);
        depthAveragedSplitting split
        (
            dampmProperties("splitRatio 1; splitHMin 0;"), g, nPerCell, 0
        );
        EXPECT_EQ(split.split(one.p, one.f, false), 1);
    }
}


TEST(depthAveragedSplitting, DefaultFloorIsOnePercentOfTheThickestColumn)
{
    const gridGeometry g = makeGrid();
    depthAveragedSplitting byDefault
    (
        dampmProperties("splitRatio 1.25;"), g, nPerCell, 1e-4
    );
    byDefault.setDefaultHMin(2.34567);
    EXPECT_EQ(byDefault.rule().hSplit, 0.0235);
    EXPECT_EQ(byDefault.rule().maxArea, 1.25*seedArea);

    depthAveragedSplitting given
    (
        dampmProperties("splitRatio 1.25; splitHMin 0.5;"), g, nPerCell, 1e-4
    );
    given.setDefaultHMin(2.34567);
    EXPECT_EQ(given.rule().hSplit, 0.5);

    // The floor is never below hMin
    depthAveragedSplitting thin
    (
        dampmProperties("splitHMin 1e-6;"), g, nPerCell, 1e-4
    );
    EXPECT_EQ(thin.rule().hSplit, 1e-4);
}


TEST(depthAveragedSplitting, LeavingColumnsUnmarkedSplitThenDroppedByThePlacing)
{
    // The solver's order: candidates marked in G2P, the marks of the
    // columns leaving cleared, the split, then the halves placed beside
    // their parents (parents()) by the pass that drops the columns leaving
    // (removeAndPlaceAppended). Against the removal first, the split of
    // marks made after it and the placing of its halves: the same columns
    // in the same order and bins, to the bit
    const gridGeometry g = makeGrid();
    const tileCellOrder o(g, 8);
    const dictionary dict = dampmProperties("splitRatio 1.25; splitHMin 0;");
    depthAveragedSplitting inG2P(dict, g, nPerCell, 1e-4);
    depthAveragedSplitting after(dict, g, nPerCell, 1e-4);
    depthAveragedParticles a = randomColumns(400, 5);
    const label n = a.p.size();
    a.p.sortByCell(g, o, 2);
    depthAveragedParticles b = a;
    std::vector<char> leaving(n, 0);
    for (label i = 0; i < n; i += 7)
    {
        leaving[i] = 1;
    }

    const splitRule r = inG2P.rule();
    std::vector<char>& marks = inG2P.flags(n);
    label nMarked = 0, nBoth = 0;
    for (label i = 0; i < n; ++i)
    {
        marks[i] = r.candidate
        (
            a.at(a.f.F(), i), a.at(a.f.F() + 1, i), a.at(a.f.F() + 2, i),
            a.at(a.f.F() + 3, i), a.at(particleArrays::VOL, i)
        );
        nMarked += marks[i];
        nBoth += marks[i] && leaving[i];
        marks[i] = marks[i] && !leaving[i];
    }
    ASSERT_GT(nMarked, 100);
    ASSERT_GT(nBoth, 10);
    const label nSplit = inG2P.split(a.p, a.f, true);
    EXPECT_GT(nSplit, 80);
    leaving.resize(a.p.size(), 0);
    ASSERT_EQ(label(inG2P.parents().size()), nSplit);
    EXPECT_EQ
    (
        a.p.removeAndPlaceAppended(leaving, inG2P.parents(), g, o, 2),
        n/7 + 1
    );

    leaving.resize(n);
    b.p.removeFlagged(leaving);
    EXPECT_FALSE(b.p.sortByCell(g, o, 2));
    EXPECT_EQ(after.split(b.p, b.f, false), nSplit);
    const std::vector<char> none(b.p.size(), 0);
    b.p.removeAndPlaceAppended(none, after.parents(), g, o, 2);

    // Placed, not re-sorted: each half right after its parent (the two
    // share their footprint exactly; a re-sort puts a half last in its bin)
    label nBeside = 0;
    for (label i = 1; i < a.p.size(); ++i)
    {
        bool same = a.p.cell()[i] == a.p.cell()[i - 1];
        for (label c = a.f.F(); c < a.f.F() + 4; ++c)
        {
            same = same && a.at(c, i) == a.at(c, i - 1);
        }
        nBeside += same;
    }
    EXPECT_EQ(nBeside, nSplit);

    ASSERT_EQ(a.p.size(), b.p.size());
    for (label c = 0; c < a.p.nComponentArrays(); ++c)
    {
        for (label i = 0; i < a.p.size(); ++i)
        {
            ASSERT_EQ(a.p.component(c)[i], b.p.component(c)[i])
                << "component " << c << ", column " << i;
        }
    }
    EXPECT_EQ(a.p.binStart(), b.p.binStart());

    // Marks of another number of columns are refused
    depthAveragedParticles d = randomColumns(400, 5);
    depthAveragedSplitting stale(dict, g, nPerCell, 1e-4);
    stale.flags(n);
    d.p.removeFlagged(leaving);
    const std::string msg =
        foamErrorMessage([&]{ stale.split(d.p, d.f, true); });
    EXPECT_NE(msg.find("split marks"), std::string::npos) << msg;
}


// ************************************************************************* //
