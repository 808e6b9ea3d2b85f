/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    mpm3dKernels: the node spans a step clears and updates hold every node
    the wall folds write (wallFoldSpans), so that no node sum outlives its
    step. A block drifting two to four cells above the floor and beside the
    side walls, with a layer on the floor elsewhere, is the layout where
    the particles' stencil spans split the fold's triples (mirror inside,
    ghost outside).

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "mpm3dKernels.H"
#include "particleArrays.H"
#include "shapeKernels.H"
#include "stencil.H"
#include <gtest/gtest.h>
#include <array>
#include <random>

using namespace Foam;

namespace
{

// A channel walled as stability/restart3D's: 5 cm cells, walls at x min,
// both y sides and the floor, open at x max and the top
gridGeometry channel()
{
    return uniformGrid(3, {0, 0, 0}, {0.05, 0.05, 0.05}, {12, 8, 10});
}

constexpr bool channelWalls[3][2] =
    {{true, false}, {true, true}, {true, false}};

constexpr label maxStale = 1;

// The particles' position columns (they move when the particles are sorted)
std::array<double*, 3> positions(particleArrays& p)
{
    return
    {
        p.component(particleArrays::X),
        p.component(particleArrays::Y),
        p.component(particleArrays::Z)
    };
}

// A layer one cell deep on the floor over the first quarter of the channel,
// and a block from 2 to 4 cells above the floor, 1.5 cells from each side
// wall, in the second half
particleArrays layerAndBlock(const gridGeometry& g, std::mt19937& gen)
{
    std::uniform_real_distribution<double> u(0, 1);
    particleArrays p;
    const label nLayer = 400, nBlock = 400;
    p.append(nLayer + nBlock);
    const std::array<double*, 3> x = positions(p);
    for (label i = 0; i < nLayer + nBlock; ++i)
    {
        const bool layer = i < nLayer;
        x[0][i] =
            layer ? 0.25*u(gen)*g.upper(0) : (0.5 + 0.3*u(gen))*g.upper(0);
        x[1][i] = layer
            ? u(gen)*g.upper(1)
            : 1.5*g.dx[1] + u(gen)*(g.upper(1) - 3*g.dx[1]);
        x[2][i] = layer ? u(gen)*g.dx[2] : (2 + 2*u(gen))*g.dx[2];
    }
    return p;
}

// The wall triples over the particles' box that the spans split: some of
// the three nodes inside, some outside
label splitTriples
(
    const gridGeometry& g,
    const nodeBox& box,
    const nodeRowSpans& rows
)
{
    auto inSpans = [&](const gridGeometry::index n)
    {
        const gridGeometry::index row = n/g.nodeStride[1];
        const gridGeometry::index along = n % g.nodeStride[1];
        return along >= rows.lo[row] && along < rows.hi[row];
    };
    label split = 0;
    forEachWallNode
    (
        g, box, channelWalls,
        [&]
        (
            const int,
            const gridGeometry::index w,
            const gridGeometry::index gh,
            const gridGeometry::index mi
        )
        {
            const int in = inSpans(w) + inSpans(gh) + inSpans(mi);
            split += in == 1 || in == 2;
        }
    );
    return split;
}

} // End anonymous namespace


// The layout splits triples of the floor and side walls; widened, the
// spans hold every triple whole or not at all, and still every stencil
// node (they only grow)
TEST(mpm3dKernels, WallFoldSpansHoldEveryFoldedTripleWhole)
{
    const gridGeometry g = channel();
    std::mt19937 gen(7);
    particleArrays p = layerAndBlock(g, gen);
    p.sortByCell(g, scatterSchedule(g, 3 + 2*maxStale));
    const nodeBox box = p.stencilNodes(g);

    nodeRowSpans rows;
    p.stencilRows(g, rows);
    const nodeRowSpans before(rows);
    const label splitBefore = splitTriples(g, box, rows);
    EXPECT_GT(splitBefore, 0) << "the layout must split triples to test";

    wallFoldSpans(g, channelWalls, rows);
    EXPECT_EQ(splitTriples(g, box, rows), 0)
        << splitBefore << " split before widening";
    label shrunk = 0;
    for (size_t r = 0; r < rows.lo.size(); ++r)
    {
        shrunk += before.lo[r] < before.hi[r]
            && (rows.lo[r] > before.lo[r] || rows.hi[r] < before.hi[r]);
    }
    EXPECT_EQ(shrunk, 0);
}


// The step's node life cycle as mpm3dFlow runs it: clear last and this
// step's spans, scatter the mass, fold it across the walls. Over 40 steps
// of the block drifting, no node outside this step's spans holds mass
// after the fold, and the mass the fold gives each mirror node is this
// step's (the same as from a cleared grid): no sum outlives its step
TEST(mpm3dKernels, WallFoldLeavesNoSumOutsideTheClearedSpans)
{
    const gridGeometry g = channel();
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> u(-1, 1);
    particleArrays p = layerAndBlock(g, gen);
    mpm3dGrid nodes, fresh;
    nodes.resize(g.nNodes());
    nodeBox particleBox, active;
    nodeRowSpans rows, lastRows, activeRows;
    // Round-off of sums of at most 27 stencil weights per particle
    constexpr double tol = 1e-12;

    for (int step = 0; step < 40; ++step)
    {
        // Drift by up to 0.3 cells per axis, the block kept clear of the
        // floor's and side walls' ghost rows
        const std::array<double*, 3> x = positions(p);
        for (label i = 0; i < p.size(); ++i)
        {
            if (x[2][i] < g.dx[2])
            {
                continue;
            }
            for (int d = 0; d < 3; ++d)
            {
                x[d][i] += 0.3*g.dx[d]*u(gen);
            }
            x[0][i] =
                std::min(std::max(x[0][i], 0.3*g.upper(0)), 0.9*g.upper(0));
            x[1][i] = std::min(std::max(x[1][i], 1.5*g.dx[1]), 6.5*g.dx[1]);
            x[2][i] = std::min(std::max(x[2][i], 2*g.dx[2]), 4*g.dx[2]);
        }
        p.sortByCell(g, scatterSchedule(g, 3 + 2*maxStale));

        // As mpm3dFlow::particlesToGrid
        active = particleBox;
        particleBox = p.stencilNodes(g);
        active.unite(particleBox);
        std::swap(lastRows, rows);
        p.stencilRows(g, rows);
        wallFoldSpans(g, channelWalls, rows);
        activeRows.unite(lastRows, rows);
        particleBox.rows = &rows;
        active.rows = &activeRows;
        zeroNodes3D(g, active, nodes);

        fresh.resize(g.nNodes());
        for (mpm3dGrid* grid : {&nodes, &fresh})
        {
            double* mass = grid->mass.data();
            const std::array<double*, 3> x = positions(p);
            for (label i = 0; i < p.size(); ++i)
            {
                const stencil<3, quadraticBSplineKernel> s
                (
                    g, quadraticBSplineKernel(), x[0][i], x[1][i], x[2][i]
                );
                s.forEachNode
                (
                    [&](label n, double N, const double*, const double*)
                    {
                        mass[n] += N;
                    }
                );
            }
            foldWalls(g, active, channelWalls, {mass}, {});
        }

        label outside = 0;
        double worst = 0;
        for (gridGeometry::index n = 0; n < g.nNodes(); ++n)
        {
            const gridGeometry::index row = n/g.nodeStride[1];
            const gridGeometry::index along = n % g.nodeStride[1];
            const bool in = along >= rows.lo[row] && along < rows.hi[row];
            outside += !in && nodes.mass[n] != 0;
            worst = std::max(worst, std::abs(nodes.mass[n] - fresh.mass[n]));
        }
        ASSERT_EQ(outside, 0) << "step " << step;
        ASSERT_LE(worst, tol) << "step " << step;
    }
}


// ************************************************************************* //
