/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    The columns S9 leaves as they are (restingColumns): steps of S8 and S9
    on random columns over nodes that move in part of the grid, once with
    the quiet cells skipped and once over every column, give every column
    array and mark the same bits, step after step: while a region moves,
    after it stops (columns that moved last step are taken again), when it
    moves again, by up to 0.85 cells a step, and after a column is changed
    outside S9 (woken). No map in the first step, after a step that may
    have moved a column by restingColumns::maxMove cells, or when too few
    nodes rest. After every step, the node sums the next step keeps
    (keptNodes) are those of their definition, node by node and cell by
    cell, with some cells' columns given another bin.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "restingColumns.H"
#include "shapeKernels.H"
#include "columnMotionArrays.H"
#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

using namespace Foam;

namespace
{

//- Random columns four to a cell, moving, with random footprints
struct columns
:
    columnMotionArrays
{
    columns(const gridGeometry& g, const int n, std::mt19937& gen)
    :
        columnMotionArrays(n)
    {
        std::uniform_real_distribution<double> u(0, 1), v(-1, 1);
        const int nc = g.nCells[0]*g.nCells[1];
        for (int i = 0; i < n; ++i)
        {
            // Four to a cell, cell after cell (the last few anywhere), as
            // the solver stores them
            const int c = i/4 < nc ? i/4 : int(u(gen)*nc);
            x[i] = g.origin[0] + g.dx[0]*(c % g.nCells[0] + u(gen));
            y[i] = g.origin[1] + g.dx[1]*(c/g.nCells[0] + u(gen));
            ux[i] = v(gen);
            uy[i] = v(gen);
            V[i] = 0.1*(1 + u(gen));
            for (int k = 0; k < 4; ++k)
            {
                C[k][i] = v(gen);
            }
            // Footprints of a quarter of a cell, some unsheared (their
            // off-diagonals +0 and -0)
            F[0][i] = 0.5*g.dx[0]*(1 + 0.1*v(gen));
            F[3][i] = 0.5*g.dx[1]*(1 + 0.1*v(gen));
            F[1][i] = i % 3 == 0 ? 0.0 : (i % 3 == 1 ? -0.0 : 0.02*v(gen));
            F[2][i] = i % 5 == 0 ? -0.0 : 0.02*v(gen);
        }
    }

    //- Will column i be split: marked, and its halves inside the domain
    //  (depthAveragedSplitting::split)? A column at rest marked but not
    //  split stays so: skipped, it is not marked, to the same effect
    bool splits(const splitRule& rule, const int i) const
    {
        const double Fi[4] = {F[0][i], F[1][i], F[2][i], F[3][i]};
        return split[i] && rule.fits(Fi, x[i], y[i]);
    }

    //- Every array the same, bit for bit, and the same columns to split
    bool same(const columns& o, const splitRule& rule) const
    {
        bool all = true;
        for (size_t i = 0; i < split.size(); ++i)
        {
            all = all && splits(rule, i) == o.splits(rule, i);
        }
        return all && sameState(o);
    }
};


//- Steps of S8 and S9, once skipping the quiet cells (a) and once over
//  every column (b)
template<class Kernel>
struct restSteps
{
    const Kernel kernel;
    const gridGeometry g;
    nodeBox box;
    shallowGrid grid;
    std::mt19937 gen;
    columns a, b;
    restingColumns resting;
    splitRule rule;
    const double dt = 0.25;

    //- The cells woken in this step, and the steps after which some node
    //  kept its sums
    std::vector<gridGeometry::index> woken;
    int nKeeping = 0;
    std::mt19937 binGen{11};

    explicit restSteps(const Kernel& k)
    :
        kernel(k),
        g(uniformGrid(2, {3, -2, 0}, {0.5, 0.4, 1}, {30, 24, 1})),
        box(g.allNodes()),
        gen(5),
        a(g, 4*30*24 + 3, gen),
        b(a)
    {
        grid.resize(g.nNodes());
        // Split marks for footprints above half a cell (none at the start)
        rule.maxArea = 0.5*g.dx[0]*g.dx[1];
        rule.hSplit = 0;
        for (int d = 0; d < 2; ++d)
        {
            rule.cell[d] = g.dx[d];
            rule.lo[d] = g.origin[d];
            rule.hi[d] = g.domainUpper(d);
        }
    }

    //- S8 with node momenta from speed(i, j) (a node's mass 1, no load),
    //  S9 both ways, then changed(); the quiet map, null if none
    template<class Speed>
    const uint8_t* step
    (
        const Speed& speed,
        const std::function<void()>& changed = []{}
    )
    {
        std::uniform_real_distribution<double> v(-1, 1);
        for (label j = 0; j < g.nNodesDir[1]; ++j)
        {
            for (label i = 0; i < g.nNodesDir[0]; ++i)
            {
                const label n = i + g.nNodesDir[0]*j;
                double* mp = grid.momentum.data() + shallowGrid::nMomentum*n;
                const double s = speed(i, j);
                mp[shallowGrid::M] = 1;
                mp[shallowGrid::PX] = s*v(gen);
                mp[shallowGrid::PY] = s*v(gen);
            }
        }
        resistanceUpdate
        (
            g, box, grid, domainSides(), dt, 1e-9, false,
            resting.nodes(g, box)
        );
        const uint8_t* quiet = resting.quietCells(g);
        const domainSides sides;

        // Does this step move every column by less than maxMove cells?
        double maxSpeed2 = 0;
        for (label n = 0; n < g.nNodes(); ++n)
        {
            const double* v = grid.velocity.data() + shallowGrid::nVelocity*n;
            maxSpeed2 = std::max(maxSpeed2, v[0]*v[0] + v[1]*v[1]);
        }
        const double reach = restingColumns::maxMove*std::min(g.dx[0], g.dx[1]);
        const bool bounded = dt*dt*maxSpeed2 < reach*reach;

        const columnMotion qa = a.motion(), qb = b.motion();
        const label nA = gridToColumns
        (
            g, kernel, grid.velocity.data(),
            columnAdvance(g, sides, dt, true, rule, qa), quiet
        );
        const label nB = gridToColumns
        (
            g, kernel, grid.velocity.data(),
            columnAdvance(g, sides, dt, true, rule, qb)
        );
        EXPECT_EQ(nA, nB);
        woken.clear();
        changed();
        splitMarked();
        resting.endStep(g, dt);
        checkKept(bounded ? quiet : nullptr);
        return quiet;
    }

    //- Column (x, y) changed outside S9
    void wake(const double x, const double y)
    {
        resting.wake(g, x, y);
        woken.push_back(g.cellIndex(g.cellDir(0, x), g.cellDir(1, y), 0));
    }

    //- keptNodes against its definition (restingColumns.H): S3 kept at a
    //  node whose cells c - 2 .. c + 1 per axis are all stable (quiet, not
    //  woken, no column given another bin), S7 where the nodes within 3
    //  keep S3; per cell, do its nodes c - 1 .. c + 2 keep, any or all?
    //  (A cell at its first node c + nGhost; none outside the grid.) No
    //  cell is stable without a map (quiet null)
    void checkKept(const uint8_t* quiet)
    {
        typedef gridGeometry::index index;
        const index nCx = g.nCells[0], nCy = g.nCells[1];
        const index nx = g.nNodesDir[0], ny = g.nNodesDir[1];
        const index nG = gridGeometry::nGhost;

        // Some cells' columns given another bin by a re-bin
        std::vector<uint8_t> binChanged(nCx*nCy, 0);
        std::uniform_int_distribution<index> anyCell(0, nCx*nCy - 1);
        for (int k = 0; k < 5; ++k)
        {
            binChanged[anyCell(binGen)] = 1;
        }
        const keptSums kept = resting.keptNodes(g, true, binChanged.data());

        std::vector<uint8_t> stable(nCx*nCy, 0);
        for (index c = 0; quiet && c < nCx*nCy; ++c)
        {
            stable[c] = quiet[c] && !binChanged[c];
        }
        for (const index c : woken)
        {
            stable[c] = 0;
        }
        // All of f over the window lo .. hi per axis of node (i, j)
        const auto all = [&]
        (
            const index i, const index j, const int lo, const int hi,
            const std::function<bool(index, index)>& f
        )
        {
            bool a = true;
            for (int b = lo; b <= hi; ++b)
            {
                for (int d = lo; d <= hi; ++d)
                {
                    a = a && f(i + d, j + b);
                }
            }
            return a;
        };
        const auto stableCell = [&](const index ci, const index cj)
        {
            return
                ci >= 0 && ci < nCx && cj >= 0 && cj < nCy
             && stable[ci + nCx*cj];
        };
        const auto keeps3 = [&](const index i, const index j)
        {
            return
                i >= 0 && i < nx && j >= 0 && j < ny
             && all(i - nG, j - nG, -2, 1, stableCell);
        };

        std::vector<uint8_t> nodes(nx*ny, 0);
        bool any = false, anyLoads = false;
        for (index j = 0; j < ny; ++j)
        {
            for (index i = 0; i < nx; ++i)
            {
                const bool k3 = keeps3(i, j);
                const bool k7 = k3 && all(i, j, -3, 3, keeps3);
                nodes[i + nx*j] = uint8_t
                (
                    (k3 ? keptSums::momentumKept : 0)
                  | (k7 ? keptSums::loadsKept : 0)
                );
                any = any || k3;
                anyLoads = anyLoads || k7;
            }
        }
        nKeeping += any;
        ASSERT_EQ(kept.nodes != nullptr, any);
        // A pass does not look where no node keeps its sum
        EXPECT_EQ(kept.of(true).cells != nullptr, anyLoads);
        if (!any)
        {
            return;
        }
        for (index n = 0; n < nx*ny; ++n)
        {
            ASSERT_EQ(kept.nodes[n], nodes[n]) << "node " << n;
        }
        for (index cj = 0; cj < nCy; ++cj)
        {
            for (index ci = 0; ci < nCx; ++ci)
            {
                uint8_t code = 0;
                for (const bool loads : {false, true})
                {
                    const keptSums k = keptSums().of(loads);
                    const auto keeps = [&](const index i, const index j)
                    {
                        return
                            i >= 0 && i < nx && j >= 0 && j < ny
                         && (nodes[i + nx*j] & k.node);
                    };
                    bool touch = false, every = true;
                    for (int b = -1; b <= 2; ++b)
                    {
                        for (int a = -1; a <= 2; ++a)
                        {
                            const bool kn = keeps(ci + nG + a, cj + nG + b);
                            touch = touch || kn;
                            every = every && kn;
                        }
                    }
                    code |= (touch ? k.touch : 0) | (every ? k.all : 0);
                }
                ASSERT_EQ(kept.cells[ci + nCx*cj], code)
                    << "cell " << ci << " " << cj;
            }
        }
    }

    //- As the solver's split: the columns to split change (their
    //  footprints halved here) and are woken
    void splitMarked()
    {
        for (int i = 0; i < int(a.x.size()); ++i)
        {
            if (a.splits(rule, i) && b.splits(rule, i))
            {
                a.F[0][i] *= 0.5;
                b.F[0][i] *= 0.5;
                wake(a.x[i], a.y[i]);
            }
        }
    }

    //- Quiet cells of a map
    label nQuiet(const uint8_t* quiet) const
    {
        label nq = 0;
        for (label c = 0; quiet && c < g.nCells[0]*g.nCells[1]; ++c)
        {
            nq += quiet[c] != 0;
        }
        return nq;
    }
};


template<class Kernel>
void checkRestingColumns(const Kernel& kernel)
{
    restSteps<Kernel> t(kernel);
    const label nCells = t.g.nCells[0]*t.g.nCells[1];
    // Node speeds that move a column by at most 0.25 of the smaller cell
    const double slow = 0.25*0.4/t.dt;
    // Nodes i < 12 move
    const auto left = [&](label i, label) { return i < 12 ? slow : 0.0; };
    const auto none = [](label, label) { return 0.0; };

    // Nothing known of the last step: no map
    EXPECT_EQ(t.step(left), nullptr);
    EXPECT_TRUE(t.a.same(t.b, t.rule));

    // The right part has rested for two steps
    for (int s = 0; s < 3; ++s)
    {
        const uint8_t* quiet = t.step(left);
        const label nq = t.nQuiet(quiet);
        EXPECT_GT(nq, nCells/4);
        EXPECT_LT(nq, 3*nCells/4);
        EXPECT_TRUE(t.a.same(t.b, t.rule)) << "step " << s;
    }

    // Everything stops: the columns that moved last step are taken again
    // (their velocities become zero), then skipped
    EXPECT_LT(t.nQuiet(t.step(none)), 3*nCells/4);
    EXPECT_TRUE(t.a.same(t.b, t.rule));
    EXPECT_GT(t.nQuiet(t.step(none)), 3*nCells/4);
    EXPECT_TRUE(t.a.same(t.b, t.rule));

    // A column at rest outgrows the split's area outside S9 (a half of a
    // split): woken, S9 marks it for the split that skipping would miss
    const int k = 4*(20 + 30*10) + 1;
    ASSERT_GT(t.a.x[k], t.g.origin[0] + 15*t.g.dx[0]);
    t.step
    (
        none,
        [&]
        {
            for (columns* c : {&t.a, &t.b})
            {
                c->F[0][k] = 0.9*t.g.dx[0];
                c->F[3][k] = 0.9*t.g.dx[1];
            }
            t.wake(t.a.x[k], t.a.y[k]);
        }
    );
    EXPECT_NE(t.step(none), nullptr);
    EXPECT_TRUE(t.a.same(t.b, t.rule));
    EXPECT_TRUE(t.a.splits(t.rule, k));

    // The left part moves again
    t.step(left);
    EXPECT_TRUE(t.a.same(t.b, t.rule));
    t.step(left);
    EXPECT_TRUE(t.a.same(t.b, t.rule));

    // Moves of up to 0.85 of the smaller cell a step, then a stop: a map
    // every step, the columns that moved taken again
    const double fast = 0.85*0.4/(std::sqrt(2.0)*t.dt);
    const auto leftFast = [&](label i, label) { return i < 12 ? fast : 0.0; };
    for (int s = 0; s < 3; ++s)
    {
        EXPECT_NE(t.step(leftFast), nullptr);
        EXPECT_TRUE(t.a.same(t.b, t.rule)) << "fast step " << s;
    }
    for (int s = 0; s < 2; ++s)
    {
        EXPECT_NE(t.step(none), nullptr);
        EXPECT_TRUE(t.a.same(t.b, t.rule)) << "stop " << s;
    }

    // A node at more than maxMove cells a step: no map in the next step
    t.step
    (
        [&](label i, label j) { return i == 20 && j == 10 ? 20*slow : 0.0; }
    );
    EXPECT_TRUE(t.a.same(t.b, t.rule));
    EXPECT_EQ(t.step(none), nullptr);
    EXPECT_TRUE(t.a.same(t.b, t.rule));
    EXPECT_GT(t.nKeeping, 5);

    // Fewer than a tenth of the nodes at rest: no map
    t.step(none);
    EXPECT_EQ
    (
        t.step([&](label i, label) { return i < 31 ? slow : 0.0; }),
        nullptr
    );
    EXPECT_TRUE(t.a.same(t.b, t.rule));
}

} // End anonymous namespace


TEST(restingColumns, SkippedColumnsAreWhatG2PGivesThemQuadraticBSpline)
{
    checkRestingColumns(quadraticBSplineKernel());
}


TEST(restingColumns, SkippedColumnsAreWhatG2PGivesThemLinear)
{
    checkRestingColumns(linearKernel());
}


TEST(restingColumns, SkippedColumnsAreWhatG2PGivesThemGIMP)
{
    checkRestingColumns(GIMPKernel(0.25));
}


// ************************************************************************* //
