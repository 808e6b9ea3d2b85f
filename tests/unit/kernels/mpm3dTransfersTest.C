/*---------------------------------------------------------------------------*\
  dampm | Material Point Method for landslide run-out and barrier impact
-------------------------------------------------------------------------------
    Copyright (C) 2026 dampm authors
-------------------------------------------------------------------------------
License
    This file is part of dampm, distributed under GPL-3.0-or-later.

Description
    mpm3dTransfers and mpm3dSmoothing, stage by stage against closed forms:
    the affine momentum at every node of a stencil, P2G's conservation of
    mass and momentum, the internal force of a uniform stress (zero at the
    interior nodes, its first moment the total -V sigma), G2P of a linear
    velocity field, the volume change of a body at rest, and J held at
    the material's maxJ.

\*---------------------------------------------------------------------------*/

#include "uniformGrid.H"
#include "sameBits.H"
#include "mpm3dKernels.H"
#include "shapeKernels.H"
#include <gtest/gtest.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <omp.h>

using namespace Foam;

namespace
{

typedef gridGeometry::index gridIndex;
typedef quadraticBSplineKernel kernel3;

// 10 x 8 x 9 cells of unequal sizes (an axis mixed up shows)
gridGeometry box()
{
    return uniformGrid(3, {-0.3, 0.2, 0}, {0.1, 0.12, 0.09}, {10, 8, 9});
}

// The cells [lo, hi) per axis that hold particles
constexpr gridIndex filledLo[3] = {2, 1, 2};
constexpr gridIndex filledHi[3] = {8, 7, 7};

// Particle columns stored cell by cell in the scatter schedule's order (so
// binStart bins them), n^3 per filled cell (filledLo .. filledHi unless
// given): a regular lattice, or jittered within the lattice cells
struct testParticles
{
    // At skewed page offsets, as the solver's columns (skewedAllocator)
    typedef std::vector<double, skewedAllocator<double>> column;
    column x[3], u[3], m, V, C[9], sigma[6], J, div, vGrid[3];
    std::vector<gridIndex> binStart;

    testParticles
    (
        const gridGeometry& g,
        const int n,
        std::mt19937* gen,
        const gridIndex (&lo)[3] = filledLo,
        const gridIndex (&hi)[3] = filledHi
    )
    {
        std::uniform_real_distribution<double> jitter(-0.4, 0.4);
        const tileCellOrder o = scatterSchedule(g).cellOrder();
        const gridIndex T = o.T;
        binStart.push_back(0);
        for (gridIndex r = 0; r < o.nRanks(); ++r)
        {
            // The cell of rank r: tile t, cell l within it
            const gridIndex t = r/o.perTile, l = r % o.perTile;
            const gridIndex c[3] =
            {
                (t % o.nTiles[0])*T + l % T,
                ((t/o.nTiles[0]) % o.nTiles[1])*T + (l/T) % T,
                (t/(o.nTiles[0]*o.nTiles[1]))*T + l/(T*T)
            };
            bool filled = true;
            for (int d = 0; d < 3; ++d)
            {
                filled = filled
                    && c[d] >= lo[d] && c[d] < hi[d] && c[d] < g.nCells[d];
            }
            for (int p = 0; filled && p < n*n*n; ++p)
            {
                const int l[3] = {p % n, (p/n) % n, p/(n*n)};
                for (int d = 0; d < 3; ++d)
                {
                    const double s =
                        (l[d] + 0.5 + (gen ? jitter(*gen) : 0))/n;
                    x[d].push_back(g.origin[d] + (c[d] + s)*g.dx[d]);
                }
                m.push_back(gen ? 1 + jitter(*gen) : 1);
                V.push_back(g.dx[0]*g.dx[1]*g.dx[2]/(n*n*n));
            }
            binStart.push_back(gridIndex(m.size()));
        }
        const size_t np = m.size();
        for (column* a :
            {&u[0], &u[1], &u[2], &J, &div, &vGrid[0], &vGrid[1], &vGrid[2]})
        {
            a->assign(np, 0.0);
        }
        for (int c = 0; c < 9; ++c)
        {
            C[c].assign(np, 0.0);
        }
        for (int c = 0; c < 6; ++c)
        {
            sigma[c].assign(np, 0.0);
        }
    }

    mpm3dParticles view()
    {
        mpm3dParticles p;
        p.n = gridIndex(m.size());
        for (int d = 0; d < 3; ++d)
        {
            p.x[d] = x[d].data();
            p.u[d] = u[d].data();
            p.vGrid[d] = vGrid[d].data();
        }
        p.m = m.data();
        p.V = V.data();
        for (int c = 0; c < 9; ++c)
        {
            p.C[c] = C[c].data();
        }
        for (int c = 0; c < 6; ++c)
        {
            p.sigma[c] = sigma[c].data();
        }
        p.J = J.data();
        p.div = div.data();
        return p;
    }
};

// P2G over the whole grid, from cleared nodes
void p2g
(
    const gridGeometry& g,
    testParticles& tp,
    const mpm3dSettings& set,
    mpm3dGrid& grid
)
{
    grid.resize(g.nNodes());
    const scatterSchedule schedule(g);
    particlesToGrid3D
    (
        g, schedule, kernel3(), g.allNodes(), tp.binStart.data(),
        tp.view(), set, grid
    );
}

// Random stresses of the particles, each component in [-scale, scale]
void randomStresses(testParticles& tp, std::mt19937& gen, const double scale)
{
    std::uniform_real_distribution<double> u(-scale, scale);
    for (size_t i = 0; i < tp.m.size(); ++i)
    {
        for (int c = 0; c < 6; ++c)
        {
            tp.sigma[c][i] = u(gen);
        }
    }
}

} // End anonymous namespace


// The momentum stage alone: q0 + a A + b B + c C at node (a, b, c) of a
// stencil is m v + m C (x_i - x_p), for jittered particles and random v, C
TEST(mpm3dTransfers, AffineMomentumIsMomentumAboutEachNode)
{
    const gridGeometry g = box();
    std::mt19937 gen(3);
    std::uniform_real_distribution<double> u(-2, 2);
    testParticles tp(g, 2, &gen);
    for (size_t i = 0; i < tp.m.size(); ++i)
    {
        for (int k = 0; k < 3; ++k)
        {
            tp.u[k][i] = u(gen);
        }
        for (int c = 0; c < 9; ++c)
        {
            tp.C[c][i] = u(gen);
        }
    }
    const mpm3dParticles p = tp.view();
    // Round-off of sums of a few terms of order 2 m/s
    constexpr double tol = 1e-13;
    double worst = 0;
    for (gridIndex i = 0; i < p.n; ++i)
    {
        const stencil<3, kernel3> s
        (
            g, kernel3(), p.x[0][i], p.x[1][i], p.x[2][i]
        );
        const affineMomentum3D q = affineMomentum(s, p, i, true);
        for (int c = 0; c < 3; ++c)
        {
            for (int b = 0; b < 3; ++b)
            {
                for (int a = 0; a < 3; ++a)
                {
                    const double r[3] =
                    {
                        s.r0[0] + a*g.dx[0],
                        s.r0[1] + b*g.dx[1],
                        s.r0[2] + c*g.dx[2]
                    };
                    for (int k = 0; k < 3; ++k)
                    {
                        double exact = p.u[k][i];
                        for (int l = 0; l < 3; ++l)
                        {
                            exact += p.C[3*k + l][i]*r[l];
                        }
                        exact *= p.m[i];
                        const double stage =
                            q.q0[k] + a*q.A[k] + b*q.B[k] + c*q.C[k];
                        worst = std::max(worst, std::abs(stage - exact));
                    }
                }
            }
        }
    }
    EXPECT_LE(worst, tol);
}


// P2G keeps mass and momentum to round-off: partition of unity, and the
// affine part adds nothing in sum (sum_i N_i (x_i - x_p) = 0)
TEST(mpm3dTransfers, P2GConservesMassAndMomentum)
{
    const gridGeometry g = box();
    std::mt19937 gen(5);
    std::uniform_real_distribution<double> u(-3, 3);
    testParticles tp(g, 2, &gen);
    double mP = 0, momP[3] = {0, 0, 0};
    for (size_t i = 0; i < tp.m.size(); ++i)
    {
        mP += tp.m[i];
        for (int k = 0; k < 3; ++k)
        {
            tp.u[k][i] = u(gen);
            momP[k] += tp.m[i]*tp.u[k][i];
        }
        for (int c = 0; c < 9; ++c)
        {
            tp.C[c][i] = u(gen);
        }
    }
    mpm3dGrid grid;
    p2g(g, tp, mpm3dSettings(), grid);

    double mG = 0, momG[3] = {0, 0, 0};
    for (gridIndex n = 0; n < g.nNodes(); ++n)
    {
        mG += grid.mass[n];
        momG[0] += grid.px[n];
        momG[1] += grid.py[n];
        momG[2] += grid.pz[n];
    }
    // Round-off of sums over 1440 particles of 27 nodes each
    constexpr double tol = 1e-12;
    EXPECT_NEAR(mG, mP, tol*mP);
    for (int k = 0; k < 3; ++k)
    {
        EXPECT_NEAR(momG[k], momP[k], tol*3*mP) << "component " << k;
    }
}


// A uniform stress in a block of a regular lattice: the internal force
// -sum V sigma grad N vanishes at every node whose support lies inside the
// block (the lattice is symmetric about the node, grad N odd), sums to
// zero over the grid, and its first moment is the block's total:
// sum_i f_i,a x_i,b = -sigma_ab sum V (linear completeness). The force
// sits on the block's surface: its traction.
TEST(mpm3dTransfers, UniformStressPushesOnlyOnTheSurface)
{
    const gridGeometry g = box();
    testParticles tp(g, 2, nullptr);
    const double sigma[6] = {-3e4, 1e3, -2e3, -5e4, 4e3, -4e4};
    double Vtotal = 0;
    for (size_t i = 0; i < tp.m.size(); ++i)
    {
        for (int c = 0; c < 6; ++c)
        {
            tp.sigma[c][i] = sigma[c];
        }
        Vtotal += tp.V[i];
    }
    mpm3dGrid grid;
    p2g(g, tp, mpm3dSettings(), grid);

    // Force scale of one node: |sigma| times a cell face
    const double fScale = 5e4*g.dx[0]*g.dx[1];
    // Round-off of sums of 216 terms of that size
    constexpr double tol = 1e-12;
    const double full[3][3] =
    {
        {sigma[0], sigma[1], sigma[2]},
        {sigma[1], sigma[3], sigma[4]},
        {sigma[2], sigma[4], sigma[5]}
    };
    const double* const f[3] = {grid.fx.data(), grid.fy.data(), grid.fz.data()};
    double sum[3] = {0, 0, 0}, moment[3][3] = {};
    double worstInterior = 0, largest = 0;
    gridIndex nInterior = 0;
    for (gridIndex n = 0; n < g.nNodes(); ++n)
    {
        gridIndex ijk[3];
        g.nodeIJK(n, ijk);
        double xi[3];
        g.nodePosition(n, xi);
        // The B-spline's support, 3 cells, inside the filled cells
        bool interior = true;
        for (int d = 0; d < 3; ++d)
        {
            interior = interior
                && ijk[d] - 1.5 >= filledLo[d] && ijk[d] + 1.5 <= filledHi[d];
        }
        nInterior += interior;
        for (int a = 0; a < 3; ++a)
        {
            sum[a] += f[a][n];
            largest = std::max(largest, std::abs(f[a][n]));
            if (interior)
            {
                worstInterior = std::max(worstInterior, std::abs(f[a][n]));
            }
            for (int b = 0; b < 3; ++b)
            {
                moment[a][b] += f[a][n]*xi[b];
            }
        }
    }
    ASSERT_GT(nInterior, 0);
    EXPECT_LE(worstInterior, tol*fScale);
    EXPECT_GT(largest, 0.1*fScale) << "no traction on the surface";
    for (int a = 0; a < 3; ++a)
    {
        EXPECT_NEAR(sum[a], 0, tol*fScale) << "component " << a;
        for (int b = 0; b < 3; ++b)
        {
            EXPECT_NEAR(moment[a][b], -full[a][b]*Vtotal, tol*5e4*Vtotal)
                << "component " << a << b;
        }
    }
}


// G2P of a linear node velocity v = v0 + B x gives v(x_p) and C = B at
// every particle (linear completeness of the B-spline)
TEST(mpm3dTransfers, G2PReproducesLinearVelocityField)
{
    const gridGeometry g = box();
    std::mt19937 gen(9);
    testParticles tp(g, 2, &gen);
    const double v0[3] = {0.5, -1, 2};
    const double B[3][3] = {{0.3, -0.2, 0.1}, {1.5, 0, -0.7}, {0.2, 0.4, -1}};

    mpm3dGrid grid;
    grid.resize(g.nNodes());
    double* const v[3] = {grid.vx.data(), grid.vy.data(), grid.vz.data()};
    for (gridIndex n = 0; n < g.nNodes(); ++n)
    {
        double xi[3];
        g.nodePosition(n, xi);
        for (int a = 0; a < 3; ++a)
        {
            v[a][n] = v0[a] + B[a][0]*xi[0] + B[a][1]*xi[1] + B[a][2]*xi[2];
        }
    }
    packVelocities3D(g, g.allNodes(), grid);

    const mpm3dParticles p = tp.view();
    const mpm3dSettings set;
    // Round-off of sums of 27 terms of order 3 m/s (gradients: over dx)
    constexpr double tol = 1e-12;
    for (gridIndex i = 0; i < p.n; ++i)
    {
        const stencil<3, kernel3> s
        (
            g, kernel3(), p.x[0][i], p.x[1][i], p.x[2][i]
        );
        double vp[3];
        const double ratio = gridToParticle3D(s, set, 1e-3, grid, p, i, vp);
        double L[9];
        for (int a = 0; a < 3; ++a)
        {
            const double exact =
                v0[a] + B[a][0]*p.x[0][i] + B[a][1]*p.x[1][i]
              + B[a][2]*p.x[2][i];
            ASSERT_NEAR(vp[a], exact, tol) << "particle " << i;
            ASSERT_NEAR(p.u[a][i], exact, tol) << "particle " << i;
            for (int b = 0; b < 3; ++b)
            {
                L[3*a + b] = B[a][b];
                ASSERT_NEAR(p.C[3*a + b][i], B[a][b], tol/g.dx[0])
                    << "particle " << i;
            }
        }
        EXPECT_NEAR(ratio, stepJacobian(L, 1e-3), 1e-14);
    }
}


// Smoothing: a body at rest (grid velocities 0, so the G2P gives the volume
// ratio r = 1) scatters (V r)_i = V_i bit for bit, so that its J stays as
// it is; the gather and this scatter are one pass (gridToParticles3D)
TEST(mpm3dTransfers, VolumeChangeOfBodyAtRestIsNodeVolumeExactly)
{
    const gridGeometry g = box();
    std::mt19937 gen(13);
    testParticles tp(g, 2, &gen);
    std::fill(tp.div.begin(), tp.div.end(), 0.5);
    mpm3dGrid grid;
    grid.resize(g.nNodes());
    const scatterSchedule schedule(g);
    const mpm3dParticles p = tp.view();
    mpm3dSettings set;
    set.smoothJ = true;
    pressureToGrid3D
    (
        g, schedule, kernel3(), g.allNodes(), tp.binStart.data(), p, grid
    );
    gridToParticles3D
    (
        g, schedule, kernel3(), g.allNodes(), tp.binStart.data(), set, 1e-3,
        grid, p
    );
    double V = 0;
    for (gridIndex n = 0; n < g.nNodes(); ++n)
    {
        V += grid.vol[n];
    }
    EXPECT_GT(V, 0);
    EXPECT_TRUE(grid.dVol == grid.vol);
    for (const double r : tp.div)
    {
        ASSERT_EQ(r, 1.0);
    }
}


TEST(mpm3dTransfers, VolumeRatioIsHeldAtTheMaterialsMaxJ)
{
    // J 1 to 1.3 and to 4.2 (held at 1.2), a compression, a volume through
    // zero (left to the material's check), a NaN (left to the NaN checks)
    constexpr int n = 5;
    double J[n] = {1, 1, 1, 1, std::nan("")};
    const double ratio[n] = {1.3, 4.2, 0.9, -2, 1};
    double m[n] = {2, 2, 2, 2, 2}, V[n] = {}, div[n] = {};
    mpm3dParticles p;
    p.n = n;
    p.J = J;
    p.m = m;
    p.V = V;
    p.div = div;
    mpm3dSettings set;
    set.rho0 = 1000;
    set.maxJ = 1.2;
    const double dt = 1e-3;
    for (gridIndex i = 0; i < p.n; ++i)
    {
        setVolumeRatio(p, i, ratio[i], set, dt);
    }
    const double expected[n - 1] = {1.2, 1.2, 0.9, -2};
    for (int i = 0; i < n - 1; ++i)
    {
        EXPECT_EQ(J[i], expected[i]) << i;
        EXPECT_EQ(V[i], m[i]*expected[i]/set.rho0) << i;
        // The step's strain rate stays the grid's
        EXPECT_EQ(div[i], (ratio[i] - 1)/dt) << i;
    }
    EXPECT_TRUE(std::isnan(J[n - 1]));
    EXPECT_TRUE(std::isnan(V[n - 1]));
}


// volumeChangeToParticles3D takes four particles at a time (stencilLanes,
// nodalMean and setVolumeRatio on lanes4) and the rest one by one: every
// particle's position, J, volume and strain rate are those of the scalar
// stencil, nodalMean and setVolumeRatio, bit for bit, and the particles
// beyond the count are not touched. Random node ratios and grid
// velocities, 3 particles left over, J held at maxJ for some
template<class Kernel>
void checkVolumeChangeInQuads(const Kernel& kernel)
{
    const gridGeometry g = box();
    std::mt19937 gen(17);
    std::uniform_real_distribution<double> u(-1, 1);
    testParticles tp(g, 3, &gen), ref(g, 3, &gen);
    const gridIndex nAll = gridIndex(tp.m.size()), n = nAll - 5;
    ASSERT_EQ(n % 4, 3);
    for (gridIndex i = 0; i < nAll; ++i)
    {
        const double J = 1 + 0.2*u(gen);
        for (int d = 0; d < 3; ++d)
        {
            const double v = 3*u(gen);
            tp.vGrid[d][i] = ref.vGrid[d][i] = v;
            ref.x[d][i] = tp.x[d][i];
        }
        tp.J[i] = ref.J[i] = J;
        ref.m[i] = tp.m[i];
    }
    mpm3dGrid grid;
    grid.resize(g.nNodes());
    for (double& r : grid.dVol)
    {
        r = 1 + 0.3*u(gen);
    }
    mpm3dSettings set;
    set.rho0 = 1300;
    set.maxJ = 1.25;
    const double dt = 2e-3;

    mpm3dParticles p = tp.view();
    p.n = n;
    volumeChangeToParticles3D(g, kernel, set, dt, grid, p);

    mpm3dParticles q = ref.view();
    for (gridIndex i = 0; i < n; ++i)
    {
        const stencil<3, Kernel> s(g, kernel, q.x[0][i], q.x[1][i], q.x[2][i]);
        const double ratio = nodalMean(s, grid.dVol.data());
        for (int d = 0; d < 3; ++d)
        {
            q.x[d][i] += dt*q.vGrid[d][i];
        }
        setVolumeRatio(q, i, ratio, set, dt);
    }
    gridIndex held = 0;
    for (gridIndex i = 0; i < nAll; ++i)
    {
        held += i < n && ref.J[i] == set.maxJ;
        for (int d = 0; d < 3; ++d)
        {
            ASSERT_TRUE(sameBits(tp.x[d][i], ref.x[d][i])) << i;
        }
        ASSERT_TRUE(sameBits(tp.J[i], ref.J[i])) << i;
        ASSERT_TRUE(sameBits(tp.V[i], ref.V[i])) << i;
        ASSERT_TRUE(sameBits(tp.div[i], ref.div[i])) << i;
    }
    EXPECT_GT(held, 0);
    EXPECT_LT(held, n/2);
}


TEST(mpm3dTransfers, VolumeChangeFourAtATimeIsEachParticlesBitForBit)
{
    checkVolumeChangeInQuads(linearKernel());
    checkVolumeChangeInQuads(quadraticBSplineKernel());
    checkVolumeChangeInQuads(GIMPKernel(1.0/6));
}


// What a smoothing scatter adds to node n of stencil s for value k,
// w_a (w_b w_c v_k), node by node: add(k, n, product)
template<class Kernel, int K, class Add>
void nodeProducts
(
    const stencil<3, Kernel>& s,
    const double (&v)[K],
    Add&& add
)
{
    for (int c = 0; c < Kernel::width; ++c)
    {
        for (int b = 0; b < Kernel::width; ++b)
        {
            const double wbc = s.w[1][b]*s.w[2][c];
            for (int a = 0; a < Kernel::width; ++a)
            {
                const gridIndex n = s.base + a + b*s.sy + c*s.sz;
                for (int k = 0; k < K; ++k)
                {
                    add(k, n, s.w[0][a]*(wbc*v[k]));
                }
            }
        }
    }
}


// The smoothing scatters (scatterScalars: a row's nodes two at a time, a
// node's values interleaved; volumePressureToPairs: the volume and
// pressure) add to every node of every stencil w_a (w_b w_c v_k), the
// scalar form's product, bit for bit: particles one after the other onto
// random node values, two values a node and one, each kernel width (2
// nodes a row and 3)
template<class Kernel, int K>
void checkSmoothingScatter(const Kernel& kernel)
{
    const gridGeometry g = box();
    std::mt19937 gen(29);
    std::uniform_real_distribution<double> u(-1, 1);
    testParticles tp(g, 2, &gen);
    std::vector<double> q(K*g.nNodes());
    for (double& v : q)
    {
        v = u(gen);
    }
    std::vector<double> ref(q);
    for (size_t i = 0; i < tp.m.size(); ++i)
    {
        const stencil<3, Kernel> s
        (
            g, kernel, tp.x[0][i], tp.x[1][i], tp.x[2][i]
        );
        double v[K];
        for (int k = 0; k < K; ++k)
        {
            v[k] = u(gen);
        }
        scatterScalars(s, v, q.data());
        nodeProducts
        (
            s, v, [&](const int k, const gridIndex n, const double x)
            {
                ref[K*n + k] += x;
            }
        );
    }
    for (size_t j = 0; j < ref.size(); ++j)
    {
        ASSERT_TRUE(sameBits(q[j], ref[j])) << j;
    }
}


// v = (V, -V tr(sigma)/3) into the pairs of volPV
template<class Kernel>
void checkVolumePressurePairs(const Kernel& kernel)
{
    const gridGeometry g = box();
    std::mt19937 gen(31);
    std::uniform_real_distribution<double> u(-1, 1);
    testParticles tp(g, 2, &gen);
    for (size_t i = 0; i < tp.m.size(); ++i)
    {
        tp.V[i] *= 1 + 0.5*u(gen);
    }
    randomStresses(tp, gen, 1e3);
    const mpm3dParticles p = tp.view();
    std::vector<double> volPV(mpm3dGrid::volPVWidth*g.nNodes());
    for (double& v : volPV)
    {
        v = u(gen);
    }
    std::vector<double> ref(volPV);
    for (gridIndex i = 0; i < p.n; ++i)
    {
        const stencil<3, Kernel> s(g, kernel, p.x[0][i], p.x[1][i], p.x[2][i]);
        volumePressureToPairs(s, p, i, volPV.data());
        const double v[2] =
        {
            p.V[i], -p.V[i]*(p.sigma[0][i] + p.sigma[3][i] + p.sigma[5][i])/3
        };
        nodeProducts
        (
            s, v, [&](const int k, const gridIndex n, const double x)
            {
                ref[2*n + k] += x;
            }
        );
    }
    for (size_t j = 0; j < ref.size(); ++j)
    {
        ASSERT_TRUE(sameBits(volPV[j], ref[j])) << j;
    }
}


// The volume and pressure scatter on a grid that has had a step: with the
// node state zeroed (zeroNodes3D) in between, the nodes' vol and pV are
// those of a fresh grid, bit for bit
TEST(mpm3dTransfers, PressureScatterStartsFromZeroEveryStep)
{
    const gridGeometry g = box();
    std::mt19937 gen(37);
    testParticles tp(g, 2, &gen);
    randomStresses(tp, gen, 1e3);
    const mpm3dParticles p = tp.view();
    const scatterSchedule schedule(g);
    const nodeBox all = g.allNodes();
    mpm3dGrid fresh, used;
    fresh.resize(g.nNodes());
    used.resize(g.nNodes());
    for (int step = 0; step < 2; ++step)
    {
        zeroNodes3D(g, all, used);
        pressureToGrid3D
        (
            g, schedule, kernel3(), all, tp.binStart.data(), p, used
        );
    }
    pressureToGrid3D(g, schedule, kernel3(), all, tp.binStart.data(), p, fresh);
    for (gridIndex n = 0; n < g.nNodes(); ++n)
    {
        ASSERT_TRUE(sameBits(used.vol[n], fresh.vol[n])) << n;
        ASSERT_TRUE(sameBits(used.pV[n], fresh.pV[n])) << n;
    }
}


TEST(mpm3dTransfers, SmoothingScatterIsEachNodesProductBitForBit)
{
    checkVolumePressurePairs(linearKernel());
    checkVolumePressurePairs(kernel3());
    checkVolumePressurePairs(GIMPKernel(1.0/6));
    checkSmoothingScatter<linearKernel, 2>(linearKernel());
    checkSmoothingScatter<kernel3, 2>(kernel3());
    checkSmoothingScatter<kernel3, 1>(kernel3());
    checkSmoothingScatter<GIMPKernel, 1>(GIMPKernel(1.0/6));
}


// Timing (label benchmark): the three particle passes of a step with
// volumetric smoothing (pressure scatter, P2G scatter, G2P gather fused
// with the volume change's scatter), per particle, on particles and nodes
// that stay in cache (1,440 particles, 1,716 nodes) and on 922,560 particles
// streamed from memory. Equal times say a pass is bound by its arithmetic,
// not by memory (benchmarks/mpm3dFoamThroughput/results.md). Each run's
// node mass is the particles' to round-off, and a body at rest keeps its
// volume ratio 1.
TEST(mpm3dTransfersBenchmark, PassesInCacheAndStreamedFromMemory)
{
    std::mt19937 gen(5);
    for (const bool streamed : {false, true})
    {
        const gridGeometry g = streamed
          ? uniformGrid(3, {0, 0, 0}, {0.1, 0.1, 0.1}, {64, 32, 64})
          : box();
        const gridIndex lo[3] = {1, 1, 1}, hi[3] = {63, 31, 63};
        testParticles tp = streamed
          ? testParticles(g, 2, &gen, lo, hi)
          : testParticles(g, 2, &gen);
        randomStresses(tp, gen, 1);
        const mpm3dParticles p = tp.view();
        const scatterSchedule schedule(g);
        mpm3dSettings set;
        set.smoothJ = true;
        mpm3dGrid grid;
        grid.resize(g.nNodes());
        const nodeBox all = g.allNodes();
        const int reps = streamed ? 5 : 2000;

        double seconds[3] = {0, 0, 0};
        for (int r = 0; r < reps; ++r)
        {
            zeroNodes3D(g, all, grid);
            std::fill(grid.sums.begin(), grid.sums.end(), 0.0);
            const auto t0 = std::chrono::steady_clock::now();
            pressureToGrid3D
            (
                g, schedule, kernel3(), all, tp.binStart.data(), p, grid
            );
            const auto t1 = std::chrono::steady_clock::now();
            scatterNodeSums3D
            (
                g, schedule, kernel3(), all, tp.binStart.data(), p, set, grid
            );
            const auto t2 = std::chrono::steady_clock::now();
            gridToParticles3D
            (
                g, schedule, kernel3(), all, tp.binStart.data(), set, 1e-3,
                grid, p
            );
            const auto t3 = std::chrono::steady_clock::now();
            seconds[0] += std::chrono::duration<double>(t1 - t0).count();
            seconds[1] += std::chrono::duration<double>(t2 - t1).count();
            seconds[2] += std::chrono::duration<double>(t3 - t2).count();
        }

        double nodeMass = 0, particleMass = 0;
        for (gridIndex n = 0; n < g.nNodes(); ++n)
        {
            nodeMass += grid.sums[mpm3dGrid::sumsWidth*n];
        }
        for (const double m : tp.m)
        {
            particleMass += m;
        }
        EXPECT_NEAR(nodeMass, particleMass, 1e-12*particleMass);
        for (const double r : tp.div)
        {
            ASSERT_EQ(r, 1.0);
        }

        const double perParticle = 1e9/(double(reps)*p.n);
        std::printf
        (
            "%s: %d particles, %d threads: pressure scatter %.1f ns, "
            "P2G scatter %.1f ns, G2P + volume change %.1f ns a particle\n",
            streamed ? "streamed" : "in cache", int(p.n), omp_get_max_threads(),
            seconds[0]*perParticle, seconds[1]*perParticle,
            seconds[2]*perParticle
        );
    }
}


// ************************************************************************* //
