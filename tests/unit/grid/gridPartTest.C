/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    A processor's part of a decomposed grid (gridGeometry's offset, as
    mpmGrid sets it for -parallel) sees what the whole domain sees, bit for
    bit: for points anywhere in the part, the stencils' weights, gradients
    and node offsets of every shape function, and the nodes they reach (as
    domain nodes), also four particles at once on the part (stencilLanes,
    against its scalar stencils); the nodal areas at every node of the part;
    the position of every node; and the domain's geometry recovered from
    the part.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "stencil.H"
#include "depthAveragedRelease.H"
#include <gtest/gtest.h>
#include <random>

using namespace Foam;

namespace
{


//- Domain (i, j) of a node of part p
std::array<int, 2> domainNode(const gridGeometry& p, const int nodei)
{
    gridGeometry::index ijk[3];
    p.nodeIJK(nodei, ijk);
    return {ijk[0] + p.offset[0], ijk[1] + p.offset[1]};
}


template<class Kernel>
void expectSameStencils
(
    const gridGeometry& g,
    const gridGeometry& p,
    const Kernel& kernel
)
{
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0, 1);
    double x[4], y[4];
    for (int s = 0; s < 2000; ++s)
    {
        // Inside the part's cells but its outermost (where the particles of
        // another processor's cells stand)
        const int l = s % 4;
        x[l] = p.lower(0) + p.dx[0]*(1 + (p.nCells[0] - 2)*u(gen));
        y[l] = p.lower(1) + p.dx[1]*(1 + (p.nCells[1] - 2)*u(gen));
        const stencil<2, Kernel> a(g, kernel, x[l], y[l], 0);
        const stencil<2, Kernel> b(p, kernel, x[l], y[l], 0);
        for (int d = 0; d < 2; ++d)
        {
            EXPECT_EQ(a.r0[d], b.r0[d]);
            for (int k = 0; k < Kernel::width; ++k)
            {
                EXPECT_EQ(a.w[d][k], b.w[d][k]);
                EXPECT_EQ(a.dw[d][k], b.dw[d][k]);
            }
        }
        EXPECT_EQ(domainNode(g, a.base), domainNode(p, b.base));
        if (l < 3)
        {
            continue;
        }

        // Four particles at once on the part: its stencils in each lane
        const stencilLanes<Kernel> lanes(p, kernel, x, y);
        for (int m = 0; m < 4; ++m)
        {
            const stencil<2, Kernel> c(p, kernel, x[m], y[m], 0);
            EXPECT_EQ(lanes.base[m], c.base);
            for (int d = 0; d < 2; ++d)
            {
                EXPECT_EQ(lanes.r0[d][m], c.r0[d]);
                for (int k = 0; k < Kernel::width; ++k)
                {
                    EXPECT_EQ(lanes.w[d][k][m], c.w[d][k]);
                    EXPECT_EQ(lanes.dw[d][k][m], c.dw[d][k]);
                }
            }
        }
    }
}

} // End anonymous namespace


TEST(gridPart, StencilsAreTheDomainsBitForBit)
{
    // An origin and spacing whose sums round: (x - origin)/dx is inexact
    const gridGeometry g =
        uniformGrid(2, {-1234.567, 89.1011, 0}, {0.3, 0.7, 1}, {50, 40, 1});
    for (const auto& part :
        {
            std::array<std::array<int, 2>, 2>{{{0, 0}, {26, 21}}},
            {{{24, 0}, {26, 21}}},
            {{{24, 19}, {26, 21}}},
            {{{13, 7}, {9, 17}}}
        })
    {
        const gridGeometry p = partOf(g, part[0], part[1]);
        expectSameStencils(g, p, linearKernel());
        expectSameStencils(g, p, GIMPKernel(0.25));
        expectSameStencils(g, p, quadraticBSplineKernel());
    }
}


TEST(gridPart, NodesAndAreasAreTheDomains)
{
    const gridGeometry g =
        uniformGrid(2, {-1234.567, 89.1011, 0}, {0.3, 0.7, 1}, {50, 40, 1});
    const gridGeometry p = partOf(g, {24, 19}, {26, 21});
    const quadraticBSplineKernel kernel;
    std::vector<double> areaG(g.nNodes()), areaP(p.nNodes());
    nodalAreas(g, kernel, 2, areaG.data());
    nodalAreas(p, kernel, 2, areaP.data());
    for (int n = 0; n < p.nNodes(); ++n)
    {
        const std::array<int, 2> ij = domainNode(p, n);
        const int m = g.nodeIndex(ij[0], ij[1], 0);
        EXPECT_EQ(areaP[n], areaG[m]);
        double xp[3], xg[3];
        p.nodePosition(n, xp);
        g.nodePosition(m, xg);
        EXPECT_EQ(xp[0], xg[0]);
        EXPECT_EQ(xp[1], xg[1]);
    }

    // The domain from the part
    const gridGeometry d = p.domain();
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_EQ(d.nCells[k], g.nCells[k]);
        EXPECT_EQ(d.offset[k], 0);
        EXPECT_EQ(d.upper(k), g.upper(k));
    }
    EXPECT_EQ(p.domainUpper(0), g.upper(0));
    EXPECT_EQ(p.lower(0), g.nodeCoord(0, 24));
}
