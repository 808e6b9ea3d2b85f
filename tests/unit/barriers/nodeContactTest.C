/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    nodeContact, the contact at the nodes (apply), with a plane as the
    barrier on a grid of 0.1 x 0.15 x 0.2 m cells (barrierProbe.H):
    - a node moving into the barrier keeps the tangential velocity (slip),
      loses it (noSlip) or has it reduced by mu |v.n| (Coulomb, down to
      zero), against the closed form and a worked example; the force is
      the momentum taken, m (v - v_new)/dt; a node moving away is left
      alone and takes no force;
    - nodePressure: the normal force m |v.n|/dt over the node's cell seen
      along the normal, |nx| dy dz + |ny| dz dx + |nz| dx dy, for walls
      facing x, y and z and inclined ones (dx dy whatever the wall's
      orientation before: twice too much on a wall facing x here);
    - on the domain's walls the node sums hold the flow's mirror images: a
      node on one wall counts half its momentum change in the force, on two
      a quarter, a ghost node beyond a wall none; its velocity is set all
      the same;
    - the blocks of contact nodes outside the flow's box are skipped: the
      force, the velocities and the node pressure are those of a pass over
      every contact node, bit for bit, also after the flow has left a
      block.

\*---------------------------------------------------------------------------*/

#include "barrierProbe.H"
#include "OStringStream.H"
#include "orderedSums.H"
#include <gtest/gtest.h>
#include <cmath>

using namespace Foam;

namespace
{

//- A plane through a point 0.05 m outside node (i, j, k), by default
//  (5, 4, 3), (so that the node is in contact) with unit normal n, and the
//  contact's keywords
std::string planeThroughNode
(
    const vector& n,
    const std::string& contact,
    const label i = 5,
    const label j = 4,
    const label k = 3
)
{
    const gridGeometry g = probeGrid();
    const point o =
        point(g.nodeCoord(0, i), g.nodeCoord(1, j), g.nodeCoord(2, k))
      + 0.05*n;
    OStringStream os;
    os.precision(17);
    os  << "type plane; point " << o << "; normal " << n << "; contact "
        << contact.c_str() << ";";
    return os.str();
}

//- Round-off of a few products
constexpr double tol = 1e-14;

} // End anonymous namespace


TEST(nodeContact, NodeMovingInLosesItsNormalVelocityByItsContact)
{
    const scalar m = 2, dt = 1e-3;
    const vector n = vector(1, 2, 2)/3;
    const vector v(-1.5, 0.4, -2);
    ASSERT_LT(v & n, 0);
    const std::pair<word, std::string> contacts[] =
    {
        {"slip", "slip"}, {"noSlip", "noSlip"},
        {"Coulomb", "Coulomb; frictionCoefficient 0.3"}
    };
    for (const auto& c : contacts)
    {
        barrierProbe probe(planeThroughNode(n, c.second));
        vector F;
        scalar p;
        const vector vNew = probe.contact(5, 4, 3, m, v, dt, F, p);
        const vector expected = contactVelocity(v, n, c.first, 0.3);
        EXPECT_LT(mag(vNew - expected), tol*mag(v)) << c.first;
        EXPECT_LT(mag(F - m*(v - expected)/dt), tol*m*mag(v)/dt) << c.first;
        EXPECT_NEAR(vNew & n, 0, tol*mag(v)) << c.first;
    }

    // Worked example: into a floor at 4 m/s, 3 m/s along it, mu = 0.5
    barrierProbe floor(planeThroughNode(vector(0, 0, 1),
        "Coulomb; frictionCoefficient 0.5"));
    vector F;
    scalar p;
    EXPECT_LT
    (
        mag(floor.contact(5, 4, 3, m, vector(3, 0, -4), dt, F, p)
          - vector(1, 0, 0)),
        tol
    );
    // Sticks where the tangential speed is within mu |v.n|
    EXPECT_EQ
    (
        floor.contact(5, 4, 3, m, vector(1.5, 0.5, -4), dt, F, p),
        vector(Zero)
    );
}


TEST(nodeContact, NodeMovingAwayIsLeftAlone)
{
    const vector n = vector(-2, 1, 2)/3;
    barrierProbe probe(planeThroughNode(n, "noSlip"));
    const vector v(-1, 1, 0.3);
    ASSERT_GT(v & n, 0);
    vector F;
    scalar p;
    EXPECT_EQ(probe.contact(5, 4, 3, 2, v, 1e-3, F, p), v);
    EXPECT_EQ(F, vector(Zero));
    EXPECT_EQ(p, 0);
}


TEST(nodeContact, NodePressureIsTheNormalForceOverTheNodesAreaOnTheWall)
{
    const gridGeometry g = probeGrid();
    const scalar dx = g.dx[0], dy = g.dx[1], dz = g.dx[2];
    const scalar m = 2, dt = 1e-3;
    const vector normals[] =
    {
        vector(1, 0, 0), vector(0, -1, 0), vector(0, 0, 1),
        vector(1, 2, 2)/3, vector(-2, 1, 2)/3
    };
    for (const vector& n : normals)
    {
        barrierProbe probe(planeThroughNode(n, "slip"));
        // 3 m/s into the wall, 1 m/s along it
        vector t = (n ^ vector(0.3, 0.5, 0.7));
        t /= mag(t);
        vector F;
        scalar p;
        probe.contact(5, 4, 3, m, -3*n + t, dt, F, p);
        const scalar area =
            mag(n.x())*dy*dz + mag(n.y())*dz*dx + mag(n.z())*dx*dy;
        const scalar expected = m*3/dt/area;
        EXPECT_NEAR(p, expected, tol*expected) << "normal " << n;
        EXPECT_NEAR(mag(F), m*3/dt, tol*m*3/dt) << "normal " << n;
    }
}


TEST(nodeContact, NodeOnTheDomainsWallsCountsTheFlowsShareOfTheForce)
{
    const scalar m = 2, dt = 1e-3;
    const vector n(1, 0, 0);
    const vector v(-3, 0.5, 0);
    const vector vNew(0, 0.5, 0);
    // Walls at x min and y min
    const bool walls[3][2] = {{true, false}, {true, false}, {false, false}};
    const struct { label i, j; scalar share; } nodes[] =
    {
        {5, 4, 1},      // inside the domain
        {0, 4, 0.5},    // on the wall x min
        {0, 0, 0.25},   // on both walls: an edge
        {-1, 4, 0}      // a ghost node beyond x min
    };
    for (const auto& node : nodes)
    {
        barrierProbe probe
        (
            planeThroughNode(n, "slip", node.i, node.j, 3),
            fileName(DAMPM_TEST_MESHES),
            walls
        );
        vector F;
        scalar p;
        const vector u = probe.contact(node.i, node.j, 3, m, v, dt, F, p);
        EXPECT_LT(mag(u - vNew), tol*mag(v)) << node.i << " " << node.j;
        EXPECT_LT
        (
            mag(F - node.share*m*(v - vNew)/dt),
            tol*m*mag(v)/dt
        ) << node.i << " " << node.j;
    }
}


// ************************************************************************* //


// A slope of several thousand contact nodes (several blocks of the force's
// ordered sum) and a patch of flow moving over it: with the flow's box the
// contact gives what it gives over the whole grid, bit for bit, also the
// node pressure of the blocks the flow has left
TEST(nodeContact, BlocksOutsideTheFlowsBoxAreSkippedExactly)
{
    const gridGeometry g = slopeGrid();
    const std::string slope = slopeText("Coulomb; frictionCoefficient 0.4");
    // The same barrier twice: over the whole grid, and in the flow's box
    barrierProbe whole(slope, fileName(DAMPM_TEST_MESHES), noWalls, g);
    barrierProbe boxed(slope, fileName(DAMPM_TEST_MESHES), noWalls, g);
    const std::vector<gridGeometry::index>& nodes =
        whole.wall().contact().nodes();
    ASSERT_GT(label(nodes.size()), 3*orderedSumsBlock);

    nodeBox all;
    for (int d = 0; d < 3; ++d)
    {
        all.hi[d] = g.nNodesDir[d];
    }
    // Mass moving into the slope at the contact nodes of a patch of the
    // grid (i0 .. i0 + 7, j0 .. j0 + 5), and the patch's box
    const auto flow = [&](mpm3dGrid& grid, const label i0, const label j0)
    {
        grid.resize(g.nNodes());
        nodeBox box;
        label k = 0;
        for (const gridGeometry::index nodei : nodes)
        {
            gridGeometry::index ijk[3];
            g.nodeIJK(nodei, ijk);
            if
            (
                ijk[0] < i0 || ijk[0] >= i0 + 8
             || ijk[1] < j0 || ijk[1] >= j0 + 6
            )
            {
                continue;
            }
            grid.mass[nodei] = 0.3 + 0.01*(k % 7);
            grid.vx[nodei] = 0.5 - 0.1*(k % 5);
            grid.vy[nodei] = 0.2 + 0.05*(k % 3);
            grid.vz[nodei] = -1.5 - 0.02*(k % 11);
            ++k;
            box.unite(g.nodeBoxOf(nodei));
        }
        EXPECT_GT(k, 20);
        return box;
    };
    const double dt = 1e-3;
    // A patch, one far from it (the first's blocks left), then back
    const label patches[3][2] = {{5, 5}, {45, 40}, {5, 5}};
    for (const auto& patch : patches)
    {
        mpm3dGrid a, b;
        flow(a, patch[0], patch[1]);
        const nodeBox box = flow(b, patch[0], patch[1]);
        whole.wall().applyContact(a, all, 0, dt);
        boxed.wall().applyContact(b, box, 0, dt);
        const vector Fa = whole.wall().contact().force();
        const vector Fb = boxed.wall().contact().force();
        EXPECT_GT(mag(Fa), 0);
        for (int d = 0; d < 3; ++d)
        {
            EXPECT_EQ(Fa[d], Fb[d]);
        }
        EXPECT_TRUE(a.vx == b.vx && a.vy == b.vy && a.vz == b.vz);
        std::vector<double> pa, pb;
        whole.wall().contact().nodePressure(g, pa);
        boxed.wall().contact().nodePressure(g, pb);
        EXPECT_TRUE(pa == pb);
    }
}
