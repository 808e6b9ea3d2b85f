/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    S9's advance of a column (columnAdvance): positions moved, a column
    through a wall put back inside with no velocity across it, one through
    an open side marked and counted, the footprint carried by I + dt C, the
    affine field pushed forward only where that does not grow it (and not
    at all when J <= 0), and the split candidates marked only with
    splitting on. Exact values: each is one short expression. Four columns
    at once (lanes4, as gridToColumns takes them) give the same bits as one
    by one, every column taken in lanes in one of two runs.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "columnMotionArrays.H"
#include <gtest/gtest.h>
#include <vector>

using namespace Foam;

namespace
{

struct columns
:
    columnMotionArrays
{
    using columnMotionArrays::columnMotionArrays;

    //- Advance every column one by one; the number marked for removal
    int advanceOneByOne(const columnAdvance& a)
    {
        int nRemoved = 0;
        for (int i = 0; i < int(x.size()); ++i)
        {
            double Ci[4] = {C[0][i], C[1][i], C[2][i], C[3][i]};
            nRemoved += a(i, ux[i], uy[i], Ci);
        }
        return nRemoved;
    }

    //- Advance columns first .. first + 3 at once, the others one by one
    int advanceInLanes(const columnAdvance& a, const int first)
    {
        int nRemoved = 0;
        for (int i = 0; i < int(x.size()); ++i)
        {
            if (i == first)
            {
                lanes4 Ci[4];
                for (int k = 0; k < 4; ++k)
                {
                    Ci[k] = loadLanes(C[k].data() + i);
                }
                nRemoved += a
                (
                    i, loadLanes(ux.data() + i), loadLanes(uy.data() + i), Ci
                );
                i += 3;
                continue;
            }
            double Cj[4] = {C[0][i], C[1][i], C[2][i], C[3][i]};
            nRemoved += a(i, ux[i], uy[i], Cj);
        }
        return nRemoved;
    }
};

} // End anonymous namespace


TEST(columnAdvance, MovesKeepsInsideWallsRemovesThroughOpenSidesAndMarksSplits)
{
    // x in [0, 10] (a wall below, open above), y in [0, 4] (walls)
    const gridGeometry g = uniformGrid(2, {0, 0, 0}, {1, 1, 1}, {10, 4, 1});
    domainSides sides;
    sides.wall[0][0] = true;
    sides.wall[1][0] = sides.wall[1][1] = true;
    splitRule rule;
    rule.maxArea = 1;
    rule.hSplit = 0.1;
    const double dt = 0.5;

    columns c(6);
    const auto advance = [&](columns& cols, const bool split)
    {
        return columnAdvance(g, sides, dt, split, rule, cols.motion());
    };
    // 0: inside, no gradient
    c.x[0] = 5; c.y[0] = 2; c.ux[0] = 1; c.uy[0] = 0.5;
    // 1: through the wall at x = 0
    c.x[1] = 0.2; c.y[1] = 1; c.ux[1] = -1; c.uy[1] = 0.25;
    // 2: through the open side x = 10
    c.x[2] = 9.8; c.y[2] = 1; c.ux[2] = 1;
    // 3: stretching (push-forward kept), footprint of area 4 (to split)
    c.x[3] = 4; c.y[3] = 2; c.C[0][3] = 0.2;
    c.F[0][3] = 2; c.F[3][3] = 2;
    // 4: compressing (the push-forward would grow C: not kept)
    c.x[4] = 6; c.y[4] = 2; c.C[0][4] = -0.2;
    // 5: folding over (J < 0: C kept), through the wall at y = 4
    c.x[5] = 7; c.y[5] = 3.9; c.uy[5] = 1; c.C[0][5] = -3;

    // Four at once, from the first column and from the third (every
    // column through the lanes in one of the two)
    columns lanes0(c), lanes2(c);
    const int nRemoved = c.advanceOneByOne(advance(c, true));
    EXPECT_EQ(lanes0.advanceInLanes(advance(lanes0, true), 0), nRemoved);
    EXPECT_EQ(lanes2.advanceInLanes(advance(lanes2, true), 2), nRemoved);
    EXPECT_TRUE(lanes0 == c);
    EXPECT_TRUE(lanes2 == c);

    EXPECT_EQ(nRemoved, 1);
    EXPECT_EQ(c.removal, std::vector<char>({0, 0, 1, 0, 0, 0}));
    EXPECT_EQ(c.split, std::vector<char>({0, 0, 0, 1, 0, 0}));

    EXPECT_EQ(c.x[0], 5 + dt*1);
    EXPECT_EQ(c.y[0], 2 + dt*0.5);
    EXPECT_EQ(c.ux[0], 1);
    EXPECT_EQ(c.uy[0], 0.5);

    EXPECT_EQ(c.x[1], 1e-6*1.0);
    EXPECT_EQ(c.ux[1], 0);
    EXPECT_EQ(c.y[1], 1 + dt*0.25);
    EXPECT_EQ(c.uy[1], 0.25);

    EXPECT_EQ(c.y[5], 4 - 1e-6*1.0);
    EXPECT_EQ(c.uy[5], 0);

    // F <- (I + dt C) F; C <- C (I + dt C)^-1 where |C G^-1| <= |C|
    const double g3 = 1 + dt*0.2;
    EXPECT_EQ(c.F[0][3], g3*2);
    EXPECT_EQ(c.F[3][3], 2);
    EXPECT_EQ(c.C[0][3], (0.2*1 - 0*0)/(g3*1 - 0*0));
    EXPECT_EQ(c.C[0][4], -0.2);
    EXPECT_EQ(c.F[0][4], (1 - dt*0.2)*0.5);
    EXPECT_EQ(c.C[0][5], -3);
    EXPECT_EQ(c.F[0][5], (1 - dt*3)*0.5);

    // Without splitting no column is marked
    columns d(6);
    d.F[0][3] = d.F[3][3] = 2;
    columns dLanes(d);
    d.advanceOneByOne(advance(d, false));
    dLanes.advanceInLanes(advance(dLanes, false), 2);
    EXPECT_EQ(d.split, std::vector<char>(6, 0));
    EXPECT_TRUE(dLanes == d);
}


// ************************************************************************* //
