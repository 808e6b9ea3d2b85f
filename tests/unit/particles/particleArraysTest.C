/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    particleArrays: fields, append, stable removal, the counting sort by
    cell that keeps every field of a particle together, the binning kept
    while every particle stays near its bin (along each axis of 3D grids
    whose cell counts are no power of two), the cells of the particles a
    full binning gives another bin, and the node rows' spans the
    particles' stencils touch.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "particleArrays.H"
#include "shapeKernels.H"
#include "stencil.H"
#include "testCase.H"
#include "threadCount.H"
#include <gtest/gtest.h>
#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <random>
#include <utility>

using namespace Foam;

namespace
{

gridGeometry grid2D()
{
    return uniformGrid(2, {0, 0, 0}, {0.5, 0.5, 1}, {16, 9, 1});
}

// Particles with an id and a value that is a function of the id
particleArrays randomParticles(const gridGeometry& g, const label n)
{
    particleArrays p;
    const label id = p.addField("id", particleArrays::fieldKind::scalar);
    const label tag = p.addField("tag", particleArrays::fieldKind::vector);
    p.append(n);
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(0, 1);
    for (label i = 0; i < n; ++i)
    {
        p.component(particleArrays::X)[i] = u(gen)*g.upper(0);
        p.component(particleArrays::Y)[i] = u(gen)*g.upper(1);
        p.component(particleArrays::M)[i] = 1 + i;
        p.component(id)[i] = i;
        p.component(tag + 2)[i] = 3.0*i;
    }
    return p;
}

// randomParticles with an internal field marked transient (t) and one
// marked recomputed (r)
struct markedParticles
{
    particleArrays p;
    label id, t, r;
};

markedParticles withMarkedFields(const gridGeometry& g, const label n)
{
    markedParticles m{randomParticles(g, n), 0, 0, 0};
    m.id = m.p.field("id").first;
    m.t = m.p.addField("t", particleArrays::fieldKind::internal);
    m.r = m.p.addField("r", particleArrays::fieldKind::internal);
    m.p.markTransient(m.t);
    m.p.markRecomputed(m.r);
    return m;
}

//- binStart counts every bin of the order, and each particle lies in its
//  cell's bin
void expectBinsHoldTheirParticles
(
    const particleArrays& p,
    const tileCellOrder& o
)
{
    ASSERT_EQ(label(p.binStart().size()), o.nRanks() + 1);
    EXPECT_EQ(p.binStart().back(), p.size());
    for (label k = 0; k < p.size(); ++k)
    {
        const label rank = o.rank(p.cell()[k]);
        EXPECT_TRUE(p.binStart()[rank] <= k && k < p.binStart()[rank + 1]);
    }
}

} // End anonymous namespace


TEST(particleArrays, HasStandardFieldsAndRefusesDuplicates)
{
    particleArrays p;
    EXPECT_TRUE(p.found("positions"));
    EXPECT_TRUE(p.found("U"));
    EXPECT_EQ(p.field("m").first, particleArrays::M);
    EXPECT_EQ(p.field("V").first, particleArrays::VOL);
    const std::string msg = foamErrorMessage
    (
        [&]{ p.addField("U", particleArrays::fieldKind::vector); }
    );
    EXPECT_NE(msg.find("exists already"), std::string::npos) << msg;
}


TEST(particleArrays, AppendedParticlesTakeTheFieldsInitialValue)
{
    particleArrays p;
    const label h = p.addField("h", particleArrays::fieldKind::scalar, 2.5);
    p.append(3);
    p.component(h)[0] = 7;
    p.append(2);
    EXPECT_EQ(p.size(), 5);
    EXPECT_EQ(p.component(h)[0], 7);
    EXPECT_EQ(p.component(h)[4], 2.5);
    EXPECT_EQ(p.component(particleArrays::M)[4], 0);

    // Also after every particle was removed (the first ones before the
    // others, which moves the arrays' start into their buffers), with and
    // without the memory beyond the particles returned
    for (const bool shrunk : {false, true})
    {
        const label n = 5000;
        p.append(n - p.size());
        std::fill_n(p.component(h), n, -1.0);
        for (const label nRemoved : {n/2, n/2})
        {
            std::vector<char> flagged(p.size(), 0);
            std::fill_n(flagged.begin(), nRemoved, 1);
            p.removeFlagged(flagged);
        }
        ASSERT_EQ(p.size(), 0);
        if (shrunk)
        {
            p.shrink();
        }
        p.append(10);
        for (label i = 0; i < 10; ++i)
        {
            EXPECT_EQ(p.component(h)[i], 2.5) << i;
        }
    }
}


TEST(particleArrays, FiniteFindsOneNaNOrInfinityInAnyColumn)
{
    const gridGeometry g = grid2D();
    particleArrays p = randomParticles(g, 1001);
    std::vector<label> all(p.nComponentArrays());
    std::iota(all.begin(), all.end(), 0);
    EXPECT_TRUE(p.finite(all));
    const double bad[3] =
    {
        std::numeric_limits<double>::quiet_NaN(),
        std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()
    };
    for (const double b : bad)
    {
        for (const label c : {label(particleArrays::X), all.back()})
        {
            for (const label i : {label(0), label(500), label(1000)})
            {
                const double keep = p.component(c)[i];
                p.component(c)[i] = b;
                EXPECT_FALSE(p.finite(all))
                    << "value " << b << " column " << c << " particle " << i;
                EXPECT_TRUE(p.finite({particleArrays::M}))
                    << "a column without it";
                p.component(c)[i] = keep;
            }
        }
    }
    // Large finite values are finite
    p.component(particleArrays::M)[7] = std::numeric_limits<double>::max();
    EXPECT_TRUE(p.finite(all));
}


// In a schedule's tile order (tiles of 5 x 5 cells on a 16 x 9 grid: partial
// tiles at the ends) each cell's and each tile's particles are one range,
// the cells in rank order; the particles are the plain sort's, permuted;
// the stencil rows are the plain order's; a restart's bins are kept
TEST(particleArrays, SortInTileOrderStoresEveryTileContiguously)
{
    const gridGeometry g = grid2D();
    const tileCellOrder o(g, 5);
    ASSERT_EQ(o.nRanks(), 4*2*25);
    particleArrays p = randomParticles(g, 5000);
    particleArrays plain = randomParticles(g, 5000);
    p.sortByCell(g, o, 1);
    plain.sortByCell(g, tileCellOrder(g, 1), 1);

    const std::vector<label>& binStart = p.binStart();
    ASSERT_EQ(label(binStart.size()), o.nRanks() + 1);
    EXPECT_EQ(binStart.back(), p.size());
    const label id = p.field("id").first;
    const double* x = p.component(particleArrays::X);
    const double* y = p.component(particleArrays::Y);
    for (label j = 0; j < g.nCells[1]; ++j)
    {
        for (label i = 0; i < g.nCells[0]; ++i)
        {
            const label c = g.cellIndex(i, j, 0);
            const label r = o.rank(c);
            EXPECT_EQ(r, o.rank(i, j, 0));
            // Tile (i/5, j/5), and within it cell (i%5, j%5)
            EXPECT_EQ(r, (i/5 + 4*(j/5))*25 + i % 5 + 5*(j % 5));
            const label cPlain = plain.binStart()[c];
            ASSERT_EQ
            (
                binStart[r + 1] - binStart[r],
                plain.binStart()[c + 1] - cPlain
            );
            for (label k = binStart[r]; k < binStart[r + 1]; ++k)
            {
                EXPECT_EQ(g.cellOf(x[k], y[k], 0), c);
                EXPECT_EQ(p.cell()[k], c);
                // Stable: the plain sort's particles of the cell, in order
                EXPECT_EQ
                (
                    p.component(id)[k],
                    plain.component(id)[cPlain + k - binStart[r]]
                );
            }
        }
    }
    // A tile's particles: ranks firstRank(t) .. firstRank(t + 1) - 1
    for (label t = 0; t < 8; ++t)
    {
        const label last = binStart[o.firstRank(t + 1)];
        for (label k = binStart[o.firstRank(t)]; k < last; ++k)
        {
            const label c = p.cell()[k];
            EXPECT_EQ((c % 16)/5 + 4*((c/16)/5), t);
        }
    }

    nodeRowSpans rows, rowsPlain;
    p.stencilRows(g, rows);
    plain.stencilRows(g, rowsPlain);
    EXPECT_TRUE(rows.lo == rowsPlain.lo);
    EXPECT_TRUE(rows.hi == rowsPlain.hi);

    // A restart: the bins set again are kept by a sort in the same order
    const std::vector<label> bins = p.cell();
    particleArrays q = p;
    ASSERT_TRUE(q.setBins(g, bins));
    EXPECT_FALSE(q.sortByCell(g, o, 1));
    EXPECT_TRUE(q.binStart() == binStart);
    // In another order they are not sorted: re-binned
    EXPECT_TRUE(q.sortByCell(g, tileCellOrder(g, 1), 1));
    EXPECT_TRUE(q.binStart() == plain.binStart());

    // A restart's bins, particles removed before the first sort: kept, and
    // counted then
    particleArrays r = p;
    ASSERT_TRUE(r.setBins(g, bins));
    std::vector<char> flagged(r.size(), 0);
    flagged[0] = flagged[17] = 1;
    EXPECT_EQ(r.removeFlagged(flagged), 2);
    EXPECT_FALSE(r.sortByCell(g, o, 1));
    expectBinsHoldTheirParticles(r, o);
}


TEST(particleArrays, TileRanksByShiftsAreTheRanksByDivisions)
{
    // Tile sizes that are powers of two take shifts and masks
    const gridGeometry g = grid2D();
    for (const label T : {1, 2, 4, 8, 3, 5})
    {
        const tileCellOrder o(g, T);
        const label nTx = (g.nCells[0] + T - 1)/T;
        for (label j = 0; j < g.nCells[1]; ++j)
        {
            for (label i = 0; i < g.nCells[0]; ++i)
            {
                const label expected =
                    (i/T + nTx*(j/T))*T*T + i % T + T*(j % T);
                EXPECT_EQ(o.rank(i, j, 0), expected) << T;
                EXPECT_EQ(o.rank(g.cellIndex(i, j, 0)), expected) << T;
            }
        }
    }
}


TEST(particleArrays, SortByCellGroupsCellsAndKeepsParticlesWhole)
{
    const gridGeometry g = grid2D();
    particleArrays p = randomParticles(g, 5000);
    p.sortByCell(g);

    const label id = p.field("id").first;
    const label tag = p.field("tag").first;
    const std::vector<label>& binStart = p.binStart();
    ASSERT_EQ(label(binStart.size()), g.nCellsTotal() + 1);
    EXPECT_EQ(binStart.back(), p.size());

    std::vector<int> seen(p.size(), 0);
    for (label c = 0; c < g.nCellsTotal(); ++c)
    {
        for (label i = binStart[c]; i < binStart[c + 1]; ++i)
        {
            const double* x = p.component(particleArrays::X);
            const double* y = p.component(particleArrays::Y);
            EXPECT_EQ(g.cellOf(x[i], y[i], 0), c);
            EXPECT_EQ(p.cell()[i], c);
            const label orig = label(p.component(id)[i]);
            ++seen[orig];
            EXPECT_EQ(p.component(particleArrays::M)[i], 1.0 + orig);
            EXPECT_EQ(p.component(tag + 2)[i], 3.0*orig);
            // Stable: within a cell the original order is kept
            if (i > binStart[c])
            {
                EXPECT_LT(p.component(id)[i - 1], p.component(id)[i]);
            }
        }
    }
    for (const int s : seen)
    {
        EXPECT_EQ(s, 1);
    }
}


TEST(particleArrays, BinningIsKeptWhileParticlesStayNearTheirCells)
{
    const gridGeometry g = grid2D();
    particleArrays p = randomParticles(g, 2000);
    EXPECT_TRUE(p.sortByCell(g, tileCellOrder(g, 1), 1));
    const std::vector<label> binStart = p.binStart();

    // Every particle moves by less than one cell: the binning is kept
    double* x = p.component(particleArrays::X);
    for (label i = 0; i < p.size(); ++i)
    {
        x[i] = std::min(std::max(x[i] + 0.9*g.dx[0]*((i % 3) - 1), 0.0),
            g.upper(0));
    }
    EXPECT_FALSE(p.sortByCell(g, tileCellOrder(g, 1), 1));
    EXPECT_TRUE(p.binStart() == binStart);

    // One particle two cells away: re-binned, and sorted again
    x[7] = x[7] > g.upper(0)/2 ? x[7] - 2.5*g.dx[0] : x[7] + 2.5*g.dx[0];
    EXPECT_TRUE(p.sortByCell(g, tileCellOrder(g, 1), 1));
    for (label i = 1; i < p.size(); ++i)
    {
        EXPECT_LE(p.cell()[i - 1], p.cell()[i]);
    }
}


// binChanges: the cells (where the particles are) of the particles a full
// binning gives another bin than they had, and only those; none while the
// binning is kept, none after clearBinChanges
TEST(particleArrays, FullBinningTellsTheCellsOfTheParticlesGivenAnotherBin)
{
    const gridGeometry g = grid2D();
    const tileCellOrder order(g, 1);
    particleArrays p = randomParticles(g, 2000);
    p.trackBinChanges(g);
    EXPECT_TRUE(p.binChanges() == nullptr);
    EXPECT_TRUE(p.sortByCell(g, order, 1));
    EXPECT_TRUE(p.binChanges() != nullptr) << "appended particles had no bin";
    p.clearBinChanges();
    EXPECT_TRUE(p.binChanges() == nullptr);

    // One particle in 50 moves by 0.9 cells: the binning is kept
    double* x = p.component(particleArrays::X);
    for (label i = 0; i < p.size(); i += 50)
    {
        x[i] = std::min(std::max(x[i] + 0.9*g.dx[0]*((i % 3) - 1), 0.0),
            g.upper(0));
    }
    EXPECT_FALSE(p.sortByCell(g, order, 1));
    EXPECT_TRUE(p.binChanges() == nullptr);

    // One more two cells away: re-binned. The cells of those that changed
    // bin, where they are now
    x[7] = x[7] > g.upper(0)/2 ? x[7] - 2.5*g.dx[0] : x[7] + 2.5*g.dx[0];
    std::vector<uint8_t> expected(g.nCellsTotal(), 0);
    label nChanged = 0;
    for (label i = 0; i < p.size(); ++i)
    {
        const label c = g.cellOf(x[i], p.component(particleArrays::Y)[i], 0);
        if (c != p.cell()[i])
        {
            expected[c] = 1;
            ++nChanged;
        }
    }
    EXPECT_GT(nChanged, 10);
    EXPECT_TRUE(p.sortByCell(g, order, 1));
    ASSERT_TRUE(p.binChanges() != nullptr);
    label nMarked = 0;
    for (label c = 0; c < g.nCellsTotal(); ++c)
    {
        EXPECT_EQ(p.binChanges()[c] != 0, expected[c] != 0) << "cell " << c;
        nMarked += expected[c];
    }
    EXPECT_GT(nMarked, 5);
    EXPECT_LT(nMarked, g.nCellsTotal()/2);
    p.clearBinChanges();
    EXPECT_TRUE(p.binChanges() == nullptr);
}


namespace
{

// On a 3D grid of n cells, in tiles of 3: the binning is kept while every
// particle stays within 2 cells of its bin per axis, and a single particle
// 3 cells from it along x, y or z alone, or 2 cells back along each axis
// from its bin's corner, is found (from cell mid, 3 cells from the grid's
// sides)
void expectStaleBinsFound
(
    const std::array<gridGeometry::index, 3>& nCells,
    const std::array<gridGeometry::index, 3>& mid
)
{
    const gridGeometry g =
        uniformGrid(3, {-1, 2, 0.5}, {0.3, 0.2, 0.4}, nCells);
    const label maxStale = 2;
    const tileCellOrder order(g, 3);
    particleArrays p;
    const label n = 3000;
    p.append(n);
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (label i = 0; i < n; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            p.component(particleArrays::X + d)[i] =
                g.origin[d] + u(gen)*(g.upper(d) - g.origin[d]);
        }
    }
    EXPECT_TRUE(p.sortByCell(g, order, maxStale));

    // The cell's lower corner of particle i's bin, and a move of it
    const auto binCorner = [&](const label i, const int d)
    {
        const label c = p.cell()[i];
        const label ijk[3] =
        {
            c % g.nCells[0], (c/g.nCells[0]) % g.nCells[1],
            c/(g.nCells[0]*g.nCells[1])
        };
        return g.origin[d] + ijk[d]*g.dx[d];
    };
    const auto moveTo = [&](const label i, const double (&cells)[3])
    {
        for (int d = 0; d < 3; ++d)
        {
            p.component(particleArrays::X + d)[i] =
                binCorner(i, d) + cells[d]*g.dx[d];
        }
    };

    // Every particle at most two cells from its bin (but within the grid)
    for (label i = 0; i < n; ++i)
    {
        double cells[3];
        for (int d = 0; d < 3; ++d)
        {
            const double x0 = (binCorner(i, d) - g.origin[d])/g.dx[d];
            const double lo = std::max(-2.0, -x0);
            const double hi = std::min(2.99, g.nCells[d] - x0 - 0.01);
            cells[d] = lo + (hi - lo)*u(gen);
        }
        moveTo(i, cells);
    }
    EXPECT_FALSE(p.sortByCell(g, order, maxStale));

    // One particle too far along one axis (from cell mid, where an exact
    // sort bins it), or two cells and a bit back along all three:
    // re-binned; then kept
    const label midCell = g.cellIndex(mid[0], mid[1], mid[2]);
    for (const std::array<double, 3>& far :
        {
            std::array<double, 3>{3.5, 0.5, 0.5},
            std::array<double, 3>{0.5, 3.5, 0.5},
            std::array<double, 3>{0.5, 0.5, 3.5},
            std::array<double, 3>{0.5, -2.5, 0.5},
            std::array<double, 3>{-2.01, -2.01, -2.01}
        }
    )
    {
        for (int d = 0; d < 3; ++d)
        {
            p.component(particleArrays::X + d)[0] =
                g.origin[d] + (mid[d] + 0.5)*g.dx[d];
        }
        p.sortByCell(g, order);
        label i = 0;
        while (p.cell()[i] != midCell)
        {
            ++i;
        }
        moveTo(i, {far[0], far[1], far[2]});
        EXPECT_TRUE(p.sortByCell(g, order, maxStale))
            << far[0] << " " << far[1] << " " << far[2];
        EXPECT_FALSE(p.sortByCell(g, order, maxStale));
    }
}

} // End anonymous namespace


// 13 x 7 x 7 cells (no power of two); 49 x 7 x 7 and 7 x 49 x 7, where
// 49 (1/49) rounds below 1 (the bin's row from its flat index, and its
// layer from its row, need the half added)
TEST(particleArrays, BinningIsKeptWhileNearAlongEveryAxis)
{
    expectStaleBinsFound({13, 7, 7}, {6, 3, 3});
    expectStaleBinsFound({49, 7, 7}, {3, 3, 3});
    expectStaleBinsFound({7, 49, 7}, {3, 3, 3});
}


// Every node of every particle's stencil lies in its row's span, particles
// up to maxStale cells from their bins included; the spans are those of
// the particles' own cells (not widened by the bins' staleness), and a
// sheet of particles (a flow over a slope in a 3D box) leaves most of its
// box out
TEST(particleArrays, StencilRowSpansHoldEveryStencilNode)
{
    const gridGeometry g =
        uniformGrid(3, {0, 0, 0}, {0.25, 0.25, 0.25}, {40, 12, 30});
    const label maxStale = 1;

    // A layer a cell thick over the slope z = 0.5 + 0.6 x
    particleArrays p;
    const label n = 20000;
    p.append(n);
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(0, 1);
    double* x[3] =
    {
        p.component(particleArrays::X),
        p.component(particleArrays::Y),
        p.component(particleArrays::Z)
    };
    for (label i = 0; i < n; ++i)
    {
        x[0][i] = u(gen)*g.upper(0);
        x[1][i] = u(gen)*g.upper(1);
        x[2][i] = 0.5 + 0.6*x[0][i] + 0.25*u(gen);
    }
    EXPECT_TRUE(p.sortByCell(g, tileCellOrder(g, 1), maxStale));

    // Each particle's nodes c - 1 .. c + 2 per axis (c its cell), as spans
    const auto boxSpans = [&](nodeRowSpans& b)
    {
        b.lo.assign(g.nNodesDir[1]*g.nNodesDir[2], g.nNodesDir[0]);
        b.hi.assign(b.lo.size(), 0);
        const double* xp = p.component(particleArrays::X);
        const double* yp = p.component(particleArrays::Y);
        const double* zp = p.component(particleArrays::Z);
        for (label i = 0; i < n; ++i)
        {
            label c[3];
            g.cellIJK(xp[i], yp[i], zp[i], c);
            for (label k = c[2]; k < c[2] + 4; ++k)
            {
                for (label j = c[1]; j < c[1] + 4; ++j)
                {
                    const label row = j + g.nNodesDir[1]*k;
                    b.lo[row] = std::min(b.lo[row], c[0]);
                    b.hi[row] = std::max(b.hi[row], c[0] + 4);
                }
            }
        }
    };
    const auto nNodes = [](const nodeRowSpans& b)
    {
        label total = 0;
        for (size_t r = 0; r < b.lo.size(); ++r)
        {
            total += std::max(0, b.hi[r] - b.lo[r]);
        }
        return total;
    };

    // Sorted, no particle stale: the spans are exactly those of the boxes
    nodeRowSpans rows, boxes;
    p.stencilRows(g, rows);
    boxSpans(boxes);
    EXPECT_TRUE(rows.lo == boxes.lo);
    EXPECT_TRUE(rows.hi == boxes.hi);

    // Moved by up to 0.9 cells per axis: still in their bins' reach (the
    // sort moved the columns: their addresses again)
    for (int d = 0; d < 3; ++d)
    {
        x[d] = p.component(particleArrays::X + d);
    }
    for (label i = 0; i < n; ++i)
    {
        for (int d = 0; d < 3; ++d)
        {
            x[d][i] = std::min
            (
                std::max(x[d][i] + 0.9*g.dx[d]*(2*u(gen) - 1), 0.0),
                g.upper(d)
            );
        }
    }
    EXPECT_FALSE(p.sortByCell(g, tileCellOrder(g, 1), maxStale));

    p.stencilRows(g, rows);
    ASSERT_EQ(label(rows.lo.size()), label(g.nNodesDir[1]*g.nNodesDir[2]));
    label outside = 0;
    for (label i = 0; i < n; ++i)
    {
        const stencil<3, quadraticBSplineKernel> s
        (
            g, quadraticBSplineKernel(), x[0][i], x[1][i], x[2][i]
        );
        s.forEachNode
        (
            [&](label nodei, double, const double*, const double*)
            {
                const label row = nodei/g.nodeStride[1];
                const label along = nodei % g.nodeStride[1];
                outside += along < rows.lo[row] || along >= rows.hi[row];
            }
        );
    }
    EXPECT_EQ(outside, 0);

    // Stale particles widen only their own bin row's box: the spans hold
    // the particles' boxes, and few nodes more
    boxSpans(boxes);
    for (size_t r = 0; r < rows.lo.size(); ++r)
    {
        if (boxes.lo[r] < boxes.hi[r])
        {
            EXPECT_LE(rows.lo[r], boxes.lo[r]);
            EXPECT_GE(rows.hi[r], boxes.hi[r]);
        }
    }
    std::cout << "span nodes " << nNodes(rows) << ", the particles' boxes "
        << nNodes(boxes) << std::endl;
    EXPECT_LT(nNodes(rows), 1.2*nNodes(boxes));

    // The spans cover a fraction of the particles' box of nodes
    const nodeBox box = p.stencilNodes(g);
    double inSpans = 0, inBox = 0;
    for (label k = box.lo[2]; k < box.hi[2]; ++k)
    {
        for (label j = box.lo[1]; j < box.hi[1]; ++j)
        {
            const label row = j + g.nNodesDir[1]*k;
            inSpans += std::max(0, rows.hi[row] - rows.lo[row]);
            inBox += box.hi[0] - box.lo[0];
        }
    }
    std::cout << "span nodes " << inSpans << " of " << inBox << " in the box"
        << std::endl;
    EXPECT_LT(inSpans, 0.5*inBox);
}


TEST(particleArrays, RemoveFlaggedKeepsOrderOfTheRest)
{
    const gridGeometry g = grid2D();
    particleArrays p = randomParticles(g, 100);
    std::vector<char> flagged(100, 0);
    for (int i = 0; i < 100; i += 3)
    {
        flagged[i] = 1;
    }
    EXPECT_EQ(p.removeFlagged(flagged), 34);
    ASSERT_EQ(p.size(), 66);
    const label id = p.field("id").first;
    label k = 0;
    for (int i = 0; i < 100; ++i)
    {
        if (!flagged[i])
        {
            EXPECT_EQ(p.component(id)[k], i);
            EXPECT_EQ(p.component(particleArrays::M)[k], 1.0 + i);
            ++k;
        }
    }
}


TEST(particleArrays, RemoveFlaggedByRunsKeepsTheRestAndTheirBins)
{
    // Flags that test the runs' edges: none, all, the first, the last (in
    // the tail of fewer than eight flags), runs of several, a few at random
    const gridGeometry g = grid2D();
    const label n = 1003;
    std::mt19937 gen(7);
    std::vector<std::vector<char>> patterns(7, std::vector<char>(n, 0));
    std::fill(patterns[1].begin(), patterns[1].end(), 1);
    patterns[2][0] = 1;
    patterns[3][n - 1] = 1;
    for (label i = 0; i < n; ++i)
    {
        patterns[4][i] = (i/10) % 3 == 1;
        patterns[5][i] = gen() % 100 == 0;
        patterns[6][i] = i > 8 && i < n - 2 && i % 9 != 0;
    }
    for (const std::vector<char>& flagged : patterns)
    {
        particleArrays p = randomParticles(g, n);
        const tileCellOrder o(g, 4);
        p.sortByCell(g, o, 1);
        const particleArrays before = p;
        const label nFlagged = std::count(flagged.begin(), flagged.end(), 1);
        EXPECT_EQ(p.removeFlagged(flagged), nFlagged);
        ASSERT_EQ(p.size(), n - nFlagged);
        label k = 0;
        for (label i = 0; i < n; ++i)
        {
            if (flagged[i])
            {
                continue;
            }
            for (label c = 0; c < p.nComponentArrays(); ++c)
            {
                EXPECT_EQ(p.component(c)[k], before.component(c)[i]);
            }
            EXPECT_EQ(p.cell()[k], before.cell()[i]);
            ++k;
        }

        // The bins stay and are counted by the next sort, which keeps them
        EXPECT_TRUE(p.binned());
        EXPECT_FALSE(p.sortByCell(g, o, 1));
        expectBinsHoldTheirParticles(p, o);
    }
}


TEST(particleArrays, RemoveAndSortIsRemoveFlaggedThenAFullSortBitForBit)
{
    // After an append (a split's): removeFlagged then the re-sort of every
    // particle, against the two in one. The arrays a removal moves (a
    // transient one too) move with their particles; a recomputed one is
    // only shortened
    const gridGeometry g = grid2D();
    const label n = 1003;
    const tileCellOrder o(g, 4);
    std::mt19937 gen(11);
    // Flags on none, on all of those before the append, on about half of
    // every k-th
    for (const int removeEvery : {0, -1, 1, 2, 9, 50})
    {
        markedParticles m = withMarkedFields(g, n);
        particleArrays& a = m.p;
        const label id = m.id, t = m.t, r = m.r;
        a.sortByCell(g, o, 1);
        const label first = a.append(37);
        std::uniform_real_distribution<double> u(0, 1);
        for (label i = 0; i < a.size(); ++i)
        {
            if (i >= first)
            {
                a.component(particleArrays::X)[i] = u(gen)*g.upper(0);
                a.component(particleArrays::Y)[i] = u(gen)*g.upper(1);
                a.component(id)[i] = n + i;
            }
            a.component(t)[i] = a.component(id)[i];
            a.component(r)[i] = -1;
        }
        std::vector<char> flagged(a.size(), 0);
        for (label i = 0; removeEvery && i < first; ++i)
        {
            flagged[i] = removeEvery < 0 || (i % removeEvery == 0 && gen() % 2);
        }
        const label nFlagged = std::count(flagged.begin(), flagged.end(), 1);
        particleArrays b = a;

        EXPECT_EQ(a.removeFlagged(flagged), nFlagged);
        a.sortByCell(g, o, 1);
        EXPECT_EQ(b.removeAndSort(flagged, g, o), nFlagged);

        ASSERT_EQ(b.size(), a.size());
        ASSERT_EQ(b.size(), first + 37 - nFlagged);
        for (label c = 0; c < a.nComponentArrays(); ++c)
        {
            if (c == t || c == r)
            {
                continue;
            }
            for (label k = 0; k < a.size(); ++k)
            {
                ASSERT_EQ(b.component(c)[k], a.component(c)[k])
                    << "component " << c << " of particle " << k;
            }
        }
        for (label k = 0; k < b.size(); ++k)
        {
            EXPECT_EQ(b.component(t)[k], b.component(id)[k]);
            EXPECT_EQ(b.cell()[k], a.cell()[k]);
        }
        EXPECT_EQ(b.binStart(), a.binStart());
        expectBinsHoldTheirParticles(b, o);

        // The binning is that of the next sort, which keeps it
        EXPECT_FALSE(b.sortByCell(g, o, 1));
    }

    particleArrays none = randomParticles(g, 0);
    EXPECT_EQ(none.removeAndSort(std::vector<char>(), g, o), 0);
    EXPECT_EQ(none.size(), 0);
    expectBinsHoldTheirParticles(none, o);

    particleArrays p = randomParticles(g, 10);
    const std::string msg = foamErrorMessage
    (
        [&]{ p.removeAndSort(std::vector<char>(9, 0), g, o); }
    );
    EXPECT_NE(msg.find("9 flags for 10 particles"), std::string::npos) << msg;
}


namespace
{

//- Particles binned in o with maxStale 1, then halves appended for parents
//  (copies of them, with ids n, n + 1, ...); t holds the ids and r the
//  storage index
markedParticles withHalves
(
    const gridGeometry& g,
    const tileCellOrder& o,
    const label n,
    const std::vector<label>& parents
)
{
    markedParticles m = withMarkedFields(g, n);
    particleArrays& p = m.p;
    p.sortByCell(g, o, 1);
    const label first = p.append(label(parents.size()));
    for (size_t k = 0; k < parents.size(); ++k)
    {
        for (label c = 0; c < p.nComponentArrays(); ++c)
        {
            p.component(c)[first + k] = p.component(c)[parents[k]];
        }
        p.component(m.id)[first + k] = n + k;
    }
    for (label i = 0; i < p.size(); ++i)
    {
        p.component(m.t)[i] = p.component(m.id)[i];
        p.component(m.r)[i] = i;
    }
    return m;
}

//- The order a placement gives (the old index of each particle): each kept
//  particle of the n before the append, then its kept halves
std::vector<label> placedOrder
(
    const label n,
    const std::vector<label>& parents,
    const std::vector<char>& flagged
)
{
    std::vector<label> from;
    const label nHalves = label(parents.size());
    for (label i = 0, k = 0; i < n; ++i)
    {
        if (!flagged[i])
        {
            from.push_back(i);
        }
        for (; k < nHalves && parents[k] == i; ++k)
        {
            if (!flagged[n + k])
            {
                from.push_back(n + k);
            }
        }
    }
    return from;
}

//- The binning's starts are those a count of its bins gives (empty bins
//  included), and the next sort keeps it
void expectBinningOfACount
(
    const particleArrays& p,
    const gridGeometry& g,
    const tileCellOrder& o
)
{
    expectBinsHoldTheirParticles(p, o);
    particleArrays counted = p;
    ASSERT_TRUE(counted.setBins(g, p.cell()));
    EXPECT_FALSE(counted.sortByCell(g, o, 1));
    EXPECT_EQ(counted.binStart(), p.binStart());
    EXPECT_TRUE(std::is_sorted(p.binStart().begin(), p.binStart().end()));
}

} // End anonymous namespace


TEST(particleArrays, AppendedPlacedAfterTheirParentsKeepTheBinning)
{
    // A split's halves (appended, parents ascending, one parent twice)
    // placed right after their parents in their parents' bins, and flagged
    // particles removed (a parent and a half among them): every array a
    // removal moves follows, a recomputed one is only shortened, and the
    // binning is that of a count of its bins, kept by the next sort. The
    // same on any number of threads; few particles leave bins empty. The
    // arrays move in place: with a removal in every 50 most runs move up,
    // with one in every 5 down (fewer particles after than before the
    // append); 500,003 particles move more than the last-level cache holds,
    // with streaming stores
    const gridGeometry g = grid2D();
    const tileCellOrder o(g, 4);
    const std::pair<label, label> sizeAndRemovals[] =
        {{1003, 50}, {60, 50}, {500003, 50}, {500003, 5}};
    for (const auto& [n, removedEvery] : sizeAndRemovals)
    {
        std::vector<label> parents;
        for (label i = 3; i < n; i += 17)
        {
            parents.push_back(i);
        }
        parents.insert(parents.begin() + 2, parents[2]);
        const label nHalves = label(parents.size());
        std::vector<std::vector<double>> ids;
        for (const int nThreads : {1, 2, 3, 7})
        {
            const threadCount threads(nThreads);
            markedParticles m = withHalves(g, o, n, parents);
            particleArrays& p = m.p;
            const label first = n;
            particleArrays before = p;
            std::vector<char> flagged(p.size(), 0);
            for (label i = 0; i < n; i += removedEvery)
            {
                flagged[i] = 1;
            }
            flagged[parents[1]] = 1;
            flagged[first + nHalves - 1] = 1;
            const label nFlagged =
                std::count(flagged.begin(), flagged.end(), 1);

            EXPECT_EQ
            (
                p.removeAndPlaceAppended(flagged, parents, g, o, 1),
                nFlagged
            );

            const std::vector<label> from = placedOrder(n, parents, flagged);
            ASSERT_EQ(p.size(), label(from.size()));
            for (label k = 0; k < p.size(); ++k)
            {
                const label i = from[k];
                const label parent = i < n ? i : parents[i - first];
                EXPECT_EQ(p.component(m.id)[k], before.component(m.id)[i]);
                EXPECT_EQ(p.component(m.t)[k], before.component(m.t)[i]);
                EXPECT_EQ(p.component(m.r)[k], k);
                EXPECT_EQ
                (
                    p.component(particleArrays::X)[k],
                    before.component(particleArrays::X)[i]
                );
                EXPECT_EQ(p.cell()[k], before.cell()[parent]);
            }
            EXPECT_TRUE(p.binned());
            expectBinningOfACount(p, g, o);
            ids.emplace_back
            (
                p.component(m.id), p.component(m.id) + p.size()
            );
        }
        for (size_t k = 1; k < ids.size(); ++k)
        {
            EXPECT_EQ(ids[k], ids[0]) << "threads' run " << k;
        }
    }

    particleArrays p = randomParticles(g, 10);
    p.append(2);
    const std::string msg = foamErrorMessage
    (
        [&]
        {
            p.removeAndPlaceAppended(std::vector<char>(12, 0), {4, 3}, g, o, 1);
        }
    );
    EXPECT_NE(msg.find("ascending"), std::string::npos) << msg;
}


TEST(particleArrays, AppendedAfterTheLastParticleStaysOrMovesDownByTheRemoved)
{
    // The half of the last particle is already right after it: nothing
    // moves. With the first particle removed, every particle moves one
    // place down, the half too
    const gridGeometry g = grid2D();
    const tileCellOrder o(g, 4);
    const label n = 500;
    for (const bool firstRemoved : {false, true})
    {
        markedParticles m = withHalves(g, o, n, {n - 1});
        particleArrays& p = m.p;
        const particleArrays before = p;
        std::vector<char> flagged(n + 1, 0);
        flagged[0] = firstRemoved;
        EXPECT_EQ
        (
            p.removeAndPlaceAppended(flagged, {n - 1}, g, o, 1),
            label(firstRemoved)
        );
        ASSERT_EQ(p.size(), n + 1 - firstRemoved);
        for (label k = 0; k < p.size(); ++k)
        {
            const label i = k + firstRemoved;
            EXPECT_EQ(p.component(m.id)[k], before.component(m.id)[i]);
            EXPECT_EQ(p.cell()[k], before.cell()[i < n ? i : n - 1]);
        }
        EXPECT_EQ(p.component(m.id)[p.size() - 1], n);
        expectBinningOfACount(p, g, o);
    }
}


TEST(particleArrays, PlacingMovesOnlyTheParticlesBetweenTheFirstChangeAndTheLast)
{
    // Halves placed and particles removed near the start of the arrays:
    // the particles after the last change stay where they are in memory
    // (each array's start moves by their shift, into the room kept before
    // it); near the end those before the first change stay. Removals alone
    // (removeFlagged) the same. Placements that outgrow the room make the
    // arrays anew. The values are those of the order every time, on any
    // number of threads
    const gridGeometry g = grid2D();
    const tileCellOrder o(g, 4);
    const label n = 20000;
    std::vector<label> many;
    for (label i = 0; i < 3000; ++i)
    {
        many.push_back(10 + i);
    }
    struct change
    {
        std::vector<label> parents, removed;
        label firstStaying, lastStaying;
    };
    const change changes[] =
    {
        {{5, 40, 40, 41}, {7, 100, n + 1}, 101, n - 1},
        {{n - 50, n - 10}, {n - 3}, 0, n - 50},
        {{}, {3, 9, 10}, 11, n - 1},
        {{}, {n - 3}, 0, n - 4},
        {many, {}, n, n - 1}
    };
    for (const change& ch : changes)
    {
        for (const int nThreads : {1, 2, 3})
        {
            const threadCount threads(nThreads);
            markedParticles m = withHalves(g, o, n, ch.parents);
            particleArrays& p = m.p;
            std::vector<char> flagged(p.size(), 0);
            for (const label i : ch.removed)
            {
                flagged[i] = 1;
            }
            std::vector<const double*> idAt(p.size()), xAt(p.size());
            for (label i = 0; i < p.size(); ++i)
            {
                idAt[i] = p.component(m.id) + i;
                xAt[i] = p.component(particleArrays::X) + i;
            }
            const particleArrays before = p;
            if (ch.parents.empty())
            {
                p.removeFlagged(flagged);
            }
            else
            {
                p.removeAndPlaceAppended(flagged, ch.parents, g, o, 1);
            }

            const std::vector<label> from =
                placedOrder(n, ch.parents, flagged);
            ASSERT_EQ(p.size(), label(from.size()));
            label nStayed = 0;
            for (label k = 0; k < p.size(); ++k)
            {
                const label i = from[k];
                EXPECT_EQ(p.component(m.id)[k], before.component(m.id)[i]);
                EXPECT_EQ
                (
                    p.component(particleArrays::X)[k],
                    before.component(particleArrays::X)[i]
                );
                if (i >= ch.firstStaying && i <= ch.lastStaying)
                {
                    EXPECT_EQ(p.component(m.id) + k, idAt[i]) << i;
                    EXPECT_EQ(p.component(particleArrays::X) + k, xAt[i]);
                    ++nStayed;
                }
            }
            EXPECT_EQ
            (
                nStayed,
                std::max(ch.lastStaying - ch.firstStaying + 1, label(0))
            );
        }
    }
}


TEST(particleArrays, AppendedPlacedOnlyWhileEveryParticleIsNearItsBin)
{
    // A half moved exactly maxStale cells from its parent's bin is placed;
    // one cell further, or without a binning in this order before the
    // append, the result is removeAndSort's. No halves, everything flagged
    // and fewer particles than threads are placed too
    const gridGeometry g = grid2D();
    const tileCellOrder o(g, 4);
    const label n = 300;
    const std::vector<label> parents{2, 40, 41, 299};
    const double dx = g.upper(0)/g.nCells[0];
    const auto sameAs = [](particleArrays& a, particleArrays& b)
    {
        ASSERT_EQ(a.size(), b.size());
        EXPECT_EQ(a.binStart(), b.binStart());
        EXPECT_EQ(a.cell(), b.cell());
        for (label c = 0; c < a.nComponentArrays(); ++c)
        {
            EXPECT_EQ
            (
                std::vector<double>(a.component(c), a.component(c) + a.size()),
                std::vector<double>(b.component(c), b.component(c) + b.size())
            ) << "component " << c;
        }
    };
    std::vector<char> flagged(n + parents.size(), 0);
    flagged[7] = 1;
    for (const label cells : {1, 2})
    {
        markedParticles m = withHalves(g, o, n, parents);
        particleArrays& a = m.p;
        // The half of parent 40 moved from the parent's bin's cell centre
        const label half = n + 1;
        const label c = a.cell()[parents[1]] % g.nCells[0];
        const double x = (c + 0.5 + (c < 8 ? cells : -cells))*dx;
        a.component(particleArrays::X)[half] = x;
        particleArrays b = a;
        EXPECT_EQ(a.removeAndPlaceAppended(flagged, parents, g, o, 1), 1);
        EXPECT_EQ(b.removeAndSort(flagged, g, o), 1);
        if (cells == 1)
        {
            EXPECT_EQ(a.component(m.id)[41], n + 1) << "placed";
            expectBinningOfACount(a, g, o);
        }
        else
        {
            sameAs(a, b);
        }
    }
    {
        // Binned in another order before the append
        markedParticles m = withHalves(g, tileCellOrder(g, 1), n, parents);
        particleArrays b = m.p;
        EXPECT_EQ(m.p.removeAndPlaceAppended(flagged, parents, g, o, 1), 1);
        EXPECT_EQ(b.removeAndSort(flagged, g, o), 1);
        sameAs(m.p, b);
    }
    {
        // No halves, then every particle flagged
        markedParticles m = withHalves(g, o, n, {});
        particleArrays& p = m.p;
        const particleArrays before = p;
        EXPECT_EQ
        (
            p.removeAndPlaceAppended(std::vector<char>(n, 0), {}, g, o, 1),
            0
        );
        EXPECT_EQ(p.binStart(), before.binStart());
        EXPECT_EQ
        (
            p.removeAndPlaceAppended(std::vector<char>(n, 1), {}, g, o, 1),
            n
        );
        EXPECT_EQ(p.size(), 0);
        expectBinsHoldTheirParticles(p, o);
    }
    {
        // Three particles and a half on seven threads
        const threadCount threads(7);
        markedParticles m = withHalves(g, o, 3, {1});
        EXPECT_EQ
        (
            m.p.removeAndPlaceAppended(std::vector<char>(4, 0), {1}, g, o, 1),
            0
        );
        EXPECT_EQ(m.p.component(m.id)[2], 3);
        expectBinningOfACount(m.p, g, o);
    }
}


TEST(particleArrays, CountingSortIsStableAndTheSameOnAnyNumberOfThreads)
{
    // The threads count and place ranges of ranks split where the
    // particles' ranks are: sorted from random order, and again after
    // moves and an append (nearly in order), with and without a removal
    const gridGeometry g = grid2D();
    const tileCellOrder o(g, 4);
    const label n = 5003;
    std::vector<std::vector<double>> ids;
    std::vector<std::vector<label>> bins;
    for (const int nThreads : {1, 2, 3, 7})
    {
        const threadCount threads(nThreads);
        particleArrays p = randomParticles(g, n);
        const label id = p.field("id").first;
        p.sortByCell(g, o, 1);
        std::mt19937 gen(5);
        std::uniform_real_distribution<double> u(-0.3, 0.3);
        double* x = p.component(particleArrays::X);
        double* y = p.component(particleArrays::Y);
        for (label i = 0; i < n; ++i)
        {
            x[i] = std::min(std::max(x[i] + u(gen), 0.0), g.upper(0));
            y[i] = std::min(std::max(y[i] + u(gen), 0.0), g.upper(1));
        }
        const label first = p.append(100);
        x = p.component(particleArrays::X);
        y = p.component(particleArrays::Y);
        for (label i = first; i < p.size(); ++i)
        {
            x[i] = 0.5*(u(gen) + 0.3)*g.upper(0)/0.3;
            y[i] = 0.5*(u(gen) + 0.3)*g.upper(1)/0.3;
            p.component(id)[i] = i;
        }
        const label slot =
            p.addField("slot", particleArrays::fieldKind::scalar);
        for (label i = 0; i < p.size(); ++i)
        {
            p.component(slot)[i] = i;
        }
        particleArrays q = p;
        std::vector<char> flagged(p.size(), 0);
        for (label i = 0; i < p.size(); i += 7)
        {
            flagged[i] = 1;
        }
        ASSERT_TRUE(p.sortByCell(g, o, 1));
        q.removeAndSort(flagged, g, o);
        for (const particleArrays* s : {&p, &q})
        {
            expectBinsHoldTheirParticles(*s, o);
            ids.emplace_back(s->component(id), s->component(id) + s->size());
            bins.push_back(s->binStart());
            // Stable: within a bin, in the storage order of before
            const double* was = s->component(slot);
            for (size_t b = 0; b + 1 < bins.back().size(); ++b)
            {
                for (label i = bins.back()[b] + 1; i < bins.back()[b + 1]; ++i)
                {
                    EXPECT_LT(was[i - 1], was[i]);
                }
            }
        }
    }
    for (size_t k = 2; k < ids.size(); ++k)
    {
        EXPECT_EQ(ids[k], ids[k % 2]) << "sort " << k;
        EXPECT_EQ(bins[k], bins[k % 2]) << "sort " << k;
    }

    // Every particle in two cells: most threads' ranges are empty, and one
    // may hold only the removed (a team of another size for the placement
    // than for the counts is not reachable but by OMP_DYNAMIC)
    std::vector<double> crowdedIds;
    for (const int nThreads : {1, 3, 7})
    {
        const threadCount threads(nThreads);
        particleArrays p = randomParticles(g, 300);
        double* x = p.component(particleArrays::X);
        for (label i = 0; i < p.size(); ++i)
        {
            x[i] = i % 3 ? 0.1 : 0.6;
            p.component(particleArrays::Y)[i] = 0.1;
        }
        std::vector<char> flagged(p.size(), 0);
        for (label i = 0; i < p.size(); i += 2)
        {
            flagged[i] = 1;
        }
        EXPECT_EQ(p.removeAndSort(flagged, g, o), 150);
        expectBinsHoldTheirParticles(p, o);
        const double* id = p.component(p.field("id").first);
        if (nThreads == 1)
        {
            crowdedIds.assign(id, id + p.size());
        }
        EXPECT_EQ(std::vector<double>(id, id + p.size()), crowdedIds);
    }
}


TEST(particleArrays, TransientAndRecomputedComponentsStayWhereTheyAre)
{
    // A transient component stays at a sort and moves at a removal; a
    // recomputed one stays at both, a removal only shortens it
    const gridGeometry g = grid2D();
    const label n = 500;
    markedParticles m = withMarkedFields(g, n);
    particleArrays& p = m.p;
    const label id = m.id, t = m.t, r = m.r;
    const auto fill = [&]
    {
        for (label i = 0; i < p.size(); ++i)
        {
            p.component(t)[i] = 10 + i;
            p.component(r)[i] = 20 + i;
        }
    };

    fill();
    ASSERT_TRUE(p.sortByCell(g));
    label moved = 0;
    for (label i = 0; i < n; ++i)
    {
        moved += p.component(id)[i] != i;
        EXPECT_EQ(p.component(t)[i], 10 + i);
        EXPECT_EQ(p.component(r)[i], 20 + i);
    }
    EXPECT_GT(moved, n/2);

    fill();
    std::vector<double> idBefore(p.component(id), p.component(id) + n);
    std::vector<char> flagged(n, 0);
    for (label i = 0; i < n; i += 5)
    {
        flagged[i] = 1;
    }
    EXPECT_EQ(p.removeFlagged(flagged), n/5);
    label k = 0;
    for (label i = 0; i < n; ++i)
    {
        if (!flagged[i])
        {
            EXPECT_EQ(p.component(id)[k], idBefore[i]);
            EXPECT_EQ(p.component(t)[k], 10 + i);
            EXPECT_EQ(p.component(r)[k], 20 + k);
            ++k;
        }
    }
    EXPECT_EQ(k, p.size());

    const std::string msg = foamErrorMessage([&]{ p.markRecomputed(r, 2); });
    EXPECT_NE(msg.find("component arrays"), std::string::npos) << msg;
}


// ************************************************************************* //
