/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    barrierMonitor's book, on a grid of 0.1 x 0.15 x 0.2 m cells
    (barrierProbe.H):
    - force and peak: each step's force is kept, the peak is the largest
      magnitude so far and its time (a later equal one does not move it);
    - run-up: the highest node outside the barrier within 1.5 cells
      (0.3 m) of it that holds more than the mass tolerance, per step and
      the highest so far; nodes farther away or inside do not count; the
      same from the flow's box of nodes over a slope of several blocks of
      nodes beside it (nodeBlockBoxes) as counted over every node;
    - overtopping along overtoppingDirection (any length): the mass of the
      particles beyond the barrier's last contact node (a box from x = 0.42
      to 0.58: its nodes at x = 0.5), plus the mass that left the domain
      beyond it; a wall between two node planes (no contact node) is
      passed beyond its far side (x = 0.56); none without the keyword.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include <gtest/gtest.h>

using namespace Foam;

namespace
{

//- Particles at x (y and z inside the probes' grid) of masses m
particleArrays particlesAt
(
    const std::vector<double>& x,
    const std::vector<double>& m
)
{
    particleArrays p;
    p.append(label(x.size()));
    for (size_t i = 0; i < x.size(); ++i)
    {
        p.component(particleArrays::X)[i] = x[i];
        p.component(particleArrays::Y)[i] = 0.6;
        p.component(particleArrays::Z)[i] = 0.5;
        p.component(particleArrays::M)[i] = m[i];
    }
    return p;
}

} // End anonymous namespace


TEST(barrierMonitor, ForceOfEachStepAndItsPeakWithTime)
{
    IStringStream is("contact slip;");
    barrierMonitor monitor("wall", dictionary(is));
    const mpm3dGrid noNodes;
    const struct { vector F; scalar t, peak, peakTime; } steps[] =
    {
        {vector(3, 4, 0), 0.1, 5, 0.1},
        {vector(0, 0, 2), 0.2, 5, 0.1},
        {vector(6, 8, 0), 0.3, 10, 0.3},
        {vector(-6, 0, -8), 0.4, 10, 0.3}
    };
    for (const auto& s : steps)
    {
        monitor.execute(s.F, noNodes, nodeBox(), 0, s.t);
        EXPECT_EQ(monitor.force(), s.F) << s.t;
        EXPECT_EQ(monitor.peakForce(), s.peak) << s.t;
        EXPECT_EQ(monitor.peakTime(), s.peakTime) << s.t;
    }
    EXPECT_FALSE(monitor.measuresOvertopping());
    EXPECT_EQ(monitor.overtoppingMass(particlesAt({0.9}, {1})), 0);
}


TEST(barrierMonitor, RunUpIsTheHighestNodeBesideTheBarrierHoldingFlow)
{
    // The material at x < 0.55
    barrierProbe probe
    (
        "type plane; point (0.55 0 0); normal (-1 0 0); contact slip;"
    );
    const gridGeometry& g = probe.grid();
    const scalar massTol = 1e-6;
    mpm3dGrid grid;
    grid.resize(g.nNodes());
    auto hold = [&](const label i, const label k, const scalar m)
    {
        grid.mass[g.nodeIndex(i, 4, k)] = m;
    };
    // x = 0.4, z = 0.4 and x = 0.3, z = 0.8: beside it; x = 0.2, z = 1:
    // 0.35 m away; x = 0.6, z = 1.2: inside
    hold(4, 2, 1);
    hold(3, 4, 1);
    hold(2, 5, 1);
    hold(6, 6, 1);
    nodeBox all;
    for (int d = 0; d < 3; ++d)
    {
        all.hi[d] = g.nNodesDir[d];
    }
    probe.wall().execute(grid, all, massTol, 0.1);
    const barrierMonitor& monitor = probe.wall().monitor();
    constexpr double tol = 1e-15; // node coordinates' round-off
    EXPECT_NEAR(monitor.runUp(), 0.8, tol);

    // Only x = 0.5, z = 0.2 holds flow now
    grid.mass.assign(grid.mass.size(), 0);
    hold(5, 1, 1);
    probe.wall().execute(grid, all, massTol, 0.2);
    EXPECT_NEAR(monitor.runUp(), 0.2, tol);
    EXPECT_NEAR(monitor.maxRunUp(), 0.8, tol);
    // The same from the flow's box: that node's
    probe.wall().execute
    (
        grid, g.nodeBoxOf(g.nodeIndex(5, 4, 1)), massTol, 0.2
    );
    EXPECT_NEAR(monitor.runUp(), 0.2, tol);

    // Below the mass tolerance: none
    hold(5, 1, 0.5*massTol);
    probe.wall().execute(grid, all, massTol, 0.3);
    EXPECT_EQ(monitor.runUp(), -GREAT);
    EXPECT_NEAR(monitor.maxRunUp(), 0.8, tol);
}


// A slope with several blocks of nodes beside it and a patch of flow moved
// over it: the run-up from the flow's box is the highest node beside the
// slope holding flow, counted over every node
TEST(barrierMonitor, RunUpFromTheFlowsBoxOverSeveralBlocks)
{
    const gridGeometry g = slopeGrid();
    barrierProbe probe
    (
        slopeText("slip"), fileName(DAMPM_TEST_MESHES), noWalls, g
    );
    const double onSurface = nodeContact::surfaceTolerance(g);
    const double near = 1.5*g.hMax();

    // Mass at every node of the columns i0 .. i0 + 7, j0 .. j0 + 5
    const label patches[3][2] = {{5, 5}, {45, 40}, {30, 20}};
    for (const auto& patch : patches)
    {
        mpm3dGrid grid;
        grid.resize(g.nNodes());
        nodeBox box;
        double expected = -GREAT;
        for (label k = -1; k <= g.nCells[2] + 1; ++k)
        {
            for (label j = patch[1]; j < patch[1] + 6; ++j)
            {
                for (label i = patch[0]; i < patch[0] + 8; ++i)
                {
                    const gridGeometry::index nodei = g.nodeIndex(i, j, k);
                    grid.mass[nodei] = 1;
                    double x[3];
                    g.nodePosition(nodei, x);
                    const double phi = probe.distance(point(x[0], x[1], x[2]));
                    if (phi > onSurface && phi <= near)
                    {
                        expected = std::max(expected, x[2]);
                    }
                    box.unite(g.nodeBoxOf(nodei));
                }
            }
        }
        ASSERT_GT(expected, -GREAT);
        probe.wall().execute(grid, box, 1e-6, 0.1);
        EXPECT_EQ(probe.wall().monitor().runUp(), expected)
            << patch[0] << " " << patch[1];
    }
}


TEST(barrierMonitor, OvertoppingIsTheMassBeyondTheLastContactNode)
{
    barrierProbe probe
    (
        "type box; min (0.42 0.3 0.2); max (0.58 0.9 0.8); contact slip;"
        " overtoppingDirection (2 0 0);"
    );
    barrierMonitor& monitor = probe.wall().monitor();
    ASSERT_TRUE(monitor.measuresOvertopping());
    EXPECT_EQ(monitor.passLevel(), 0.5);
    const particleArrays p = particlesAt({0.45, 0.55, 0.9}, {1, 2, 4});
    EXPECT_EQ(monitor.overtoppingMass(p), 6);
    monitor.addPassedOutflow(0.5);
    EXPECT_EQ(monitor.overtoppingMass(p), 6.5);

    // No contact node: beyond the far side
    barrierProbe thin
    (
        "type box; min (0.52 0.3 0.2); max (0.56 0.9 0.8); contact slip;"
        " overtoppingDirection (1 0 0);"
    );
    EXPECT_EQ(thin.wall().contact().nodes().size(), 0u);
    EXPECT_EQ(thin.wall().monitor().passLevel(), 0.56);
    // Of the particles only the one at x = 0.9
    EXPECT_EQ(thin.wall().monitor().overtoppingMass(p), 4);
}


// ************************************************************************* //
