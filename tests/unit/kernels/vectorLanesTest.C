/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    dampmFoam's kernels sum a node's or a column's values as vectors of
    lanes (vectorLanes.H); each lane must do the scalar code's operations in
    its order, so that results stay the same to the bit. Against scalar
    references on random columns (positions, masses, velocities, gradients,
    stresses, basal coefficients) and random node fields, for the three
    shape functions, compared bit for bit:
    - the momentum scatter (S3) against particlesToGridMomentum;
    - the force scatter (S7) against its scalar form, in the same scatter
      order, for the gradient and divergence forms, with and without
      stress and basal coefficients;
    - the node values that pad the lanes stay +0;
    - the surface gather (S5, the node levels interleaved) against its
      scalar form, with and without terrain, for one column (gatherColumn)
      and over every column four at a time (gatherSurface);
    - the velocity gather of G2P against the generic (any Dim) sum;
    - four particles' stencils at once (stencilLanes) against the scalar
      stencil: weights, gradients, offsets and nodes, for the three shape
      functions (GIMP at half-widths 1/2, 1/4 and 1/6), at random positions
      and at the places where a kernel changes piece;
    - the force scatter with the surface gather in the same pass (the
      frictionless case's S5 + S7) against S5 column by column then the
      scalar scatter: the columns' gathered values and the node sums;
    - S9 in one pass (gridToColumns, the node velocities as pairs)
      against G2P (two arrays) then the advance of each column one by
      one: positions, velocities, gradients, footprints and the removal
      and split marks;
    - the nodes' levels (S4) and velocity pairs (S8) that the gathers read
      are the node arrays' values, on every node of the box, with mass
      and without;
    - fusedMulAdd rounds once, lane by lane: std::fma's bits for a double,
      two lanes and four, where the product and the sum rounded apart
      differ;
    - the scatters with node sums kept from a whole scatter before
      (keptSums: the columns whose nodes all keep left out, the others
      added to the nodes that do not keep only): every node's sums those
      of the whole scatter, and some columns left out, only of those
      whose nodes all keep.
    Random columns fill each tile with any number of columns, so that the
    scatters four at a time also end tiles with one to three columns taken
    one by one; their number is not a multiple of four, so that the passes
    over every column end so too.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "sameBits.H"
#include "depthAveragedKernels.H"
#include "particleTransfers.H"
#include "shapeKernels.H"
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace Foam;

namespace
{

//- Random columns sorted by cell on a 2D grid, with every per-column array
//  the kernels read or write, and random node fields
struct laneCase
{
    gridGeometry g;
    scatterSchedule schedule;
    particleArrays p;
    label gradU;
    nodeBox nodes;
    std::vector<double> h, a, kappa, Zb, gzx, gzy, gZx, gZy;
    std::vector<double> sigma[3];
    std::vector<double> s, k1, k2;
    //- The nodes' height, surface and bed elevation
    std::vector<double> hN, zetaN, ZN;
    shallowGrid grid;

    laneCase()
    :
        g(uniformGrid(2, {10, -5, 0}, {0.4, 0.5, 1}, {24, 20, 1})),
        schedule(g),
        gradU(p.addField("gradU", particleArrays::fieldKind::tensor))
    {
        std::mt19937 gen(17);
        std::uniform_real_distribution<double> u(0, 1), v(-1, 1);
        // Not a multiple of four: the passes over every column end with
        // one to three columns taken one by one
        const label n = 4*g.nCellsTotal() + 3;
        p.append(n);
        for (label i = 0; i < n; ++i)
        {
            for (int d = 0; d < 2; ++d)
            {
                p.component(particleArrays::X + d)[i] =
                    g.origin[d] + u(gen)*(g.upper(d) - g.origin[d]);
                p.component(particleArrays::UX + d)[i] = v(gen);
            }
            p.component(particleArrays::M)[i] = 0.5 + u(gen);
            p.component(particleArrays::VOL)[i] = 0.1 + u(gen);
            for (int k = 0; k < 4; ++k)
            {
                p.component(gradU + k)[i] = v(gen);
            }
        }
        p.sortByCell(g, schedule);
        nodes = p.stencilNodes(g);

        for (std::vector<double>* f : {&h, &a, &kappa, &Zb, &gzx, &gzy, &gZx,
            &gZy, &sigma[0], &sigma[1], &sigma[2], &s, &k1, &k2})
        {
            f->resize(n);
            for (double& x : *f)
            {
                x = v(gen);
            }
        }
        for (label i = 0; i < n; ++i)
        {
            h[i] = 0.1 + u(gen);
            kappa[i] = 0.5 + 0.5*u(gen);
        }

        grid.resize(g.nNodes());
        hN.resize(g.nNodes());
        zetaN.resize(g.nNodes());
        ZN.resize(g.nNodes());
        for (label j = 0; j < g.nNodes(); ++j)
        {
            hN[j] = u(gen);
            zetaN[j] = 2 + v(gen);
            ZN[j] = v(gen);
            grid.h[j] = hN[j];
            grid.Z[j] = ZN[j];
            double* const levels =
                grid.levels.data() + shallowGrid::nLevels*j;
            levels[shallowGrid::HEIGHT] = hN[j];
            levels[shallowGrid::ZETA] = zetaN[j];
            levels[shallowGrid::ELEVATION] = ZN[j];
            grid.vx[j] = v(gen);
            grid.vy[j] = v(gen);
        }
    }

    shallowColumns columns()
    {
        shallowColumns c;
        c.n = p.size();
        c.x = p.component(particleArrays::X);
        c.y = p.component(particleArrays::Y);
        c.ux = p.component(particleArrays::UX);
        c.uy = p.component(particleArrays::UY);
        c.m = p.component(particleArrays::M);
        c.V = p.component(particleArrays::VOL);
        for (int k = 0; k < 4; ++k)
        {
            c.C[k] = p.component(gradU + k);
        }
        for (int k = 0; k < 3; ++k)
        {
            c.sigma[k] = sigma[k].data();
        }
        c.h = h.data();
        c.a = a.data();
        c.kappa = kappa.data();
        c.Zb = Zb.data();
        c.gradZetaX = gzx.data();
        c.gradZetaY = gzy.data();
        c.gradZx = gZx.data();
        c.gradZy = gZy.data();
        c.s = s.data();
        c.k1 = k1.data();
        c.k2 = k2.data();
        return c;
    }

    columnScatter scatter() const
    {
        return columnScatter{g, nodes, schedule, p.binStart().data()};
    }
};


template<class Kernel>
void checkMomentum(const Kernel& kernel)
{
    laneCase t;
    const columnScatter sc = t.scatter();
    zeroNodes(t.g, t.nodes, t.grid);
    scatterMomentum(sc, kernel, t.grid, t.columns());

    const label nN = t.g.nNodes();
    std::vector<double> mass(nN), momX(nN), momY(nN);
    double* const mom[2] = {momX.data(), momY.data()};
    particlesToGridMomentum<2>
    (
        t.g, t.schedule, kernel, t.nodes, t.p.binStart().data(),
        affineArraysOf<2>(t.p, t.gradU), mass.data(), mom
    );

    typedef shallowGrid G;
    for (label j = 0; j < nN; ++j)
    {
        const double* q = t.grid.momentum.data() + G::nMomentum*j;
        ASSERT_TRUE(sameBits(q[G::M], mass[j])) << "node " << j;
        ASSERT_TRUE(sameBits(q[G::PX], momX[j])) << "node " << j;
        ASSERT_TRUE(sameBits(q[G::PY], momY[j])) << "node " << j;
        ASSERT_TRUE(sameBits(q[G::momentumPad], 0.0)) << "node " << j;
    }
}


//- The scalar form of the force scatter, column by column in the scatter's
//  order: the node forces F and basal sums B; before(i, st) runs first for
//  each column (the fused pass's S5)
template
<
    class Kernel, bool GradientForm, bool Stress, bool Basal, class Before
>
void scalarLoads
(
    const columnScatter& sc,
    const Kernel& kernel,
    const shallowColumns& cols,
    const double rho,
    const double gravity,
    Before&& before,
    std::vector<double> F[2],
    std::vector<double> B[3]
)
{
    const label nN = sc.g.nNodes();
    for (int k = 0; k < 2; ++k)
    {
        F[k].assign(nN, 0.0);
    }
    for (int k = 0; k < 3; ++k)
    {
        B[k].assign(nN, 0.0);
    }
    sc.schedule.scatter
    (
        sc.g,
        sc.nodes,
        sc.binStart,
        [&](const int32_t i)
        {
            const stencil<2, Kernel> st(sc.g, kernel, cols.x[i], cols.y[i], 0);
            before(i, st);
            const columnLoads c =
                loadsOf<GradientForm, Stress>(cols, i, rho, gravity);
            st.forEachNode
            (
                [&]
                (
                    const int32_t j,
                    const double N,
                    const double* gN,
                    const double*
                )
                {
                    double Fx = N*c.bx + c.pre*gN[0];
                    double Fy = N*c.by + c.pre*gN[1];
                    if (Stress)
                    {
                        Fx -= c.sxx*gN[0] + c.sxy*gN[1];
                        Fy -= c.sxy*gN[0] + c.syy*gN[1];
                    }
                    F[0][j] += Fx;
                    F[1][j] += Fy;
                    if (Basal)
                    {
                        B[0][j] += N*cols.s[i];
                        B[1][j] += N*cols.k1[i];
                        B[2][j] += N*cols.k2[i];
                    }
                }
            );
        }
    );
}


template<class Kernel, bool GradientForm, bool Stress, bool Basal>
void checkForces(const Kernel& kernel)
{
    laneCase t;
    const columnScatter sc = t.scatter();
    const shallowColumns cols = t.columns();
    const double rho = 1800, gravity = 9.81;
    zeroNodes(t.g, t.nodes, t.grid);
    scatterForces<Kernel, GradientForm, Stress, Basal>
    (
        sc, kernel, t.grid, cols, rho, gravity
    );

    // The scalar sums, column by column in the same scatter order
    const label nN = t.g.nNodes();
    std::vector<double> F[2], B[3];
    scalarLoads<Kernel, GradientForm, Stress, Basal>
    (
        sc, kernel, cols, rho, gravity,
        [](const int32_t, const stencil<2, Kernel>&) {},
        F, B
    );

    typedef shallowGrid L;
    for (label j = 0; j < nN; ++j)
    {
        const double* l = t.grid.loads.data() + L::nLoads*j;
        ASSERT_TRUE(sameBits(l[L::FX], F[0][j])) << "node " << j;
        ASSERT_TRUE(sameBits(l[L::FY], F[1][j])) << "node " << j;
        ASSERT_TRUE(sameBits(l[L::S], B[0][j])) << "node " << j;
        ASSERT_TRUE(sameBits(l[L::K1], B[1][j])) << "node " << j;
        ASSERT_TRUE(sameBits(l[L::K2], B[2][j])) << "node " << j;
        for (const int pad : {2, 3, 7})
        {
            ASSERT_TRUE(sameBits(l[pad], 0.0)) << "node " << j;
        }
    }
}


template<class Kernel, bool Terrain>
void checkSurfaceGather(const Kernel& kernel)
{
    laneCase t;
    const shallowColumns cols = t.columns();
    const double hMin = 0.05;
    for (label i = 0; i < cols.n; ++i)
    {
        const stencil<2, Kernel> st(t.g, kernel, cols.x[i], cols.y[i], 0);
        gatherColumn<Kernel, Terrain>(st, t.grid, cols, i, hMin, true);

        double h = 0, Zb = 0, gzx = 0, gzy = 0, gZx = 0, gZy = 0;
        st.forEachNode
        (
            [&]
            (
                const int32_t j,
                const double N,
                const double* gN,
                const double*
            )
            {
                h += N*t.hN[j];
                gzx += t.zetaN[j]*gN[0];
                gzy += t.zetaN[j]*gN[1];
                if (Terrain)
                {
                    Zb += N*t.ZN[j];
                    gZx += t.ZN[j]*gN[0];
                    gZy += t.ZN[j]*gN[1];
                }
            }
        );
        ASSERT_TRUE(sameBits(cols.h[i], h)) << "column " << i;
        ASSERT_TRUE(sameBits(cols.a[i], cols.V[i]/(h > hMin ? h : hMin)));
        ASSERT_TRUE(sameBits(cols.gradZetaX[i], gzx)) << "column " << i;
        ASSERT_TRUE(sameBits(cols.gradZetaY[i], gzy)) << "column " << i;
        if (Terrain)
        {
            ASSERT_TRUE(sameBits(cols.Zb[i], Zb)) << "column " << i;
            ASSERT_TRUE(sameBits(cols.gradZx[i], gZx)) << "column " << i;
            ASSERT_TRUE(sameBits(cols.gradZy[i], gZy)) << "column " << i;
            ASSERT_TRUE
            (
                sameBits(cols.kappa[i], 1/(1 + gZx*gZx + gZy*gZy))
            ) << "column " << i;
        }
    }
}


//- Every value S5 gives column i the same in both, bit for bit
void expectSameSurfaceOf
(
    const shallowColumns& cols,
    const shallowColumns& ref,
    const label i
)
{
    for
    (
        const auto& f :
        {
            std::make_pair(cols.h, ref.h), {cols.a, ref.a},
            {cols.kappa, ref.kappa}, {cols.Zb, ref.Zb},
            {cols.gradZetaX, ref.gradZetaX},
            {cols.gradZetaY, ref.gradZetaY},
            {cols.gradZx, ref.gradZx}, {cols.gradZy, ref.gradZy}
        }
    )
    {
        ASSERT_TRUE(sameBits(f.first[i], f.second[i]))
            << "column " << i << ": " << f.first[i] << " against "
            << f.second[i];
    }
}


//- Every value S5 gives the columns the same in both, bit for bit
void expectSameSurface(const shallowColumns& cols, const shallowColumns& ref)
{
    for (label i = 0; i < cols.n; ++i)
    {
        expectSameSurfaceOf(cols, ref, i);
    }
}


//- gatherSurface (four columns at a time, the last three one by one)
//  against gatherColumn column by column, each on its own copy of the same
//  random columns
template<class Kernel, bool Terrain>
void checkSurfaceGatherOfAll(const Kernel& kernel)
{
    const double hMin = 0.05;
    laneCase t, r;
    const shallowColumns cols = t.columns(), ref = r.columns();
    gatherSurface<Kernel, Terrain>(t.g, kernel, t.grid, cols, hMin, true);
    for (label i = 0; i < ref.n; ++i)
    {
        const stencil<2, Kernel> st(r.g, kernel, ref.x[i], ref.y[i], 0);
        gatherColumn<Kernel, Terrain>(st, r.grid, ref, i, hMin, true);
    }
    expectSameSurface(cols, ref);
}


template<class Kernel>
void checkVelocityGather(const Kernel& kernel)
{
    laneCase t;
    const double* const nodeVel[2] = {t.grid.vx.data(), t.grid.vy.data()};
    const affineArrays<2> cols = affineArraysOf<2>(t.p, t.gradU);
    gridToParticlesVelocity<2>(t.g, kernel, cols, nodeVel);
    for (label i = 0; i < cols.n; ++i)
    {
        const stencil<2, Kernel> st
        (
            t.g, kernel, cols.x[0][i], cols.x[1][i], cols.x[2][i]
        );
        double v[2] = {0, 0};
        double L[2][2] = {{0, 0}, {0, 0}};
        gatherNodeVelocity<2, Kernel>(st, nodeVel, v, L);
        for (int a = 0; a < 2; ++a)
        {
            ASSERT_TRUE(sameBits(cols.u[a][i], v[a])) << "column " << i;
            for (int b = 0; b < 2; ++b)
            {
                ASSERT_TRUE(sameBits(cols.C[2*a + b][i], L[a][b]))
                    << "column " << i;
            }
        }
    }
}


//- Four particles' stencils against four scalar stencils, bit for bit
template<class Kernel>
void checkStencilLanes
(
    const gridGeometry& g,
    const Kernel& kernel,
    const double x[4],
    const double y[4]
)
{
    const stencilLanes<Kernel> lanes(g, kernel, x, y);
    constexpr int W = Kernel::width;
    for (int l = 0; l < 4; ++l)
    {
        const stencil<2, Kernel> st(g, kernel, x[l], y[l], 0);
        ASSERT_EQ(lanes.base[l], st.base) << "lane " << l;
        for (int d = 0; d < 2; ++d)
        {
            ASSERT_TRUE(sameBits(lanes.r0[d][l], st.r0[d])) << "lane " << l;
            for (int a = 0; a < W; ++a)
            {
                ASSERT_TRUE(sameBits(lanes.w[d][a][l], st.w[d][a]))
                    << "lane " << l << " x " << x[l] << " y " << y[l];
                ASSERT_TRUE(sameBits(lanes.dw[d][a][l], st.dw[d][a]))
                    << "lane " << l << " x " << x[l] << " y " << y[l];
            }
        }
    }

    // The node loops: the same nodes, weights, gradients and offsets
    std::vector<int32_t> nodes[4];
    std::vector<double> values[4];
    lanes.forEachNode
    (
        [&]
        (
            const int,
            const int32_t offset,
            const lanes4 N,
            const lanes4* gN,
            const lanes4* r
        )
        {
            int32_t j[4];
            lanes.nodesAt(offset, j);
            for (int l = 0; l < 4; ++l)
            {
                nodes[l].push_back(j[l]);
                for (const double v : {N[l], gN[0][l], gN[1][l]})
                {
                    values[l].push_back(v);
                }
                values[l].push_back(r[0][l]);
                values[l].push_back(r[1][l]);
            }
        }
    );
    for (int l = 0; l < 4; ++l)
    {
        const stencil<2, Kernel> st(g, kernel, x[l], y[l], 0);
        std::size_t k = 0, v = 0;
        st.forEachNode
        (
            [&]
            (
                const int32_t j,
                const double N,
                const double* gN,
                const double* r
            )
            {
                ASSERT_EQ(nodes[l][k++], j);
                for (const double e : {N, gN[0], gN[1], r[0], r[1]})
                {
                    ASSERT_TRUE(sameBits(values[l][v++], e)) << "lane " << l;
                }
            }
        );
    }
}


//- stencilLanes at random positions and where a kernel changes piece:
//  cell faces, cell centres and, for GIMP, lp either side of a face
template<class Kernel>
void checkStencilLanes(const Kernel& kernel, const double lp)
{
    const gridGeometry g
    (
        uniformGrid(2, {10, -5, 0}, {0.4, 0.5, 1}, {24, 20, 1})
    );
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> special;
    for (const double f : {0.0, 0.5, lp, 1 - lp, 0.5 - lp, 0.5 + lp})
    {
        for (const double c : {0.0, 3.0, 23.0})
        {
            special.push_back(c + f);
        }
    }
    const int nSpecial = int(special.size());
    for (int trial = 0; trial < 2000; ++trial)
    {
        double x[4], y[4];
        for (int l = 0; l < 4; ++l)
        {
            const double sx = trial < nSpecial*nSpecial
              ? special[(trial + l) % nSpecial] : 24*u(gen);
            const double sy = trial < nSpecial*nSpecial
              ? special[(trial/nSpecial + l) % nSpecial] : 20*u(gen);
            x[l] = g.origin[0] + std::min(sx, 23.999)*g.dx[0];
            y[l] = g.origin[1] + std::min(sy, 19.999)*g.dx[1];
        }
        checkStencilLanes(g, kernel, x, y);
        if (::testing::Test::HasFatalFailure())
        {
            return;
        }
    }
}


//- 3D: four particles' stencils and rows of nodes against four scalar
//  stencils, bit for bit, at random positions and on cell faces and
//  centres (lp either side of them) of a grid of unequal cell sizes
template<class Kernel>
void checkStencilLanes3D(const Kernel& kernel, const double lp)
{
    const gridGeometry g
    (
        uniformGrid(3, {10, -5, 2}, {0.4, 0.5, 0.3}, {12, 10, 9})
    );
    constexpr int W = Kernel::width;
    std::mt19937 gen(9);
    std::uniform_real_distribution<double> u(0, 1);
    const double special[] = {0, 0.5, lp, 1 - lp, 0.5 - lp, 0.5 + lp, 3, 8};
    for (int trial = 0; trial < 1000; ++trial)
    {
        double x[3][4];
        for (int d = 0; d < 3; ++d)
        {
            for (int l = 0; l < 4; ++l)
            {
                const double s = trial < 64
                  ? special[(trial + 3*l + d) % 8] + (trial/8) % 3
                  : g.nCells[d]*u(gen);
                x[d][l] =
                    g.origin[d] + std::min(s, g.nCells[d] - 0.001)*g.dx[d];
            }
        }
        const stencilLanes<Kernel, 3> lanes(g, kernel, x[0], x[1], x[2]);
        std::vector<double> rows[4];
        std::vector<int32_t> firsts[4];
        lanes.forEachRow
        (
            [&]
            (
                const laneIndex4 first, const int, const int,
                const lanes4 wbc, const lanes4 dwb, const lanes4 dwc
            )
            {
                for (int l = 0; l < 4; ++l)
                {
                    firsts[l].push_back(first[l]);
                    rows[l].insert(rows[l].end(), {wbc[l], dwb[l], dwc[l]});
                }
            }
        );
        for (int l = 0; l < 4; ++l)
        {
            ASSERT_EQ(firsts[l].size(), std::size_t(W*W));
            const stencil<3, Kernel> st
            (
                g, kernel, x[0][l], x[1][l], x[2][l]
            );
            ASSERT_EQ(lanes.base[l], st.base) << "lane " << l;
            for (int d = 0; d < 3; ++d)
            {
                ASSERT_TRUE(sameBits(lanes.r0[d][l], st.r0[d])) << l;
                for (int a = 0; a < W; ++a)
                {
                    ASSERT_TRUE(sameBits(lanes.w[d][a][l], st.w[d][a]))
                        << "lane " << l << " axis " << d;
                    ASSERT_TRUE(sameBits(lanes.dw[d][a][l], st.dw[d][a]))
                        << "lane " << l << " axis " << d;
                }
            }
            std::size_t k = 0;
            st.forEachRow
            (
                [&]
                (
                    const int32_t first, const int, const int,
                    const double wbc, const double dwb, const double dwc
                )
                {
                    ASSERT_LT(k, rows[l].size());
                    ASSERT_EQ(firsts[l][k/3], first);
                    for (const double e : {wbc, dwb, dwc})
                    {
                        ASSERT_TRUE(sameBits(rows[l][k++], e)) << l;
                    }
                }
            );
            ASSERT_EQ(k, rows[l].size());
        }
        if (::testing::Test::HasFatalFailure())
        {
            return;
        }
    }
}


//- The force scatter with S5 in the same pass, against S5 column by
//  column (gatherColumn) then the scalar scatter; each on its own copy of
//  the same random columns
template<class Kernel, bool Terrain>
void checkFusedGather(const Kernel& kernel)
{
    const double rho = 1800, gravity = 9.81, hMin = 0.3;
    laneCase t, r;
    const shallowColumns cols = t.columns(), ref = r.columns();

    // The forces zeroed, the node heights kept (zeroNodes clears both)
    std::fill(t.grid.loads.begin(), t.grid.loads.end(), 0.0);
    scatterForces<Kernel, true, false, false, true, Terrain>
    (
        t.scatter(), kernel, t.grid, cols, rho, gravity, hMin, true
    );

    const label nN = r.g.nNodes();
    std::vector<double> F[2], B[3];
    scalarLoads<Kernel, true, false, false>
    (
        r.scatter(), kernel, ref, rho, gravity,
        [&](const int32_t i, const stencil<2, Kernel>& st)
        {
            gatherColumn<Kernel, Terrain>(st, r.grid, ref, i, hMin, true);
        },
        F, B
    );

    expectSameSurface(cols, ref);
    if (::testing::Test::HasFatalFailure())
    {
        return;
    }
    typedef shallowGrid L;
    for (label j = 0; j < nN; ++j)
    {
        const double* l = t.grid.loads.data() + L::nLoads*j;
        ASSERT_TRUE(sameBits(l[L::FX], F[0][j])) << "node " << j;
        ASSERT_TRUE(sameBits(l[L::FY], F[1][j])) << "node " << j;
    }
}


//- The arrays S9 moves, on a laneCase's columns, with random footprints
struct motionArrays
{
    std::vector<double> F[4];
    std::vector<char> removal, split;

    explicit motionArrays(laneCase& t)
    {
        std::mt19937 gen(3);
        std::uniform_real_distribution<double> u(0.5, 1.5), v(-0.3, 0.3);
        const label n = t.p.size();
        for (int k = 0; k < 4; ++k)
        {
            F[k].resize(n);
            for (double& f : F[k])
            {
                f = (k == 0 || k == 3 ? u(gen) : v(gen))*t.g.dx[0];
            }
        }
        removal.assign(n, 7);
        split.assign(n, 7);
    }

    columnMotion of(laneCase& t)
    {
        columnMotion m;
        m.n = t.p.size();
        m.x = t.p.component(particleArrays::X);
        m.y = t.p.component(particleArrays::Y);
        m.ux = t.p.component(particleArrays::UX);
        m.uy = t.p.component(particleArrays::UY);
        for (int k = 0; k < 4; ++k)
        {
            m.C[k] = t.p.component(t.gradU + k);
            m.F[k] = F[k].data();
        }
        m.V = t.p.component(particleArrays::VOL);
        m.removal = removal.data();
        m.splitCandidate = split.data();
        return m;
    }
};


//- gridToColumns (the node velocities as pairs) against
//  gridToParticlesVelocity (as two arrays) then columnAdvance one
//  column at a time, with a large step (columns leave through the open
//  side and through the walls) and splitting on
template<class Kernel>
void checkGridToColumns(const Kernel& kernel)
{
    laneCase t, r;
    motionArrays mt(t), mr(r);
    domainSides sides;
    sides.wall[0][0] = sides.wall[1][0] = sides.wall[1][1] = true;
    splitRule rule;
    rule.maxArea = 0.8*t.g.dx[0]*t.g.dx[1];
    rule.hSplit = 0.01;
    const double dt = 0.3;
    const double* const vel[2] = {t.grid.vx.data(), t.grid.vy.data()};
    // The same velocities as S8's pairs
    std::vector<double> pairs(2*t.g.nNodes());
    for (label n = 0; n < t.g.nNodes(); ++n)
    {
        pairs[2*n] = vel[0][n];
        pairs[2*n + 1] = vel[1][n];
    }

    const columnMotion qt = mt.of(t), qr = mr.of(r);
    const label nRemoved = gridToColumns
    (
        t.g, kernel, pairs.data(),
        columnAdvance(t.g, sides, dt, true, rule, qt)
    );

    gridToParticlesVelocity<2>
    (
        r.g, kernel, affineArraysOf<2>(r.p, r.gradU), vel
    );
    const columnAdvance advance(r.g, sides, dt, true, rule, qr);
    label nRef = 0;
    for (label i = 0; i < qr.n; ++i)
    {
        double C[4] = {qr.C[0][i], qr.C[1][i], qr.C[2][i], qr.C[3][i]};
        nRef += advance(i, qr.ux[i], qr.uy[i], C);
    }

    EXPECT_GT(nRef, 0);
    EXPECT_EQ(nRemoved, nRef);
    EXPECT_EQ(mt.removal, mr.removal);
    EXPECT_EQ(mt.split, mr.split);
    for (label i = 0; i < qt.n; ++i)
    {
        for
        (
            const auto& f :
            {
                std::make_pair(qt.x, qr.x), {qt.y, qr.y}, {qt.ux, qr.ux},
                {qt.uy, qr.uy}, {qt.C[0], qr.C[0]}, {qt.C[1], qr.C[1]},
                {qt.C[2], qr.C[2]}, {qt.C[3], qr.C[3]}, {qt.F[0], qr.F[0]},
                {qt.F[1], qr.F[1]}, {qt.F[2], qr.F[2]}, {qt.F[3], qr.F[3]}
            }
        )
        {
            ASSERT_TRUE(sameBits(f.first[i], f.second[i])) << "column " << i;
        }
    }
}


GIMPKernel gimp()
{
    return GIMPKernel(0.25);
}


//- Nodes that keep sums (keptSums) on a laneCase's grid: S3's sums in a
//  block, S7's in a smaller one, both at a node alone; and per cell, do
//  the nodes c - 1 .. c + 2 of its columns keep, any or all?
struct keptBlocks
{
    std::vector<uint8_t> nodes, cells;

    explicit keptBlocks(const gridGeometry& g)
    {
        typedef gridGeometry::index index;
        const index nx = g.nNodesDir[0], ny = g.nNodesDir[1];
        nodes.assign(g.nNodes(), 0);
        for (index j = 0; j < ny; ++j)
        {
            for (index i = 0; i < nx; ++i)
            {
                uint8_t& k = nodes[i + nx*j];
                if (i >= 6 && i < 19 && j >= 4 && j < 15)
                {
                    k |= keptSums::momentumKept;
                }
                if (i >= 9 && i < 16 && j >= 6 && j < 12)
                {
                    k |= keptSums::loadsKept;
                }
            }
        }
        nodes[3 + nx*17] = keptSums::momentumKept | keptSums::loadsKept;

        const index nCx = g.nCells[0], nCy = g.nCells[1];
        const index nG = gridGeometry::nGhost;
        cells.assign(nCx*nCy, 0);
        for (index cj = 0; cj < nCy; ++cj)
        {
            for (index ci = 0; ci < nCx; ++ci)
            {
                uint8_t any = 0, all = 0xff;
                for (index b = -1; b <= 2; ++b)
                {
                    for (index a = -1; a <= 2; ++a)
                    {
                        const uint8_t k =
                            nodes[ci + nG + a + nx*(cj + nG + b)];
                        any |= k;
                        all &= k;
                    }
                }
                const uint8_t m = keptSums::momentumKept;
                const uint8_t l = keptSums::loadsKept;
                cells[ci + nCx*cj] = uint8_t
                (
                    ((any & m) ? keptSums::momentumTouch : 0)
                  | ((all & m) ? keptSums::momentumAll : 0)
                  | ((any & l) ? keptSums::loadsTouch : 0)
                  | ((all & l) ? keptSums::loadsAll : 0)
                );
            }
        }
    }

    keptSums sums() const
    {
        keptSums k;
        k.nodes = nodes.data();
        k.cells = cells.data();
        return k;
    }
};


//- Kept node sums (keptSums): the scatters of a step that keep some nodes'
//  sums from the step before, leave out the columns whose nodes all keep
//  and add nothing to a node that keeps, give every node the whole
//  scatter's sums, bit for bit
template<class Kernel>
void checkKeptSums(const Kernel& kernel)
{
    typedef gridGeometry::index index;
    laneCase t;
    const shallowColumns cols = t.columns();
    const double rho = 1800, gravity = 9.81;
    const auto scatterBoth = [&](const keptSums& kept, index nLeft[2])
    {
        columnScatter sc = t.scatter();
        sc.kept = kept.of(false);
        nLeft[0] = scatterMomentum(sc, kernel, t.grid, cols);
        sc.kept = kept.of(true);
        nLeft[1] = scatterForces<Kernel, true, true, true>
        (
            sc, kernel, t.grid, cols, rho, gravity
        );
    };

    // The whole scatters
    index nLeft[2];
    zeroNodes(t.g, t.nodes, t.grid);
    scatterBoth(keptSums(), nLeft);
    ASSERT_EQ(nLeft[0] + nLeft[1], 0);
    const std::vector<double> momentum
    (
        t.grid.momentum.begin(), t.grid.momentum.end()
    );
    const std::vector<double> loads(t.grid.loads.begin(), t.grid.loads.end());

    const keptBlocks blocks(t.g);
    const std::vector<uint8_t>& nodes = blocks.nodes;
    const std::vector<uint8_t>& cells = blocks.cells;
    const keptSums kept = blocks.sums();

    // The next step: the kept sums as the whole scatters left them, the
    // others not (zeroNodes clears them)
    typedef shallowGrid G;
    t.g.forEachNodeRow
    (
        t.nodes,
        [&](const index first, const index last)
        {
            for (index j = first; j < last; ++j)
            {
                for (int c = 0; c < G::nMomentum; ++c)
                {
                    t.grid.momentum[G::nMomentum*j + c] =
                        (nodes[j] & keptSums::momentumKept)
                      ? momentum[G::nMomentum*j + c] : 12345.0;
                }
                for (int c = 0; c < G::nLoads; ++c)
                {
                    t.grid.loads[G::nLoads*j + c] =
                        (nodes[j] & keptSums::loadsKept)
                      ? loads[G::nLoads*j + c] : -6789.0;
                }
            }
        }
    );
    zeroNodes(t.g, t.nodes, t.grid, kept);
    scatterBoth(kept, nLeft);

    for (label j = 0; j < t.g.nNodes(); ++j)
    {
        for (int c = 0; c < G::nMomentum; ++c)
        {
            ASSERT_TRUE
            (
                sameBits
                (
                    t.grid.momentum[G::nMomentum*j + c],
                    momentum[G::nMomentum*j + c]
                )
            ) << "node " << j << ", mass or momentum " << c;
        }
        for (int c = 0; c < G::nLoads; ++c)
        {
            ASSERT_TRUE
            (
                sameBits(t.grid.loads[G::nLoads*j + c], loads[G::nLoads*j + c])
            ) << "node " << j << ", load " << c;
        }
    }

    // Left out: columns in cells whose nodes all keep (four at a time, so
    // not those in a four with another column); and some columns added to
    // the nodes that do not keep only
    index expected[2] = {0, 0}, masked[2] = {0, 0};
    for (label i = 0; i < cols.n; ++i)
    {
        const uint8_t c = cells[t.g.cellOf(cols.x[i], cols.y[i], 0)];
        expected[0] += (c & keptSums::momentumAll) != 0;
        expected[1] += (c & keptSums::loadsAll) != 0;
        masked[0] +=
            (c & keptSums::momentumTouch) && !(c & keptSums::momentumAll);
        masked[1] += (c & keptSums::loadsTouch) && !(c & keptSums::loadsAll);
    }
    for (int k = 0; k < 2; ++k)
    {
        EXPECT_GT(nLeft[k], 0) << (k ? "S7" : "S3");
        EXPECT_LE(nLeft[k], expected[k]) << (k ? "S7" : "S3");
        EXPECT_GT(masked[k], 0) << (k ? "S7" : "S3");
    }
}


//- S5 with S7's view of kept sums (keptBlocks) against S5 of every column:
//  a column is left out, nothing written for it, exactly when it is in a
//  four (or among the last few, alone) all of whose columns S7 leaves
//  out; every other column has the whole gather's values, bit for bit
template<class Kernel, bool Terrain>
void checkSurfaceGatherLeavesOut(const Kernel& kernel)
{
    typedef gridGeometry::index index;
    const double hMin = 0.05;
    laneCase t, r;
    const keptBlocks blocks(t.g);
    const shallowColumns cols = t.columns(), ref = r.columns();
    gatherSurface<Kernel, Terrain>(r.g, kernel, r.grid, ref, hMin, true);

    // What each column held before: left out, it still holds it
    laneCase before;
    const shallowColumns held = before.columns();
    const index nLeft = gatherSurface<Kernel, Terrain>
    (
        t.g, kernel, t.grid, cols, hMin, true, blocks.sums().of(true)
    );

    const auto leftOut = [&](const index i)
    {
        return
            (blocks.cells[t.g.cellOf(cols.x[i], cols.y[i], 0)]
          & keptSums::loadsAll) != 0;
    };
    index expected = 0;
    for (index i = 0; i < cols.n; ++i)
    {
        const index first = i - i%4;
        bool out = leftOut(i);
        if (first + 4 <= cols.n)
        {
            for (index l = first; l < first + 4; ++l)
            {
                out = out && leftOut(l);
            }
        }
        expected += out;
        SCOPED_TRACE(out ? "left out" : "gathered");
        expectSameSurfaceOf(cols, out ? held : ref, i);
    }
    EXPECT_EQ(nLeft, expected);
    EXPECT_GT(nLeft, 16);
    EXPECT_LT(nLeft, cols.n/2);
}

} // End anonymous namespace


TEST(vectorLanes, ScattersKeepTheKeptSumsAndLeaveOutTheirColumns)
{
    checkKeptSums(linearKernel());
    checkKeptSums(gimp());
    checkKeptSums(quadraticBSplineKernel());
}


TEST(vectorLanes, SurfaceGatherLeavesOutTheColumnsTheForceScatterLeavesOut)
{
    checkSurfaceGatherLeavesOut<linearKernel, true>(linearKernel());
    checkSurfaceGatherLeavesOut<GIMPKernel, false>(gimp());
    checkSurfaceGatherLeavesOut<quadraticBSplineKernel, true>
    (
        quadraticBSplineKernel()
    );
}


TEST(vectorLanes, MomentumScatterIsTheScalarSumBitForBit)
{
    checkMomentum(linearKernel());
    checkMomentum(gimp());
    checkMomentum(quadraticBSplineKernel());
}


TEST(vectorLanes, ForceScatterIsTheScalarSumBitForBit)
{
    checkForces<linearKernel, true, false, false>(linearKernel());
    checkForces<GIMPKernel, true, true, true>(gimp());
    checkForces<quadraticBSplineKernel, true, true, true>
    (
        quadraticBSplineKernel()
    );
    checkForces<quadraticBSplineKernel, false, true, false>
    (
        quadraticBSplineKernel()
    );
    checkForces<quadraticBSplineKernel, false, false, true>
    (
        quadraticBSplineKernel()
    );
}


TEST(vectorLanes, ForceScatterTakesANullBasalCoefficientAsZeros)
{
    // Each coefficient that no model adds to, null, against the same one
    // zeroed: the node loads are the same bits (four columns at a time and
    // the last few one by one)
    const quadraticBSplineKernel kernel;
    for (const int absent : {0, 1, 2})
    {
        laneCase t;
        std::vector<double>* coefficients[3] = {&t.s, &t.k1, &t.k2};
        coefficients[absent]->assign(t.p.size(), 0.0);
        const auto loads = [&](const shallowColumns& cols)
        {
            zeroNodes(t.g, t.nodes, t.grid);
            scatterForces<quadraticBSplineKernel, true, true, true>
            (
                t.scatter(), kernel, t.grid, cols, 1800, 9.81
            );
            return t.grid.loads;
        };
        const auto zeroed = loads(t.columns());
        shallowColumns cols = t.columns();
        const double** pointers[3] = {&cols.s, &cols.k1, &cols.k2};
        *pointers[absent] = nullptr;
        const auto null = loads(cols);
        ASSERT_EQ(zeroed.size(), null.size());
        for (size_t j = 0; j < zeroed.size(); ++j)
        {
            ASSERT_TRUE(sameBits(zeroed[j], null[j]))
                << "coefficient " << absent << ", load " << j;
        }
    }
}


TEST(vectorLanes, SurfaceGatherIsTheScalarSumBitForBit)
{
    checkSurfaceGather<linearKernel, true>(linearKernel());
    checkSurfaceGather<GIMPKernel, false>(gimp());
    checkSurfaceGather<quadraticBSplineKernel, true>(quadraticBSplineKernel());
    checkSurfaceGather<quadraticBSplineKernel, false>(quadraticBSplineKernel());
    checkSurfaceGatherOfAll<linearKernel, true>(linearKernel());
    checkSurfaceGatherOfAll<GIMPKernel, false>(gimp());
    checkSurfaceGatherOfAll<quadraticBSplineKernel, true>
    (
        quadraticBSplineKernel()
    );
}


TEST(vectorLanes, VelocityGatherIsTheScalarSumBitForBit)
{
    checkVelocityGather(linearKernel());
    checkVelocityGather(gimp());
    checkVelocityGather(quadraticBSplineKernel());
}


TEST(vectorLanes, FourStencilsAtOnceAreTheScalarStencilsBitForBit)
{
    checkStencilLanes(linearKernel(), 0.25);
    checkStencilLanes(quadraticBSplineKernel(), 0.25);
    for (const double lp : {0.5, 0.25, 1.0/6})
    {
        checkStencilLanes(GIMPKernel(lp), lp);
    }
}


TEST(vectorLanes, FourStencilsAtOnceIn3DAreTheScalarStencilsBitForBit)
{
    checkStencilLanes3D(linearKernel(), 0.25);
    checkStencilLanes3D(quadraticBSplineKernel(), 0.25);
    checkStencilLanes3D(GIMPKernel(0.25), 0.25);
}


TEST(vectorLanes, ForceScatterWithTheSurfaceGatherIsTheScalarPassBitForBit)
{
    checkFusedGather<quadraticBSplineKernel, true>(quadraticBSplineKernel());
    checkFusedGather<quadraticBSplineKernel, false>(quadraticBSplineKernel());
    checkFusedGather<GIMPKernel, false>(gimp());
    checkFusedGather<linearKernel, true>(linearKernel());
}


TEST(vectorLanes, VelocityGatherAndAdvanceInOnePassAreTheTwoPassesBitForBit)
{
    checkGridToColumns(linearKernel());
    checkGridToColumns(gimp());
    checkGridToColumns(quadraticBSplineKernel());
}


// nodeHeights (S4) and resistanceUpdate (S8) on random node sums, some
// nodes without mass: the levels hold h, kappa h + Z and Z, and the pairs
// vx and vy, at every node of the box, bit for bit; the levels' pad lane
// stays +0. Twice, so that a node that loses its mass is rewritten too
TEST(vectorLanes, NodeLevelsAndVelocityPairsAreTheNodeArrays)
{
    laneCase t;
    typedef shallowGrid G;
    std::mt19937 gen(23);
    std::uniform_real_distribution<double> u(0, 1), v(-1, 1);
    const label nNodes = t.g.nNodes();
    std::vector<double> kappaNode(nNodes);
    for (label n = 0; n < nNodes; ++n)
    {
        t.grid.area[n] = 0.1 + u(gen);
        kappaNode[n] = 0.5 + 0.5*u(gen);
    }
    const double rho = 1800, massTol = 0.2, dt = 1e-2;
    for (int pass = 0; pass < 2; ++pass)
    {
        for (label n = 0; n < nNodes; ++n)
        {
            double* mp = t.grid.momentum.data() + G::nMomentum*n;
            mp[G::M] = u(gen);
            mp[G::PX] = v(gen);
            mp[G::PY] = v(gen);
            double* l = t.grid.loads.data() + G::nLoads*n;
            l[G::FX] = v(gen);
            l[G::FY] = v(gen);
            l[G::S] = 10*u(gen);
            l[G::K1] = u(gen);
            l[G::K2] = u(gen);
        }
        nodeHeights(t.g, t.nodes, t.grid, rho, massTol, true, kappaNode.data());
        resistanceUpdate(t.g, t.nodes, t.grid, domainSides(), dt, massTol, true);

        label inBox = 0, withMass = 0;
        t.g.forEachNodeRow
        (
            t.nodes,
            [&](const label first, const label last)
            {
                for (label n = first; n < last; ++n)
                {
                    const double* lv = t.grid.levels.data() + G::nLevels*n;
                    const double* vel = t.grid.velocity.data() + G::nVelocity*n;
                    const double h = t.grid.h[n];
                    ++inBox;
                    withMass += h > 0;
                    ASSERT_TRUE(sameBits(lv[G::HEIGHT], h)) << n;
                    ASSERT_TRUE
                    (
                        sameBits(lv[G::ZETA], kappaNode[n]*h + t.grid.Z[n])
                    ) << n;
                    ASSERT_TRUE(sameBits(lv[G::ELEVATION], t.grid.Z[n])) << n;
                    ASSERT_TRUE(sameBits(lv[G::levelPad], 0.0)) << n;
                    ASSERT_TRUE(sameBits(vel[G::VX], t.grid.vx[n])) << n;
                    ASSERT_TRUE(sameBits(vel[G::VY], t.grid.vy[n])) << n;
                }
            }
        );
        EXPECT_GT(withMass, inBox/2);
        EXPECT_LT(withMass, inBox);
    }
}


// fusedMulAdd is one rounding of a b + c in every lane: std::fma's bits.
// a b = 1 - 2^-60 rounds to 1 on its own, so the product and the sum
// rounded apart give 0 where the fused operation gives -2^-60; random
// operands, any lane, and the signed zeros, give std::fma's bits too
TEST(vectorLanes, FusedMulAddRoundsOnceInEveryLane)
{
    const double a = 1 + std::ldexp(1.0, -30), b = 1 - std::ldexp(1.0, -30);
    ASSERT_EQ(a*b - 1, 0.0);
    EXPECT_EQ(fusedMulAdd(a, b, -1.0), -std::ldexp(1.0, -60));

    std::mt19937 gen(37);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 1000; ++trial)
    {
        double x[3][4];
        for (auto& v : x)
        {
            for (double& xl : v)
            {
                xl = u(gen);
            }
        }
        // One lane holds the case above, another signed zeros
        const int l = trial % 4;
        x[0][l] = a;
        x[1][l] = b;
        x[2][l] = -1;
        x[0][(l + 1) % 4] = -0.0;
        x[2][(l + 1) % 4] = trial % 2 ? -0.0 : 0.0;

        const lanes4 r4 = fusedMulAdd
        (
            loadLanes(x[0]), loadLanes(x[1]), loadLanes(x[2])
        );
        const lanes4 s4 =
            fusedMulAdd(x[0][0], loadLanes(x[1]), loadLanes(x[2]));
        const lanes2 r2 = fusedMulAdd
        (
            loadPair(x[0]), loadPair(x[1]), loadPair(x[2])
        );
        for (int k = 0; k < 4; ++k)
        {
            const double ref = std::fma(x[0][k], x[1][k], x[2][k]);
            ASSERT_TRUE(sameBits(r4[k], ref)) << trial << " lane " << k;
            ASSERT_TRUE
            (
                sameBits(fusedMulAdd(x[0][k], x[1][k], x[2][k]), ref)
            ) << trial << " lane " << k;
            ASSERT_TRUE
            (
                sameBits(s4[k], std::fma(x[0][0], x[1][k], x[2][k]))
            ) << trial << " lane " << k;
            if (k < 2)
            {
                ASSERT_TRUE(sameBits(r2[k], ref)) << trial << " lane " << k;
            }
        }
        EXPECT_EQ(r4[l], -std::ldexp(1.0, -60));
    }
}


// ************************************************************************* //
